// The reducer's loss law (physics/ReducerLosses.h) against LossyGear's closed forms written out
// here: (1 − η_f)·|P| while the motor side drives, (1/η_r − 1)·|P| while the crank side drives;
// the papers' setting is M·u·η both ways; the smooth blend is continuous and never negative.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/ReducerLosses.h"
#include "scene/SceneParser.h"

namespace rollerdyn {
namespace {

ReducerLaw powerFlow(double eta_f, double eta_r) {
  ReducerLaw l;
  l.model = ReducerLossModel::PowerFlow;
  l.ratio = 9.8;
  l.eta_forward = eta_f;
  l.eta_reverse = eta_r;
  l.torque_band = 0.01 * 215.4 * 9.8;  // 1 % of M_kr·u of Loveikin and Pochka's (2007) motor
  l.speed_band = 1e-3 * 104.72 / 9.8;
  return l;
}

TEST(ReducerLosses, MotorSideDrivingLosesOneMinusEtaForwardOfThePower) {
  const ReducerLaw l = powerFlow(0.9, 0.8);
  const double M = 150.0, w = 10.4;  // motor torque at the rotor [N·m], crank-axis speed [rad/s]
  const double P = M * 9.8 * w;      // power entering the reducer at its motor shaft [W]
  EXPECT_NEAR(reducerLossTorque(l, M, w) * w, (1.0 - 0.9) * P, 1e-9 * P);
  EXPECT_NEAR(reducerCrankTorque(l, M, w), 0.9 * M * 9.8, 1e-9 * M * 9.8);
}

TEST(ReducerLosses, CrankSideDrivingLosesOneOverEtaReverseMinusOneOfThePower) {
  const ReducerLaw l = powerFlow(0.9, 0.8);
  const double M = -120.0, w = 10.9;  // the motor generates: the crank side drives it
  const double P = std::abs(M * 9.8 * w);
  EXPECT_NEAR(reducerLossTorque(l, M, w) * w, (1.0 / 0.8 - 1.0) * P, 1e-9 * P);
  // The crank must supply |P|/η_r: the torque at the crank is M·u/η_r.
  EXPECT_NEAR(reducerCrankTorque(l, M, w), M * 9.8 / 0.8, 1e-9 * std::abs(M) * 9.8);
}

TEST(ReducerLosses, RunningBackwardsTheDirectionIsThatOfThePowerNotOfTheTorque) {
  const ReducerLaw l = powerFlow(0.9, 0.8);
  // Negative torque at negative speed: the motor drives (P > 0), forward efficiency.
  EXPECT_NEAR(reducerCrankTorque(l, -100.0, -5.0), 0.9 * -100.0 * 9.8, 1e-9 * 980.0);
  EXPECT_NEAR(reducerCrankTorque(l, 100.0, -5.0), 100.0 * 9.8 / 0.8, 1e-9 * 980.0);
}

TEST(ReducerLosses, PapersSettingIsMTimesUTimesEtaInBothDirections) {
  ReducerLaw l = powerFlow(0.9, 0.5);
  l.model = ReducerLossModel::Papers;
  for (double M : {150.0, -120.0, 0.3})
    for (double w : {10.4, -3.0, 0.0}) {
      EXPECT_EQ(reducerCrankTorque(l, M, w), M * 9.8 * 0.9);  // eq. (37), the same bits
      // The loss the papers imply, (1 − η)·M·u, whatever the direction (negative while generating).
      EXPECT_NEAR(reducerLossTorque(l, M, w), (1.0 - 0.9) * M * 9.8, 1e-12 * std::abs(M) * 9.8);
    }
}

TEST(ReducerLosses, BothSettingsAgreeWhenLossless) {
  ReducerLaw pf = powerFlow(1.0, 1.0), pa = pf;
  pa.model = ReducerLossModel::Papers;
  for (double M : {-200.0, -1.0, 0.0, 0.5, 180.0})
    for (double w : {-2.0, 0.0, 1e-4, 10.0}) {
      EXPECT_EQ(reducerLossTorque(pf, M, w), 0.0);
      EXPECT_NEAR(reducerCrankTorque(pf, M, w), reducerCrankTorque(pa, M, w), 1e-12 * 2000.0);
    }
}

TEST(ReducerLosses, BlendedLawIsContinuousAndItsLossesNeverNegative) {
  const ReducerLaw l = powerFlow(0.9, 0.85);
  const double T_b = l.torque_band, w_b = l.speed_band;
  // Across zero torque at running speed, and across zero speed at a fixed torque: the loss power
  // is ≥ 0 everywhere, and adjacent samples 1e-4 band apart differ by at most a Lipschitz bound
  // (|dL/dT| ≤ 1.3·max(k_f, k_r); in speed |dL/dω| ≤ a·(k_f + k_r)/ω_b < 3·k_max·a/ω_b; a jump
  // would be of order a·k, thousands of times these).
  const double k_max = std::max(1.0 - 0.9, 1.0 / 0.85 - 1.0);
  double prev = reducerLossTorque(l, -5.0 * T_b / 9.8, 10.0);
  for (int i = 1; i <= 100000; ++i) {
    const double M = (-5.0 + 1e-4 * i) * T_b / 9.8;
    const double L = reducerLossTorque(l, M, 10.0);
    EXPECT_GE(L * 10.0, 0.0) << "M = " << M;
    ASSERT_LE(std::abs(L - prev), 1.3 * k_max * 1e-4 * T_b) << "jump at M = " << M;
    prev = L;
  }
  const double M = 2.0 * T_b / 9.8;
  prev = reducerLossTorque(l, M, -5.0 * w_b);
  for (int i = 1; i <= 100000; ++i) {
    const double w = (-5.0 + 1e-4 * i) * w_b;
    const double L = reducerLossTorque(l, M, w);
    EXPECT_GE(L * w, 0.0) << "w = " << w;
    ASSERT_LE(std::abs(L - prev), 3.0 * k_max * 2.0 * T_b * 1e-4) << "jump at w = " << w;
    prev = L;
  }
  // Outside 4 band widths the blend is LossyGear's law to 1e-3 of the loss.
  EXPECT_NEAR(reducerLossTorque(l, 4.0 * T_b / 9.8, 10.0), 0.1 * 4.0 * T_b, 1e-3 * 0.1 * 4.0 * T_b);
  EXPECT_NEAR(reducerLossTorque(l, -4.0 * T_b / 9.8, 10.0), (1.0 / 0.85 - 1.0) * 4.0 * T_b,
              1e-3 * (1.0 / 0.85 - 1.0) * 4.0 * T_b);
}

TEST(ReducerLosses, SceneKeysChooseTheLawAndTheReverseEfficiencyDefaultsToTheForwardOne) {
  const std::string file = std::string(ROLLERDYN_SOURCE_DIR) + "/model/recuperative-2cart.yaml";
  const ReducerLaw papers = reducerLaw(parseSceneFile(file, {}), 215.4);
  EXPECT_EQ(papers.model, ReducerLossModel::Papers);
  const ReducerLaw same = reducerLaw(parseSceneFile(file, {"reducer.losses=power_flow"}), 215.4);
  EXPECT_EQ(same.model, ReducerLossModel::PowerFlow);
  EXPECT_EQ(same.eta_reverse, same.eta_forward);
  const ReducerLaw own = reducerLaw(parseSceneFile(file, {"reducer.losses=power_flow", "reducer.efficiency_reverse=0.8"}), 215.4);
  EXPECT_EQ(own.eta_reverse, 0.8);
  // T_b = 1 % of M_kr·u = 0.01·215.4·9.8 N·m (the scene's motor and reducer).
  EXPECT_NEAR(own.torque_band, 0.01 * 215.4 * 9.8, 1e-9);
  EXPECT_THROW(parseSceneFile(file, {"reducer.losses=lossy"}), std::exception);
  EXPECT_THROW(parseSceneFile(file, {"reducer.losses=power_flow", "reducer.efficiency_reverse=1.2"}), std::exception);
}

}  // namespace
}  // namespace rollerdyn
