// A key the run names as without effect changes nothing in it, and a key that changes nothing is
// named: each rule checked on a real run by changing the key's value (the consistency harness
// found these silently ignored: the Kloss law's current data, Kloss's critical slip under a fitted
// circuit, a switch-off after the run's end, a changeover speed the motor never reached).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "reduced/ReducedModel.h"
#include "scene/SceneParser.h"
#include "studies/RunSummary.h"

namespace rollerdyn {
namespace {

using nlohmann::json;

json summaryOf(const std::vector<std::string>& sets) {
  const Scene s = parseSceneFile(std::string(ROLLERDYN_SOURCE_DIR) + "/model/balanced-4cart.yaml", sets);
  return summarizeRun(s, runReducedModel(s), RunSummaryOptions{}, nullptr);
}

// The summary without what differs between any two runs (timings) or names the keys themselves.
json figures(json j) {
  for (const char* k : {"cpu_seconds", "real_time_factor", "overrides", "keys_without_effect", "warnings"}) j.erase(k);
  if (j.contains("performance")) j.erase("performance");
  if (j.contains("start_up") && j["start_up"].is_object()) j["start_up"].erase("keys_not_reached");
  return j;
}

bool named(const json& summary, const std::string& key) {
  for (const json& w : summary["keys_without_effect"])
    if (w.get<std::string>().rfind(key + " has no effect", 0) == 0) return true;
  return false;
}

// `key` is named in a run with `base` and changes no figure when set to `other`.
void expectWithoutEffect(std::vector<std::string> base, const std::string& key, const std::string& value,
                         const std::string& other) {
  std::vector<std::string> a = base, b = base;
  a.push_back(key + "=" + value);
  b.push_back(key + "=" + other);
  const json ja = summaryOf(a), jb = summaryOf(b);
  EXPECT_TRUE(named(ja, key)) << key << ": " << ja["keys_without_effect"].dump();
  EXPECT_EQ(figures(ja), figures(jb)) << key << " " << value << " -> " << other << " changed a figure";
}

const std::vector<std::string> kShort = {"simulation.t_end=6"};

TEST(KeysWithoutEffectInRuns, TheKlossLawsCurrentDataChangeNothing) {
  expectWithoutEffect(kShort, "motor.voltage", "380", "418");
  expectWithoutEffect(kShort, "motor.catalogue.current", "41.27", "45");
  expectWithoutEffect(kShort, "motor.catalogue.power_factor", "0.9", "0.85");
  // Under a law fitted to the catalogue they are its data, and not named.
  const json circuit = summaryOf({"simulation.t_end=6", "motor.model=circuit"});
  EXPECT_FALSE(named(circuit, "motor.voltage"));
  EXPECT_FALSE(named(circuit, "motor.catalogue.current"));
}

TEST(KeysWithoutEffectInRuns, KlossCriticalSlipChangesNothingUnderAFittedCircuit) {
  expectWithoutEffect({"simulation.t_end=6", "motor.model=circuit"}, "motor.overload_ratio", "2.4", "2.2");
  // Where λ gives the nominal torque (no other source of M_n), it is read, and not named.
  const json kloss = summaryOf(kShort);
  EXPECT_FALSE(named(kloss, "motor.overload_ratio"));
}

// Kloss's M_kr under a circuit fitted to the catalogue: the integrators' torque scale and the
// reducer's power-flow band read the circuit's own breakdown torque, so the key changes nothing
// (the consistency harness found it silently ignored, seed 3064 of its generated machines).
TEST(KeysWithoutEffectInRuns, KlossBreakdownTorqueChangesNothingUnderAFittedCircuit) {
  expectWithoutEffect({"simulation.t_end=6", "motor.model=circuit"},
                      "motor.breakdown_torque", "517.14", "800");
  expectWithoutEffect({"simulation.t_end=6", "motor.model=circuit",
                       "reducer.losses=power_flow"},
                      "motor.breakdown_torque", "517.14", "800");
  // Under the Kloss law it is the law itself, and not named.
  EXPECT_FALSE(named(summaryOf({"simulation.t_end=6", "motor.breakdown_torque=517.14"}), "motor.breakdown_torque"));
}

// One cart has no second crank: the angle between consecutive cranks places nothing (the
// consistency harness's seed 3258).
TEST(KeysWithoutEffectInRuns, TheCrankOffsetOfASingleCartChangesNothing) {
  expectWithoutEffect({"simulation.t_end=6", "carts.count=1"}, "crank.offset_deg", "195", "210");
  EXPECT_FALSE(named(summaryOf({"simulation.t_end=6", "crank.offset_deg=80"}), "crank.offset_deg"));
}

// A bearing's rating turns its load into a life; without reactions no joint is loaded (the
// consistency harness's seed 3577: sizing.bearing_rating.main_bearing under simulation.reactions:
// false changed nothing and was not named).
TEST(KeysWithoutEffectInRuns, BearingRatingsChangeNothingWithoutReactions) {
  const std::vector<std::string> off = {"simulation.t_end=6", "simulation.reactions=false"};
  expectWithoutEffect(off, "sizing.bearing_rating.guide_roller", "43000", "47000");
  expectWithoutEffect(off, "sizing.bearing_rating.rod_end", "250000", "275000");
  // With reactions the rating gives the guide rollers' life: read, and not named.
  EXPECT_FALSE(named(summaryOf({"simulation.t_end=6", "simulation.reactions=true",
                                "sizing.bearing_rating.guide_roller=43000"}),
                     "sizing.bearing_rating.guide_roller"));
}

TEST(KeysWithoutEffectInRuns, ASwitchOffAfterTheRunsEndChangesNothing) {
  expectWithoutEffect({"simulation.t_end=6", "motor.stop.brake_torque=50"}, "motor.stop.t_off", "100", "110");
  const json within = summaryOf({"simulation.t_end=6", "motor.stop.t_off=4"});
  EXPECT_FALSE(named(within, "motor.stop.t_off"));
}

TEST(KeysWithoutEffectInRuns, AChangeoverSpeedTheMotorNeverReachesChangesNothing) {
  // Six carts of 1200 kg stall in star: the star's third of the starting torque cannot break away.
  const std::vector<std::string> stalls = {"carts.count=6", "crank.offset_deg=60", "carts.mass=1200",
                                           "loads.rolling_resistance=0.1", "initial.crank_speed=0",
                                           "motor.start.method=star_delta", "simulation.t_end=3"};
  expectWithoutEffect(stalls, "motor.start.changeover_speed", "95", "100");
  // The default machine reaches it and changes over: read, and not named.
  const json starts = summaryOf({"initial.crank_speed=0", "motor.start.method=star_delta",
                                 "motor.start.changeover_speed=95", "simulation.t_end=6"});
  EXPECT_FALSE(named(starts, "motor.start.changeover_speed"));
}

TEST(KeysWithoutEffectInRuns, AnInitialTwistOfARigidCouplingChangesNothing) {
  expectWithoutEffect({"simulation.t_end=2", "coupling.type=rigid"}, "initial.twist", "0", "0.001");
  EXPECT_FALSE(named(summaryOf({"simulation.t_end=2", "initial.twist=0.001"}), "initial.twist"));
}

TEST(KeysWithoutEffectInRuns, TheEndOfARunAStallEndedEarlyChangesNothing) {
  const std::vector<std::string> stalls = {"carts.count=6", "crank.offset_deg=60", "carts.mass=1200",
                                           "loads.rolling_resistance=0.1", "initial.crank_speed=0"};
  expectWithoutEffect(stalls, "simulation.t_end", "3", "4");
  // A run that completes is read to its end.
  EXPECT_FALSE(named(summaryOf(kShort), "simulation.t_end"));
}

// The catalogue's breakdown ratio under a Kloss law with its own M_kr: the check of the two against
// each other is shown as a figure, (M_k/M_n)·P_n/ω_n, whether they agree or not (4A200M6U3: P_n =
// 22 kW, ω_n = 102.1 rad/s).
TEST(KeysWithoutEffectInRuns, TheCataloguesBreakdownTorqueStandsBesideKlossMkr) {
  const json j = summaryOf({"simulation.t_end=6", "motor.catalogue.breakdown_torque_ratio=2.28"});
  EXPECT_NEAR(j["sizing"]["motor"]["breakdown_torque_catalogue"].get<double>(), 2.28 * 22000.0 / 102.1, 1e-9);
  EXPECT_FALSE(named(j, "motor.catalogue.breakdown_torque_ratio"));
}

}  // namespace
}  // namespace rollerdyn
