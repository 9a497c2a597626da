// The two models on the same motor law and the same starting method: the multibody model (both
// formulations) and the reduced model run the law of motor.model with the supply of
// motor.start / motor.stop, switching at the same events (timed ones at the same instants,
// speed-triggered ones by root finding in each integrator), so on the equivalence scenes
// (split rods, no guide friction: ModelComparison.h) they must agree as closely as without a
// starting method: crank speed and coupling torque to max_rel_diff <= 1e-6 at accuracy 1e-9
// (kEquivalenceTarget; the argument in test_equivalence.cpp). Runs of 1.5 s from rest: the
// start itself, where the switching happens.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "compare/ModelComparison.h"
#include "scene/SceneParser.h"

using namespace rollerdyn;

namespace {

std::string modelFile(const std::string& name) { return std::string(ROLLERDYN_SOURCE_DIR) + "/model/" + name; }

const std::vector<std::string> kEquivalent = {"rods.model=split", "loads.guide_friction.coefficient=0",
                                              "reduced.kinematics=exact", "reduced.integrator=cvode",
                                              "simulation.accuracy=1e-9", "simulation.t_end=1.5"};

ModelComparison compareOn(const std::vector<std::string>& sets, const std::string& file = "balanced-4cart.yaml") {
  std::vector<std::string> all = kEquivalent;
  all.insert(all.end(), sets.begin(), sets.end());
  return runComparison(parseSceneFile(modelFile(file), all));
}

void expectAgreement(const ModelComparison& c, const std::string& what) {
  ASSERT_TRUE(c.multibody.stats.complete) << what << ": " << c.multibody.stats.status;
  ASSERT_TRUE(c.reduced.stats.complete) << what << ": " << c.reduced.stats.status;
  const double dw = c.find("omega_crank")->stats.max_rel_diff, dM = c.find("coupling_torque")->stats.max_rel_diff;
  std::printf("  %-60s max rel. diff: crank speed %.3g, coupling torque %.3g\n", what.c_str(), dw, dM);
  EXPECT_LE(dw, 1e-6) << what;
  EXPECT_LE(dM, 1e-6) << what;
  // The motor columns of the rows (motor torque, the supply) agree as well: every row of both
  // tables is evaluated in the supply phase the run is in (rows interpolated after an event too).
  const Table &a = c.multibody.timeseries, &b = c.reduced.timeseries;
  for (const char* col : {"motor_torque", "supply_voltage_ratio", "stator_current"}) {
    if (!a.has(col) || !b.has(col)) continue;
    const int ia = a.index(col), ib = b.index(col);
    double diff = 0, scale = 0;
    for (std::size_t i = 0; i < a.rows.size() && i < b.rows.size(); ++i) {
      diff = std::max(diff, std::abs(a.rows[i][ia] - b.rows[i][ib]));
      scale = std::max(scale, std::abs(a.rows[i][ia]));
    }
    EXPECT_LE(diff, 1e-6 * scale) << what << ": column " << col << " differs by " << diff << " (scale " << scale << ")";
  }
}

// The motor state, the supply columns and the stator-current column exist in both tables alike.
void expectSameMotorColumns(const ModelComparison& c, const std::vector<std::string>& columns) {
  for (const std::string& col : columns) {
    EXPECT_TRUE(c.multibody.timeseries.has(col)) << col;
    EXPECT_TRUE(c.reduced.timeseries.has(col)) << col;
  }
}

TEST(EquivalenceStartUp, DynamicKlossDirectOnLine) {
  expectAgreement(compareOn({"motor.model=kloss_dynamic"}), "kloss_dynamic, direct on line at t = 0");
}

TEST(EquivalenceStartUp, StarDeltaByTimeWithOpenTransition) {
  const ModelComparison c = compareOn({"motor.model=kloss_dynamic", "motor.start.method=star_delta",
                                       "motor.start.changeover_time=0.4", "motor.start.changeover_gap=0.03"});
  expectAgreement(c, "kloss_dynamic, star-delta at 0.4 s, 30 ms open");
  expectSameMotorColumns(c, {"supply_voltage_ratio", "supply_frequency_ratio"});
}

TEST(EquivalenceStartUp, StarDeltaBySpeedFoundByRootFindingInBothModels) {
  const ModelComparison c = compareOn({"motor.model=kloss_dynamic", "motor.start.method=star_delta",
                                       "motor.start.changeover_speed=20"});
  expectAgreement(c, "kloss_dynamic, star-delta at 20 rad/s (minimal formulation)");
  // The changeover happened (the delta voltage is reached) in both.
  for (const RunResult* r : {&c.multibody, &c.reduced})
    EXPECT_EQ(r->timeseries.rows.back()[r->timeseries.index("supply_voltage_ratio")], 1.0) << r->model;
}

TEST(EquivalenceStartUp, StarDeltaBySpeedConstrainedFormulation) {
  const ModelComparison c = compareOn({"motor.model=kloss_dynamic", "motor.start.method=star_delta",
                                       "motor.start.changeover_speed=20", "simulation.formulation=constrained",
                                       "simulation.t_end=1.5"});
  expectAgreement(c, "kloss_dynamic, star-delta at 20 rad/s (constrained formulation)");
}

TEST(EquivalenceStartUp, SoftStarterRampStaticKloss) {
  expectAgreement(compareOn({"motor.start.method=soft_starter", "motor.start.initial_voltage=0.5",
                             "motor.start.ramp_time=0.8"}),
                  "kloss, soft starter 0.5 U_n over 0.8 s");
}

TEST(EquivalenceStartUp, FrequencyConverterRamp) {
  expectAgreement(compareOn({"motor.model=kloss_dynamic", "motor.start.method=frequency_converter",
                             "motor.start.initial_frequency=5", "motor.start.ramp_time=1", "motor.start.boost=0.03"}),
                  "kloss_dynamic, V/f ramp 5 -> 50 Hz over 1 s");
}

TEST(EquivalenceStartUp, LateSwitchOnSwitchOffBrakeAndRestart) {
  const ModelComparison c =
      compareOn({"motor.model=kloss_dynamic", "motor.start.t_on=0.1", "motor.stop.t_off=0.9",
                 "motor.stop.brake_torque=150", "motor.stop.brake_delay=0.05", "motor.stop.t_restart=1.2"});
  expectAgreement(c, "kloss_dynamic, on 0.1 s, off 0.9 s, brake, restart 1.2 s");
  expectSameMotorColumns(c, {"supply_voltage_ratio", "brake_torque"});
  // The brake dissipates energy, accounted in both audits alike.
  EXPECT_GT(c.multibody.energy.brake_dissipation, 0.0);
  EXPECT_NEAR(c.multibody.energy.brake_dissipation, c.reduced.energy.brake_dissipation,
              1e-6 * c.multibody.energy.brake_dissipation);
}

// The space-phasor machine fitted to the paper's catalogue (4 flux states, switching transient).
TEST(EquivalenceStartUp, ParkDirectOnLineAndStarDelta) {
  expectAgreement(compareOn({"motor.model=park", "simulation.output_step=0.001"}), "park, direct on line at t = 0");
  const ModelComparison c = compareOn({"motor.model=park", "motor.start.method=star_delta",
                                       "motor.start.changeover_time=0.6", "motor.start.changeover_gap=0.02"});
  expectAgreement(c, "park, star-delta at 0.6 s, 20 ms open");
  expectSameMotorColumns(c, {"stator_current", "supply_voltage_ratio"});
}

TEST(EquivalenceStartUp, ParkSoftStartWithCurrentLimitAndRestartAtSpeed) {
  expectAgreement(compareOn({"motor.model=park", "motor.start.method=soft_starter", "motor.start.initial_voltage=0.35",
                             "motor.start.ramp_time=0.8", "motor.start.current_limit=120"}),
                  "park, soft starter 0.35 U_n over 0.8 s, 120 A limit");
  expectAgreement(compareOn({"motor.model=park", "motor.stop.t_off=0.9", "motor.stop.t_restart=1.0"}),
                  "park, off at 0.9 s, on again at 1.0 s (residual flux)");
}

}  // namespace
