// A metre value typed in millimetres (the 6-cart trial: accepted without a word) gets a warning
// naming the key, the value and what was likely meant; the papers' own values get none.
#include <gtest/gtest.h>

#include "scene/Plausibility.h"
#include "support/Seed000Scene.h"

namespace rollerdyn {
namespace {

TEST(Plausibility, LengthTypedInMillimetresIsNamedAndThePapersValuesAreNot) {
  Scene s = test_scenes::seed000Scene();
  EXPECT_TRUE(plausibilityWarnings(s).empty());
  s.crank.radius = 200;  // meant 200 mm
  const auto w = plausibilityWarnings(s);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("crank.radius = 200 m"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("write 0.2"), std::string::npos) << w[0];
}

}  // namespace
}  // namespace rollerdyn
