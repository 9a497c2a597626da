// Each main bearing's reaction from the crankshaft's beam statics (analysis/CrankshaftBearings.h)
// against hand calculations: the lever rule, the classic continuous-beam results and the
// three-moment equation. R is the force of the bearing on the shaft: a load P pushes it back.
#include <gtest/gtest.h>

#include <vector>

#include "analysis/CrankshaftBearings.h"

namespace rollerdyn {
namespace {

constexpr double kP = 1000.0;  // N

TEST(CrankshaftBearings, TwoBearingsShareALoadByTheLeverRule) {
  // Bearings at 0 and 1 m, load at 0.3 m: R1 = −P·0.7, R2 = −P·0.3.
  const ShaftBeam beam({0.0, 1.0}, {0.3});
  const std::vector<double> R = beam.reactions({kP});
  ASSERT_EQ(R.size(), 2u);
  EXPECT_NEAR(R[0], -700.0, 1e-9);
  EXPECT_NEAR(R[1], -300.0, 1e-9);
}

TEST(CrankshaftBearings, OverhungThrowPullsTheFarBearingTheOtherWay) {
  // Bearings at 0 and 1 m, load at 1.5 m (beyond the second): moments about bearing 2 give
  // R1·1 = P·0.5 the other way, R1 = +0.5·P; R2 = −1.5·P.
  const ShaftBeam beam({0.0, 1.0}, {1.5});
  const std::vector<double> R = beam.reactions({kP});
  EXPECT_NEAR(R[0], 500.0, 1e-9);
  EXPECT_NEAR(R[1], -1500.0, 1e-9);
}

TEST(CrankshaftBearings, ThreeBearingsEqualSpansLoadAtEachMidSpanGiveFiveSixteenthsElevenEighths) {
  const ShaftBeam beam({0.0, 1.0, 2.0}, {0.5, 1.5});
  const std::vector<double> R = beam.reactions({kP, kP});
  ASSERT_EQ(R.size(), 3u);
  EXPECT_NEAR(R[0], -5.0 / 16.0 * kP, 1e-8);
  EXPECT_NEAR(R[1], -11.0 / 8.0 * kP, 1e-8);
  EXPECT_NEAR(R[2], -5.0 / 16.0 * kP, 1e-8);
}

TEST(CrankshaftBearings, ThreeBearingsOneLoadInTheFirstSpanLiftsTheFarBearing) {
  // Classic: 13/32, 11/16 and −3/32 of P.
  const ShaftBeam beam({0.0, 1.0, 2.0}, {0.5});
  const std::vector<double> R = beam.reactions({kP});
  EXPECT_NEAR(R[0], -13.0 / 32.0 * kP, 1e-8);
  EXPECT_NEAR(R[1], -11.0 / 16.0 * kP, 1e-8);
  EXPECT_NEAR(R[2], 3.0 / 32.0 * kP, 1e-8);
}

TEST(CrankshaftBearings, UnequalSpansFollowTheThreeMomentEquation) {
  // Spans L1 = 1, L2 = 2 m, P at the middle of span 2 (b = 1 m from the far bearing). Three
  // moments: 2·M_B·(L1 + L2) = −P·b·(L2² − b²)/L2 = −1.5·P, M_B = −P/4. Span 1: R_A = M_B/L1 =
  // −P/4 (held down); span 2: R_C = P/2 + M_B/L2 = 3P/8; R_B = P − R_A − R_C = 7P/8.
  const ShaftBeam beam({0.0, 1.0, 3.0}, {2.0});
  const std::vector<double> R = beam.reactions({kP});
  EXPECT_NEAR(R[0], 0.25 * kP, 1e-8);
  EXPECT_NEAR(R[1], -0.875 * kP, 1e-8);
  EXPECT_NEAR(R[2], -0.375 * kP, 1e-8);
}

TEST(CrankshaftBearings, ThrowOnABearingIsTakenWhollyByIt) {
  const ShaftBeam three({0.0, 1.0, 2.0}, {1.0});
  const std::vector<double> R = three.reactions({kP});
  EXPECT_NEAR(R[0], 0.0, 1e-9);
  EXPECT_NEAR(R[1], -kP, 1e-9);
  EXPECT_NEAR(R[2], 0.0, 1e-9);
  const ShaftBeam two({0.0, 1.0}, {0.0});
  const std::vector<double> R2 = two.reactions({kP});
  EXPECT_NEAR(R2[0], -kP, 1e-9);
  EXPECT_NEAR(R2[1], 0.0, 1e-9);
}

TEST(CrankshaftBearings, BendingMomentAtMidSpanIsPLOverFour) {
  // Simply supported span L = 2 m, P at the middle: M = P·L/4 under the load (of the forces left
  // of it: the bearing's −P/2 at arm 1 m).
  const ShaftBeam beam({0.0, 2.0}, {1.0});
  const std::vector<double> loads = {kP};
  const std::vector<double> R = beam.reactions(loads);
  EXPECT_NEAR(std::abs(beam.bendingMoment(loads, R, 1.0)), kP * 2.0 / 4.0, 1e-9);
}

TEST(CrankshaftBearings, LayoutWithFewerThanTwoOrUnorderedBearingsIsRefused) {
  EXPECT_THROW(ShaftBeam({0.0}, {0.5}), std::invalid_argument);
  EXPECT_THROW(ShaftBeam({1.0, 0.0}, {0.5}), std::invalid_argument);
}

}  // namespace
}  // namespace rollerdyn
