// Each main bearing's reaction from the crankshaft's beam statics (analysis/CrankshaftBearings.h)
// against hand calculations: the lever rule, the classic continuous-beam results and the
// three-moment equation. R is the force of the bearing on the shaft: a load P pushes it back.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "analysis/CrankshaftBearings.h"
#include "analysis/DriveSizing.h"
#include "analysis/SizingSummary.h"
#include "analysis/SteadyState.h"

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

// One cart at constant crank speed whose rod pushes its crank pin with a constant F0 along x; the
// bearings' resultant is −F0 (nothing else on the shaft). Throw at z = 0.25 m between bearings at 0
// and 1 m: the lever rule gives |R1| = 0.75·F0, |R2| = 0.25·F0, constant, so P = |R| and
// L10 = (C/P)³·10⁶ revolutions, L10h = L10/(Ω/2π·3600).
TEST(CrankshaftBearings, EachBearingGetsItsOwnJointRowWithItsShareAndLife) {
  constexpr double F0 = 8000, Om = 10.0, C = 60000, kPi = 3.14159265358979323846;
  Scene sc{};
  sc.simulation.steady_window_revolutions = 3;
  sc.crank.radius = 0.2;
  sc.crank.offset = 0;
  sc.rods.length = 0.8;
  sc.rods.model = RodModel::Massless;
  sc.carts.count = 1;
  sc.carts.side = {1};
  sc.carts.mass = 1000;
  sc.sizing.rating_main_bearing = C;
  sc.crankshaft.throw_positions = {0.25};
  sc.crankshaft.bearing_positions = {0.0, 1.0};
  RunResult rr;
  rr.model = "multibody";
  rr.timeseries.columns = {"t", "phi_crank", "omega_crank", "eps_crank"};
  rr.reactions.columns = {"t", "crankpin_x_1", "crankpin_y_1", "bearing_x", "bearing_y"};
  const double T = 5 * 2 * kPi / Om;
  for (int i = 0; i <= 5000; ++i) {
    const double t = T * i / 5000;
    rr.timeseries.rows.push_back({t, Om * t, Om, 0.0});
    rr.reactions.rows.push_back({t, F0, 0.0, -F0, 0.0});
  }
  appendBearingColumns(sc, rr);
  ASSERT_TRUE(rr.reactions.has("bearing_x_2"));
  const SteadyState w = detectSteadyState(rr.timeseries, sc.simulation.steady_window_revolutions);
  const DriveSizing s = computeDriveSizing(sc, rr, w, true, 0.0, "turning");
  std::vector<const JointSizing*> mains;
  for (const JointSizing& j : s.joints)
    if (j.joint == "main_bearing") mains.push_back(&j);
  ASSERT_EQ(mains.size(), 2u);
  const double share[2] = {0.75, 0.25}, z[2] = {0.0, 1.0};
  for (int k = 0; k < 2; ++k) {
    EXPECT_EQ(mains[k]->bearing, k + 1);
    EXPECT_EQ(mains[k]->position, z[k]);
    EXPECT_NEAR(mains[k]->load.peak, share[k] * F0, 1e-6);
    EXPECT_NEAR(mains[k]->load.equivalent, share[k] * F0, 1e-6);
    const double L10 = std::pow(C / (share[k] * F0), 3) * 1e6;
    EXPECT_NEAR(mains[k]->life_hours, L10 / (Om / (2 * kPi) * 3600), 1e-6 * L10);
  }
  const nlohmann::json j = sizingJson(s);
  EXPECT_EQ(j["joints"]["main_bearing"]["per_cart"][1]["bearing"], 2);
  EXPECT_EQ(j["joints"]["main_bearing"]["per_cart"][1]["position"], 1.0);
  EXPECT_EQ(j["crankshaft"]["bearing_positions"], nlohmann::json::array({0.0, 1.0}));
}

}  // namespace
}  // namespace rollerdyn
