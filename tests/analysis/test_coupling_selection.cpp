// The coupling selection after DIN 740-2 (analysis/CouplingSelection.h) on a synthetic run whose
// figures are known by construction, against hand calculations with the method's formulas
// (KTR, "Coupling selection according to DIN 740 part 2"):
//   T_KN >= T_N·S_t,  T_Kmax >= T_S·S_A·S_z·S_t,  T_KW >= T_W·S_t·S_f (S_f = √(f/10 Hz) above 10 Hz),
//   P_KW >= P_W·S_t;
// each check made to FAIL and to be "not applicable" with its reason.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "analysis/CouplingSelection.h"
#include "analysis/DriveSizing.h"
#include "analysis/RunResult.h"
#include "analysis/SizingChecks.h"
#include "analysis/StartUp.h"
#include "scene/Scene.h"

namespace rollerdyn {
namespace {

constexpr double kPi = 3.141592653589793;

TEST(CouplingSelection, TheFrequencyFactorIsOneUpToTenHertzAndRootAbove) {
  EXPECT_EQ(frequencyFactor(5), 1.0);
  EXPECT_EQ(frequencyFactor(10), 1.0);
  EXPECT_DOUBLE_EQ(frequencyFactor(40), 2.0);
}

// The run: start t = 0 ... 1 s with a torque peak of -3000 N·m; steady window t = 2 ... 4 s with
// the crank at 2.5 rev/s and T = 1000 + 400·cos(6φ) (order 6: f = 15 Hz, S_f = √1.5), the twist
// rate Δω = 0.1·sin(6φ) rad/s, so with k = 2000 N·m·s/rad the mean k·Δω² is 2000·0.01/2 = 10 W.
RunResult syntheticRun() {
  RunResult run;
  run.timeseries.columns = {"t", "phi_crank", "coupling_torque", "twist_rate"};
  run.timeseries.rows.push_back({0.0, 0.0, 0.0, 0.0});
  run.timeseries.rows.push_back({0.5, 0.1, -3000.0, 0.0});
  run.timeseries.rows.push_back({1.0, 0.2, 800.0, 0.0});
  const double omega = 2 * kPi * 2.5;
  for (int i = 0; i <= 600; ++i) {
    const double t = 2.0 + i / 300.0, phi = omega * (t - 2.0) + 1.0;
    run.timeseries.rows.push_back({t, phi, 1000 + 400 * std::cos(6 * (phi - 1.0)), 0.1 * std::sin(6 * (phi - 1.0))});
  }
  return run;
}

SteadyState steadyWindow(bool reached = true) {
  SteadyState w;
  w.reached = reached;
  w.t_begin = 2.0;
  w.t_end = 4.0;
  w.row_begin = 3;
  w.row_end = 604;
  w.finite_rows = 604;
  w.not_reached = reached ? "" : "steady state not reached within the run: run at least 8 s (simulation.t_end)";
  return w;
}

StartUp startFromRest(bool from_rest = true) {
  StartUp s;
  s.applicable = true;
  s.from_rest = from_rest;
  s.starts = true;
  s.t_on = 0;
  s.start_end = 1.0;
  return s;
}

// Ratings chosen so every check passes by a few per cent: S_t = 1.4, S_z = 1.2, S_A = 1.
Scene sceneWith(double T_KN = 2000, double T_Kmax = 6000, double T_KW = 700, double P_KW = 15, bool rigid = false) {
  Scene s{};
  s.coupling.type = rigid ? CouplingType::Rigid : CouplingType::Elastic;
  s.coupling.damping = 2000;
  CouplingRatings& c = s.sizing.coupling;
  c.rated_torque = T_KN;
  c.max_torque = T_Kmax;
  c.vibratory_torque = T_KW;
  c.damping_power = P_KW;
  c.temperature_factor = 1.4;
  c.start_factor = 1.2;
  c.shock_factor = 1.0;
  return s;
}

std::vector<SizingCheck> checks(const Scene& sc, bool from_rest = true, bool reached = true) {
  const StartUp su = startFromRest(from_rest);
  DriveSizing s;
  s.motion = "turning";
  s.steady_reached = reached;
  s.steady_not_reached = steadyWindow(reached).not_reached;
  s.coupling_selection = computeCouplingSelection(sc, syntheticRun(), steadyWindow(reached), &su);
  std::vector<SizingCheck> out;
  appendSignOffChecks(s, true, out);
  return out;
}

const SizingCheck& named(const std::vector<SizingCheck>& c, const std::string& name) {
  for (const SizingCheck& k : c)
    if (k.name == name) return k;
  throw std::runtime_error("no check " + name);
}

TEST(CouplingSelection, FiguresOfTheRunMatchTheHandValues) {
  const StartUp su = startFromRest();
  const CouplingSelection c = computeCouplingSelection(sceneWith(), syntheticRun(), steadyWindow(), &su);
  EXPECT_EQ(c.start_peak, 3000.0);
  EXPECT_NEAR(c.steady_peak, 1400.0, 1e-6);
  EXPECT_NEAR(c.steady_amplitude, 400.0, 1e-6);
  EXPECT_EQ(c.excitation_order, 6);
  EXPECT_NEAR(c.excitation_frequency, 15.0, 1e-9);
  EXPECT_NEAR(c.S_f, std::sqrt(1.5), 1e-9);
  EXPECT_NEAR(c.damping_power_run, 10.0, 1e-6);
  // Hand: 1400·1.4/2000 = 0.98; 3000·1·1.2·1.4/6000 = 0.84; 400·1.4·√1.5/700 = 0.9798; 10·1.4/15 = 0.9333.
  EXPECT_NEAR(c.rated_ratio, 0.98, 1e-9);
  EXPECT_NEAR(c.max_ratio, 0.84, 1e-9);
  EXPECT_NEAR(c.vibratory_ratio, 400 * 1.4 * std::sqrt(1.5) / 700, 1e-9);
  EXPECT_NEAR(c.damping_ratio, 14.0 / 15.0, 1e-6);
  for (const SizingCheck& k : checks(sceneWith())) EXPECT_EQ(k.verdict, "pass") << k.name << ": " << k.reason;
}

TEST(CouplingSelection, EachCheckFailsWhenItsRatingIsTooSmall) {
  EXPECT_EQ(named(checks(sceneWith(1900)), "coupling_rated_torque").verdict, "FAIL");             // 1.032
  EXPECT_EQ(named(checks(sceneWith(2000, 5000)), "coupling_max_torque").verdict, "FAIL");         // 1.008
  EXPECT_EQ(named(checks(sceneWith(2000, 6000, 600)), "coupling_vibratory_torque").verdict, "FAIL");  // 1.143
  EXPECT_EQ(named(checks(sceneWith(2000, 6000, 700, 12)), "coupling_damping_power").verdict, "FAIL");  // 1.167
}

TEST(CouplingSelection, WithoutASteadyWindowTheRunningChecksAreNotApplicable) {
  const std::vector<SizingCheck> c = checks(sceneWith(), true, false);
  for (const char* name : {"coupling_rated_torque", "coupling_vibratory_torque", "coupling_damping_power"}) {
    EXPECT_EQ(named(c, name).verdict, "not applicable") << name;
    EXPECT_NE(named(c, name).reason.find("simulation.t_end"), std::string::npos) << named(c, name).reason;
  }
}

TEST(CouplingSelection, WithoutAStartTheMaximumTorqueCannotPass) {
  const SizingCheck& k = named(checks(sceneWith(), false), "coupling_max_torque");
  EXPECT_EQ(k.verdict, "not applicable");
  EXPECT_NE(k.reason.find("initial.crank_speed: 0"), std::string::npos) << k.reason;
}

TEST(CouplingSelection, ARigidCouplingsDampingPowerIsNotApplicable) {
  const SizingCheck& k = named(checks(sceneWith(2000, 6000, 700, 15, true)), "coupling_damping_power");
  EXPECT_EQ(k.verdict, "not applicable");
  EXPECT_NE(k.reason.find("rigid"), std::string::npos) << k.reason;
}

TEST(CouplingSelection, OnlyTheGivenRatingsAreChecked) {
  const std::vector<SizingCheck> c = checks(sceneWith(2000, 0, 0, 0));
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].name, "coupling_rated_torque");
  EXPECT_TRUE(checks(Scene{}).empty());
}

}  // namespace
}  // namespace rollerdyn
