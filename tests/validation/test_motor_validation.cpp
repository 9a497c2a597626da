// Validation section (5), the induction-motor laws: every claim holds and carries its numbers.
#include <gtest/gtest.h>

#include <string>

#include "compare/ValidationSuite.h"

namespace rollerdyn {
namespace {

TEST(MotorValidation, EveryClaimHoldsWithItsNumbers) {
  validation::ValidationOptions o;
  o.model_dir = std::string(ROLLERDYN_SOURCE_DIR) + "/model";
  const auto claims = validation::runMotorValidation(o);
  ASSERT_EQ(claims.size(), 9u);
  for (const auto& c : claims) {
    std::string text;
    for (const auto& l : c.lines) text += "\n    " + l;
    EXPECT_EQ(c.verdict, validation::Finding::Verdict::Holds) << c.id << " " << c.title << text;
    EXPECT_GE(c.lines.size(), 1u);
    std::cout << c.id << " " << c.title << text << "\n";
  }
  const std::string md = validation::motorReportMarkdown(claims);
  EXPECT_NE(md.find("## (5) The induction-motor laws"), std::string::npos);
  EXPECT_EQ(validation::motorReportJson(claims).size(), 9u);
}

}  // namespace
}  // namespace rollerdyn
