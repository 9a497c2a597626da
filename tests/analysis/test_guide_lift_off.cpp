// Guide lift-off (analysis/GuideLiftOff.h): a guide reaction that changes sign in the steady
// window is reported per cart and guide with the share of the time on its minority side and its
// worst value there; one that keeps its sign (either sign) holds; without reactions or a steady
// window the verdict is not applicable.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/GuideLiftOff.h"

namespace rollerdyn {
namespace {

// Reactions of two carts over t = 0 ... 2 s: cart 1's front reaction 500 + 1000·sin(2πt) is
// negative where sin(2πt) < −1/2, i.e. for 1/3 of every period (t in (7/12, 11/12)); its minimum
// is −500 N. Cart 2's reactions keep their sign: the front one positive, the rear one negative
// (a cart resting on its guides).
RunResult twoCarts(bool lifting) {
  RunResult r;
  r.reactions.columns = {"t", "N_front_1", "N_rear_1", "N_front_2", "N_rear_2"};
  for (int i = 0; i <= 20000; ++i) {
    const double t = 1e-4 * i, s = std::sin(2.0 * M_PI * t);
    r.reactions.rows.push_back({t, (lifting ? 500.0 : 1500.0) + 1000.0 * s, 3000.0, 2000.0 + 100.0 * s, -2500.0 + 50.0 * s});
  }
  return r;
}

SteadyState window(double t0, double t1) {
  SteadyState ss;
  ss.reached = true;
  ss.t_begin = t0;
  ss.t_end = t1;
  return ss;
}

TEST(GuideLiftOff, ANegativeGuideReactionIsReportedWithItsShareOfTimeAndWorstValue) {
  const GuideLiftOff g = computeGuideLiftOff(twoCarts(true), window(1.0, 2.0), true);
  EXPECT_EQ(g.verdict, "lifts off");
  EXPECT_EQ(g.guides_checked, 4);
  ASSERT_EQ(g.lifting.size(), 1u);
  EXPECT_EQ(g.lifting[0].cart, 1);
  EXPECT_EQ(g.lifting[0].guide, "front");
  EXPECT_NEAR(g.lifting[0].time_fraction, 1.0 / 3.0, 1e-6);
  EXPECT_NEAR(g.lifting[0].worst_reaction, -500.0, 1e-3);
  EXPECT_TRUE(g.lifting[0].presses_down);
  EXPECT_NEAR(g.lifting[0].prevailing_extreme, 1500.0, 1e-3);
  ASSERT_EQ(g.warnings.size(), 1u);
  EXPECT_NE(g.warnings[0].find("guide reactions change sign"), std::string::npos) << g.warnings[0];
  EXPECT_NE(g.warnings[0].find("cart 1 front: downward"), std::string::npos) << g.warnings[0];
  EXPECT_NE(g.warnings[0].find("33.3 %"), std::string::npos) << g.warnings[0];
  EXPECT_NE(g.warnings[0].find("-500 N"), std::string::npos) << g.warnings[0];
}

TEST(GuideLiftOff, GuideReactionsThatKeepTheirSignHold) {
  const GuideLiftOff g = computeGuideLiftOff(twoCarts(false), window(1.0, 2.0), true);
  EXPECT_EQ(g.verdict, "holds");
  EXPECT_TRUE(g.lifting.empty());
  EXPECT_TRUE(g.warnings.empty());
}

TEST(GuideLiftOff, NotApplicableWithoutReactionsOrSteadyWindowAndSaysWhy) {
  const GuideLiftOff none = computeGuideLiftOff(RunResult{}, window(1.0, 2.0), true);
  EXPECT_EQ(none.verdict, "not applicable");
  EXPECT_NE(none.reason.find("simulation.reactions"), std::string::npos);
  SteadyState ss = window(1.0, 2.0);
  ss.reached = false;
  ss.not_reached = "steady state not reached within the run: run longer";
  const GuideLiftOff unsteady = computeGuideLiftOff(twoCarts(true), ss, false);
  EXPECT_EQ(unsteady.verdict, "not applicable");
  EXPECT_EQ(unsteady.reason, ss.not_reached);
  EXPECT_TRUE(unsteady.warnings.empty());
  EXPECT_TRUE(guideLiftOffJson(unsteady)["t_begin"].is_null());
}

}  // namespace
}  // namespace rollerdyn
