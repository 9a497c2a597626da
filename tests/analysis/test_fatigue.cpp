// Rainflow counting (analysis/Rainflow.h) against the worked example of ASTM E1049-85, Miner's
// rule (analysis/Fatigue.h) against hand calculations, and the fatigue checks: each made to FAIL
// and to be "not applicable" with its reason.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include "analysis/DriveSizing.h"
#include "analysis/Fatigue.h"
#include "analysis/Rainflow.h"
#include "analysis/RunResult.h"
#include "analysis/SizingChecks.h"
#include "analysis/SizingSummary.h"
#include "analysis/StartUp.h"
#include "scene/Scene.h"

namespace rollerdyn {
namespace {

// ASTM E1049-85 (reapproved 2017), section 5.4.4, rainflow counting: the worked load history
// -2, 1, -3, 5, -1, 3, -4, 4, -2 of its figure, counted by hand with the three-point rules:
//   A-B (range 3) half, B-C (4) half, E-F (-1..3, range 4) one cycle, C-D (8) half,
//   residue D-G (9), G-H (8), H-I (6) halves.
// The standard's table of the example: range 9: 0.5, 8: 1.0, 6: 0.5, 4: 1.5, 3: 0.5 (10, 7, 5: 0),
// the same counts that independent implementations document as their check against this figure
// (MATLAB's rainflow reference page; the Python package rainflow's tests).
TEST(Rainflow, ReproducesTheWorkedExampleOfAstmE1049) {
  const std::vector<RainflowCycle> cycles = rainflow({-2, 1, -3, 5, -1, 3, -4, 4, -2});
  std::map<double, double> count_by_range;
  for (const RainflowCycle& c : cycles) count_by_range[c.range] += c.count;
  const std::map<double, double> astm = {{3, 0.5}, {4, 1.5}, {6, 0.5}, {8, 1.0}, {9, 0.5}};
  EXPECT_EQ(count_by_range, astm);
  // The one full cycle is -1 .. 3: range 4, mean 1.
  int full = 0;
  for (const RainflowCycle& c : cycles)
    if (c.count == 1.0) {
      ++full;
      EXPECT_EQ(c.range, 4.0);
      EXPECT_EQ(c.mean, 1.0);
    }
  EXPECT_EQ(full, 1);
}

TEST(Rainflow, TurningPointsDropPointsOnTheWayAndPlateaus) {
  EXPECT_EQ(turningPoints({0, 1, 2, 2, 1, 0, 0, 3}), (std::vector<double>{0, 2, 0, 3}));
  EXPECT_EQ(turningPoints({5, 5, 5}), (std::vector<double>{5}));
}

// A big reversal -1000 .. 1000 .. -1000 with two inner cycles 200 .. 600 (hand count: two full
// cycles of range 400, mean 400; two half cycles of range 2000, mean 0).
const std::vector<double> kStartHistory = {-1000, 1000, 200, 600, 200, 600, -1000};
// S-N curve: S_D = 300 at N_D = 1e6, m = 5.
SnCurve curve(double ultimate = 0) {
  SnCurve c;
  c.endurance_amplitude = 300;
  c.knee_cycles = 1e6;
  c.slope = 5;
  c.ultimate = ultimate;
  return c;
}
// Hand: N(1000) = 1e6·0.3^5 = 2430; the half pair is one cycle: D = 1/2430.
const double kDamageBig = 1.0 / 2430.0;
// Haibach below the knee, slope 2m - 1 = 9: N(200) = 1e6·1.5^9 = 3.8443e7, two cycles.
const double kDamageInnerHaibach = 2.0 / (1e6 * std::pow(1.5, 9));

TEST(Miner, DamageOfAHistoryMatchesTheHandSumWithHaibachsExtension) {
  const MinerResult m = minerDamage(rainflow(kStartHistory), curve(), true);
  EXPECT_NEAR(m.damage, kDamageBig + kDamageInnerHaibach, 1e-12);
  EXPECT_DOUBLE_EQ(m.cycles, 3.0);
  ASSERT_EQ(m.top.size(), 3u);
  EXPECT_EQ(m.top[0].range, 2000.0);
  EXPECT_NEAR(m.top[0].damage, 0.5 / 2430.0, 1e-15);
}

TEST(Miner, TheCutOffKneeLeavesCyclesBelowItHarmless) {
  const MinerResult m = minerDamage(rainflow(kStartHistory), curve(), false);
  EXPECT_NEAR(m.damage, kDamageBig, 1e-15);
}

// Goodman with S_u = 2000: the inner cycles (amplitude 200, mean 400) act as 200/(1 - 0.2) = 250,
// N = 1e6·1.2^9; the big cycles have mean 0 and stay.
TEST(Miner, GoodmansLineRaisesTheAmplitudeOfCyclesWithAMean) {
  const MinerResult m = minerDamage(rainflow(kStartHistory), curve(2000), true);
  EXPECT_NEAR(m.damage, kDamageBig + 2.0 / (1e6 * std::pow(1.2, 9)), 1e-12);
  EXPECT_EQ(cyclesToFailure(curve(), true, goodmanAmplitude(curve(2000), 10, 2500)), 1.0);  // |S_m| > S_u
}

// A synthetic run: the start (t = 0 ... 1 s) holds kStartHistory, then the torque rests at -1000;
// the steady window t = 2 ... 4 s alternates ±500 forty times (20 cycles of amplitude 500).
RunResult syntheticRun() {
  RunResult run;
  run.timeseries.columns = {"t", "coupling_torque"};
  for (std::size_t i = 0; i < kStartHistory.size(); ++i) run.timeseries.rows.push_back({0.1 * i, kStartHistory[i]});
  run.timeseries.rows.push_back({1.5, -1000});
  for (int i = 0; i <= 40; ++i) run.timeseries.rows.push_back({2.0 + 0.05 * i, i % 2 ? -500.0 : 500.0});
  return run;
}
// Hand: 20/N(500), N(500) = 1e6·0.6^5; per hour ×3600 s/2 s.
const double kDamagePerHour = 20.0 / (1e6 * std::pow(0.6, 5)) * 1800.0;

StartUp startFromRest() {
  StartUp s;
  s.applicable = true;
  s.from_rest = true;
  s.starts = true;
  s.t_on = 0;
  s.start_end = 1.0;
  return s;
}

SteadyState steadyWindow(bool reached = true) {
  SteadyState w;
  w.reached = reached;
  w.t_begin = 2.0;
  w.t_end = 4.0;
  w.not_reached = reached ? "" : "steady state not reached within the run: run at least 8 s (simulation.t_end)";
  return w;
}

Scene sceneWith(double required_starts, double required_hours, bool coupling_curve = true) {
  Scene s{};
  if (coupling_curve) s.sizing.fatigue.coupling_torque = curve();
  s.sizing.fatigue.required_starts = required_starts;
  s.sizing.fatigue.required_hours = required_hours;
  return s;
}

TEST(Fatigue, DamagePerStartAndPerHourMatchTheHandCalculation) {
  const StartUp su = startFromRest();
  const FatigueSizing f = computeFatigue(sceneWith(0, 0), syntheticRun(), steadyWindow(), &su);
  ASSERT_EQ(f.signals.size(), 1u);
  const SignalFatigue& g = f.signals[0];
  EXPECT_NEAR(g.damage_per_start, kDamageBig + kDamageInnerHaibach, 1e-12);
  EXPECT_NEAR(g.starts_to_failure, 1.0 / (kDamageBig + kDamageInnerHaibach), 1e-6);
  EXPECT_NEAR(g.damage_per_hour, kDamagePerHour, 1e-9);
  EXPECT_NEAR(g.hours_to_failure, 1.0 / kDamagePerHour, 1e-9);
}

const SizingCheck& checkNamed(const std::vector<SizingCheck>& checks, const std::string& name) {
  for (const SizingCheck& c : checks)
    if (c.name == name) return c;
  throw std::runtime_error("no check " + name);
}

std::vector<SizingCheck> fatigueChecks(const Scene& sc, const StartUp* su, const SteadyState& w) {
  DriveSizing s;
  s.motion = "turning";
  s.steady_reached = w.reached;
  s.fatigue = computeFatigue(sc, syntheticRun(), w, su);
  std::vector<SizingCheck> out;
  appendSignOffChecks(s, true, out);
  return out;
}

// Allowed starts 1/D = 2425: 2400 required pass, 2500 fail.
TEST(FatigueChecks, RequiredStartsBeyondTheAllowedFail) {
  const StartUp su = startFromRest();
  const double allowed = 1.0 / (kDamageBig + kDamageInnerHaibach);
  EXPECT_EQ(checkNamed(fatigueChecks(sceneWith(2400, 0), &su, steadyWindow()), "fatigue_starts_coupling_torque").verdict,
            "pass");
  const SizingCheck c = checkNamed(fatigueChecks(sceneWith(2500, 0), &su, steadyWindow()), "fatigue_starts_coupling_torque");
  EXPECT_EQ(c.verdict, "FAIL");
  EXPECT_NEAR(c.value, 2500 / allowed, 1e-9);
}

TEST(FatigueChecks, RequiredHoursBeyondTheAllowedFail) {
  const StartUp su = startFromRest();
  const double hours = 1.0 / kDamagePerHour;  // 2.16 h
  EXPECT_EQ(checkNamed(fatigueChecks(sceneWith(0, 0.9 * hours), &su, steadyWindow()), "fatigue_hours_coupling_torque").verdict,
            "pass");
  EXPECT_EQ(checkNamed(fatigueChecks(sceneWith(0, 1.1 * hours), &su, steadyWindow()), "fatigue_hours_coupling_torque").verdict,
            "FAIL");
}

TEST(FatigueChecks, NoStartInTheRunIsNotApplicable) {
  StartUp su = startFromRest();
  su.from_rest = false;
  const SizingCheck c = checkNamed(fatigueChecks(sceneWith(1e9, 0), &su, steadyWindow()), "fatigue_starts_coupling_torque");
  EXPECT_EQ(c.verdict, "not applicable");
  EXPECT_NE(c.reason.find("initial.crank_speed: 0"), std::string::npos) << c.reason;
  EXPECT_TRUE(std::isnan(c.value));
}

TEST(FatigueChecks, NoSteadyWindowIsNotApplicable) {
  const StartUp su = startFromRest();
  const SizingCheck c = checkNamed(fatigueChecks(sceneWith(0, 1e9), &su, steadyWindow(false)), "fatigue_hours_coupling_torque");
  EXPECT_EQ(c.verdict, "not applicable");
  EXPECT_NE(c.reason.find("steady state not reached"), std::string::npos) << c.reason;
}

TEST(FatigueChecks, ARequirementWithoutAnSnCurveIsNotApplicable) {
  const StartUp su = startFromRest();
  const std::vector<SizingCheck> c = fatigueChecks(sceneWith(1e9, 1e9, false), &su, steadyWindow());
  const SizingCheck& k = checkNamed(c, "fatigue_starts_coupling_torque");
  EXPECT_EQ(k.verdict, "not applicable");
  EXPECT_NE(k.reason.find("sizing.fatigue.coupling_torque"), std::string::npos) << k.reason;
  EXPECT_EQ(checkNamed(c, "fatigue_hours_rod_force").verdict, "not applicable");
}

TEST(FatigueChecks, NothingGivenMeansNoFatigueChecksAndNullInTheSummary) {
  const StartUp su = startFromRest();
  EXPECT_TRUE(fatigueChecks(Scene{}, &su, steadyWindow()).empty());
  EXPECT_TRUE(fatigueJson(computeFatigue(Scene{}, syntheticRun(), steadyWindow(), &su)).is_null());
}

TEST(FatigueSummary, TheJsonCarriesTheDamagesAndTheDominantCycles) {
  const StartUp su = startFromRest();
  const nlohmann::json j = fatigueJson(computeFatigue(sceneWith(0, 0), syntheticRun(), steadyWindow(), &su));
  const nlohmann::json& g = j["signals"]["coupling_torque"];
  EXPECT_NEAR(g["damage_per_hour"].get<double>(), kDamagePerHour, 1e-9);
  EXPECT_EQ(g["per_start"]["dominant_cycles"][0]["range"].get<double>(), 2000.0);
  const std::string text = signOffText({{"fatigue", j}});
  EXPECT_NE(text.find("per start"), std::string::npos) << text;
}

}  // namespace
}  // namespace rollerdyn
