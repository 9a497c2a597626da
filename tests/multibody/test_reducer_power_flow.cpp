// reducer.losses in both models: the loss the runs record against LossyGear's closed forms with
// the Kloss torque computed here, the energy balance with the reducer's column, the papers'
// default (M·u·η, its loss (1 − η)·P) unchanged, both settings agreeing when η = 1, and the two
// models agreeing with each other under power_flow.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "analysis/Summary.h"
#include "multibody/MultibodySimulation.h"
#include "reduced/ReducedModel.h"
#include "scene/KeyEffects.h"
#include "scene/SceneParser.h"

namespace rollerdyn {
namespace {

// Loveikin and Pochka's (2007) recuperative drive (rigid), a few crank revolutions.
Scene recuperative(std::vector<std::string> sets, double t_end = 2.0) {
  sets.push_back("simulation.t_end=" + std::to_string(t_end));
  return parseSceneFile(std::string(ROLLERDYN_SOURCE_DIR) + "/model/recuperative-2cart.yaml", sets);
}

// Kloss's torque at the rotor, written out: M = 2·M_kr·s·s_kr/(s² + s_kr²), s = 1 − ω_r/ω0.
double kloss(const Scene& sc, double w_rotor) {
  const double s = 1.0 - w_rotor / sc.motor.omega_sync, skr = sc.motor.critical_slip;
  return 2.0 * sc.motor.breakdown_torque * s * skr / (s * s + skr * skr);
}

TEST(ReducerPowerFlow, ReducedModelLosesOneMinusEtaForwardMotoringAndOneOverEtaReverseMinusOneGenerating) {
  const Scene sc = recuperative({"reducer.losses=power_flow", "reducer.efficiency_reverse=0.8"});
  const ReducedModel m(sc);
  const double u = sc.reducer.ratio, eta_f = sc.reducer.efficiency;
  const double w_sync = sc.motor.omega_sync / u;
  for (double w : {0.97 * w_sync, 1.02 * w_sync}) {  // motoring, then generating
    Eigen::VectorXd y = m.initialState();
    y(m.iOmega()) = w;
    const ModelEvaluation e = m.evaluate(y);
    const double P = kloss(sc, w * u) * u * w;  // power at the reducer's motor shaft
    const double expected = P > 0 ? (1.0 - eta_f) * P : (1.0 / 0.8 - 1.0) * -P;
    EXPECT_NEAR(e.reducer_loss_power, expected, 1e-9 * std::abs(P)) << "w = " << w;
    EXPECT_NEAR(e.motor_torque * w, P - expected, 1e-9 * std::abs(P)) << "power passed on, w = " << w;
  }
}

TEST(ReducerPowerFlow, PapersDefaultIsMTimesUTimesEtaAndItsLossOneMinusEtaOfTheShaftPower) {
  const Scene sc = recuperative({});
  const RunResult r = runReducedModel(sc);
  ASSERT_TRUE(r.stats.complete) << r.stats.status;
  EXPECT_FALSE(r.timeseries.has("reducer_loss_torque"));  // the papers' tables keep their columns
  const double u = sc.reducer.ratio, eta = sc.reducer.efficiency;
  const std::vector<double> M = r.timeseries.column("motor_torque"), w = r.timeseries.column("omega_motor");
  for (std::size_t i = 0; i < M.size(); ++i)
    ASSERT_NEAR(M[i], kloss(sc, w[i] * u) * u * eta, 1e-9 * sc.motor.breakdown_torque * u) << "row " << i;
  // The papers' loss: (1 − η)·M·u·ω, i.e. (1 − η)/η of what the motor passes on: the motor shaft
  // work is motor_work/η.
  EXPECT_NEAR(r.energy.motorShaftWork(), r.energy.motor_work / eta, 1e-9 * std::abs(r.energy.motor_work));
}

TEST(ReducerPowerFlow, BothSettingsAgreeWhenTheReducerIsLossless) {
  // The runs differ in their integrated states (power_flow adds the losses' integral), so they
  // agree to the integration error, held small here.
  const RunResult a = runReducedModel(recuperative({"reducer.efficiency=1", "simulation.accuracy=1e-10"}));
  const RunResult b =
      runReducedModel(recuperative({"reducer.efficiency=1", "reducer.losses=power_flow", "simulation.accuracy=1e-10"}));
  ASSERT_TRUE(a.stats.complete && b.stats.complete);
  EXPECT_EQ(b.energy.reducer_losses, 0.0);
  EXPECT_EQ(a.energy.reducer_losses, 0.0);
  const std::vector<double> wa = a.timeseries.column("omega_crank"), wb = b.timeseries.column("omega_crank");
  ASSERT_EQ(wa.size(), wb.size());
  for (std::size_t i = 0; i < wa.size(); ++i) ASSERT_NEAR(wa[i], wb[i], 1e-7 * wa[i]) << "row " << i;
}

// ∫ L·ω dt by the trapezoidal rule over the output rows: a quadrature independent of the
// integrated state.
double trapezoidLosses(const RunResult& r) {
  const std::vector<double> t = r.timeseries.column("t"), L = r.timeseries.column("reducer_loss_torque"),
                            w = r.timeseries.column("omega_motor");
  double W = 0;
  for (std::size_t i = 1; i < t.size(); ++i) W += 0.5 * (L[i] * w[i] + L[i - 1] * w[i - 1]) * (t[i] - t[i - 1]);
  return W;
}

TEST(ReducerPowerFlow, EnergyBalanceClosesWithTheReducersColumnInBothModels) {
  for (const char* model : {"reduced", "multibody"}) {
    Scene sc = recuperative({"reducer.losses=power_flow", "reducer.efficiency_reverse=0.8", "simulation.output_step=0.001"});
    const RunResult r = std::string(model) == "reduced" ? runReducedModel(sc) : runMultibodyModel(sc);
    ASSERT_TRUE(r.stats.complete) << model << ": " << r.stats.status;
    const EnergyAudit& e = r.energy;
    EXPECT_GT(e.reducer_losses, 0.0) << model;
    // The motor's shaft work = reducer losses + what it passes on; the balance of the rest closes.
    EXPECT_LT(std::abs(e.residualRelative()), 1e-5) << model << ": residual " << e.residual() << " J";
    EXPECT_NEAR(e.reducer_losses, trapezoidLosses(r), 2e-3 * e.reducer_losses) << model;
  }
}

TEST(ReducerPowerFlow, BothModelsAgreeUnderPowerFlow) {
  const Scene sc = recuperative({"reducer.losses=power_flow", "reducer.efficiency_reverse=0.8"}, 3.0);
  const RunResult a = runReducedModel(sc), b = runMultibodyModel(sc);
  ASSERT_TRUE(a.stats.complete && b.stats.complete);
  EXPECT_NEAR(a.energy.reducer_losses, b.energy.reducer_losses, 1e-3 * a.energy.reducer_losses);
  EXPECT_NEAR(a.energy.motor_work, b.energy.motor_work, 1e-3 * a.energy.motor_work);
  const std::vector<double> wa = a.timeseries.column("omega_crank"), wb = b.timeseries.column("omega_crank");
  ASSERT_EQ(wa.size(), wb.size());
  double worst = 0;
  for (std::size_t i = 0; i < wa.size(); ++i) worst = std::max(worst, std::abs(wa[i] - wb[i]) / wa[i]);
  EXPECT_LT(worst, 1e-3);
}

TEST(ReducerPowerFlow, ReverseEfficiencyIsNamedAsWithoutEffectUnderThePapersLawOnly) {
  auto named = [](const Scene& sc) {
    for (const std::string& w : keysWithoutEffect(sc, "reduced"))
      if (w.rfind("reducer.efficiency_reverse", 0) == 0) return true;
    return false;
  };
  EXPECT_TRUE(named(recuperative({"reducer.efficiency_reverse=0.8"})));
  EXPECT_FALSE(named(recuperative({"reducer.efficiency_reverse=0.8", "reducer.losses=power_flow"})));
}

// Guide lift-off on shipped scenes (analysis/GuideLiftOff.h): the recuperative drive's carts rest
// on their guides (no roller normal forces: N < 0 throughout), the balanced 4-cart drive's front
// guide reactions swing through zero (the mix lifts the carts, R_j1 + R_j2 = 19.5 kN > G, and the
// rod's vertical force turns the front reaction over).
TEST(GuideLiftOffScenes, TheBalancedFourCartDrivesFrontGuidesChangeSignTheRecuperativeDrivesDoNot) {
  const Scene rest = recuperative({}, 8.0);
  const nlohmann::json a = makeSummary(rest, runReducedModel(rest));
  EXPECT_EQ(a["guide_lift_off"]["verdict"], "holds") << a["guide_lift_off"].dump();
  const Scene lifted = parseSceneFile(std::string(ROLLERDYN_SOURCE_DIR) + "/model/balanced-4cart.yaml", {});
  const nlohmann::json b = makeSummary(lifted, runReducedModel(lifted));
  const nlohmann::json& g = b["guide_lift_off"];
  ASSERT_EQ(g["verdict"], "lifts off") << g.dump();
  ASSERT_EQ(g["lifting"].size(), 4u) << g.dump();  // the four front guides, no rear one
  for (const auto& e : g["lifting"]) {
    EXPECT_EQ(e["guide"], "front");
    EXPECT_LT(e["worst_reaction"].get<double>() * e["prevailing_extreme"].get<double>(), 0.0);
    EXPECT_GT(e["time_fraction"].get<double>(), 0.0);
    EXPECT_LE(e["time_fraction"].get<double>(), 0.5);
  }
  int warned = 0;  // one line naming the four
  for (const auto& w : b["warnings"]) {
    const std::string text = w.get<std::string>();
    if (text.find("guide reactions change sign") == std::string::npos) continue;
    ++warned;
    for (int j = 1; j <= 4; ++j)
      EXPECT_NE(text.find("cart " + std::to_string(j) + " front"), std::string::npos) << text;
  }
  EXPECT_EQ(warned, 1);
}

}  // namespace
}  // namespace rollerdyn
