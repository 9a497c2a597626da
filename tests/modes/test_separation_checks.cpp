// The separation margins as checks of the sign-off sheet (modes/SeparationMargins.h,
// separationChecks): each order shown becomes a check with value SM_k, limit 10 % (passes when
// SM_k >= 0.10), method API 617 / API 684, the margins' own verdicts; an order too weak to drive
// the mode "not applicable" where it lies within 10 % of it, and no check further away;
// margins that do not apply give one "not applicable" check with their reason. modes.json holds
// them under separation_margins.checks.
#include <gtest/gtest.h>

#include <cmath>

#include "modes/SeparationMargins.h"

using namespace rollerdyn;
using namespace rollerdyn::modes;

namespace {

SeparationMargin row(int k, double margin, const std::string& verdict) {
  SeparationMargin m;
  m.order = k;
  m.excitation = k * 10.0;
  m.p_low = m.p_high = 42.0;
  m.frequency_source = "Floquet multipliers";
  m.margin = margin;
  m.damping_ratio = 0.2;
  m.amplification = 2.5;
  m.verdict = verdict;
  m.reason = "reason of order " + std::to_string(k);
  return m;
}

}  // namespace

TEST(SeparationChecks, EachOrderIsACheckAgainstTenPercent) {
  SeparationMargins s;
  s.applicable = true;
  s.omega = 10.0;
  s.rows = {row(4, 0.05, "FAIL"), row(2, 0.52, "pass"), row(8, 0.02, "n/a"), row(12, 0.9, "n/a")};
  const std::vector<SizingCheck> c = separationChecks(s);
  ASSERT_EQ(c.size(), 3u);  // order 12: too weak to drive the mode and 90 % away from it, no check
  EXPECT_EQ(c[0].name, "separation_margin_order_4");
  EXPECT_EQ(c[0].verdict, "FAIL");
  EXPECT_DOUBLE_EQ(c[0].value, 0.05);
  EXPECT_EQ(c[1].verdict, "pass");
  EXPECT_EQ(c[2].verdict, "not applicable");
  EXPECT_TRUE(std::isnan(c[2].value));
  EXPECT_EQ(c[2].reason, "reason of order 8");
  for (const SizingCheck& k : c) {
    EXPECT_DOUBLE_EQ(k.limit, 0.10);
    EXPECT_EQ(k.passes_when, ">=");
    EXPECT_NE(k.method.find("API 617"), std::string::npos);
  }
  const nlohmann::json j = separationJson(s);
  ASSERT_EQ(j["checks"].size(), 3u);
  EXPECT_EQ(j["checks"][0]["limit"], 0.10);
}

TEST(SeparationChecks, OnlyWeakOrdersFarFromTheModeGiveOneNotApplicableCheck) {
  SeparationMargins s;
  s.applicable = true;
  s.omega = 10.0;
  s.rows = {row(1, 3.0, "n/a"), row(3, 0.5, "n/a")};
  const std::vector<SizingCheck> c = separationChecks(s);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].name, "separation_margin");
  EXPECT_EQ(c[0].verdict, "not applicable");
  EXPECT_NE(c[0].reason.find("no crank order drives the coupling mode"), std::string::npos);
}

TEST(SeparationChecks, MarginsThatDoNotApplyGiveOneCheckWithTheReason) {
  SeparationMargins s;
  s.not_applicable = "rigid coupling (coupling.type: rigid): no torsional mode";
  const std::vector<SizingCheck> c = separationChecks(s);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].verdict, "not applicable");
  EXPECT_EQ(c[0].reason, s.not_applicable);
  EXPECT_EQ(separationJson(s)["checks"][0]["verdict"], "not applicable");
}
