// With the reducer's backlash the linear modes are those of permanent tooth contact: the analysis
// says so by name and gives the same modes as the drive without backlash (no silent use).
#include <gtest/gtest.h>

#include <cmath>

#include "ModesTestSupport.h"

using namespace rollerdyn;
using namespace rollerdyn::modes;

namespace {
ModesReport light(const std::vector<std::string>& overrides) { return rollerdyn::modes::test::lightModes(overrides); }
}  // namespace

TEST(ModesBacklash, PermanentToothContactIsANamedApproximation) {
  const ModesReport with = light({"reducer.backlash=0.0017453"});
  ASSERT_EQ(with.approximations.size(), 1u);
  EXPECT_EQ(with.approximations[0].first, "permanent tooth contact");
  EXPECT_NE(with.approximations[0].second.find("always in contact"), std::string::npos);
  EXPECT_EQ(modesJson(with)["approximations"][0]["name"], "permanent tooth contact");
  EXPECT_NE(modesText(with).find("approximation, permanent tooth contact"), std::string::npos);
  const ModesReport without = light({});
  EXPECT_TRUE(without.approximations.empty());
  // the same linear drive: the same steady motion's Floquet multipliers
  ASSERT_TRUE(with.steady.found && without.steady.found);
  ASSERT_EQ(with.steady.multipliers.size(), without.steady.multipliers.size());
  for (std::size_t i = 0; i < with.steady.multipliers.size(); ++i)
    EXPECT_EQ(with.steady.multipliers[i].m.modulus, without.steady.multipliers[i].m.modulus);
}
