// The reducer's load spectrum and application factor after ISO 6336-6 (analysis/GearDuty.h) on
// synthetic runs whose spectra are known by construction, against hand calculations of
//   T_eq = (Σ n_i·T_i^p / N_L)^(1/p),  K_A = T_eq / (u·η·M_n);
// each check made to FAIL and to be "not applicable" with the key or the run to fix it.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "analysis/DriveSizing.h"
#include "analysis/GearDuty.h"
#include "analysis/RunResult.h"
#include "analysis/SizingChecks.h"
#include "analysis/StartUp.h"
#include "scene/Scene.h"

namespace rollerdyn {
namespace {

constexpr double kTwoPi = 6.283185307179586;

TEST(GearDuty, EquivalentTorqueOfAHandBuiltSpectrumIsMinersMeanOfTorqueToThePowerP) {
  // Three classes, p = 3: (600·1000³ + 300·1500³ + 100·2000³)/1000 = 0.6e9 + 1.0125e9 + 0.8e9 = 2.4125e9.
  const std::vector<TorqueClass> c = {{1000, 600}, {1500, 300}, {2000, 100}};
  EXPECT_NEAR(equivalentTorque(c, 3.0, 1000), std::cbrt(2.4125e9), 1e-6);
  // p = 6.61 (flanks of case-hardened steel): a heavier weight on the largest class.
  const double hand = std::pow((600 * std::pow(1000, 6.61) + 300 * std::pow(1500, 6.61) + 100 * std::pow(2000, 6.61)) / 1000,
                               1 / 6.61);
  EXPECT_NEAR(equivalentTorque(c, 6.61, 1000), hand, 1e-6 * hand);
  EXPECT_GT(hand, std::cbrt(2.4125e9));
  // Cycles of the other flank count in N_L without torque on this one: 1000 more revolutions halve Σ.
  EXPECT_NEAR(equivalentTorque(c, 3.0, 2000), std::cbrt(2.4125e9 / 2), 1e-6);
}

// Rows of a crank turning at 1 rev/s from `t0` (angle phi0) with the torque T for `revs` revolutions
// (a row at each quarter revolution); the first row repeats the previous row's time and angle, so
// a step of the torque falls on no interval.
void segment(Table& ts, double t0, double phi0, double revs, double T) {
  for (int i = 0; i <= static_cast<int>(std::lround(4 * revs)); ++i)
    ts.rows.push_back({t0 + i / 4.0, phi0 + kTwoPi * i / 4.0, T});
}

TEST(GearDuty, TheSpectrumCountsCrankRevolutionsPerTorqueClassWithTheReversedTorqueOnTheOtherFlank) {
  Table ts;
  ts.columns = {"t", "phi_crank", "coupling_torque"};
  segment(ts, 0, 0, 2, 1000);              // 2 revolutions at 1000 N·m
  segment(ts, 2, 2 * kTwoPi, 1, 2000);     // 1 at 2000 N·m
  segment(ts, 3, 3 * kTwoPi, 1, -500);     // 1 at −500 N·m: the other flank
  const GearSpectrum s = loadSpectrum(ts, 0, ts.rows.size(), 100.0, 3.0);
  ASSERT_TRUE(s.applies) << s.not_applicable;
  EXPECT_NEAR(s.revolutions, 4.0, 1e-12);
  ASSERT_EQ(s.drive.classes.size(), 2u);
  EXPECT_NEAR(s.drive.classes[0].torque, 1000, 1e-9);
  EXPECT_NEAR(s.drive.classes[0].cycles, 2.0, 1e-12);
  EXPECT_NEAR(s.drive.classes[1].torque, 2000, 1e-9);
  EXPECT_NEAR(s.drive.classes[1].cycles, 1.0, 1e-12);
  ASSERT_EQ(s.coast.classes.size(), 1u);
  EXPECT_NEAR(s.coast.classes[0].torque, 500, 1e-9);
  EXPECT_NEAR(s.coast.cycles, 1.0, 1e-12);
  // Hand, p = 3, N_L = 4: drive (2·1e9 + 8e9)/4 = 2.5e9; other flank 1.25e8/4.
  EXPECT_NEAR(s.drive.equivalent_torque, std::cbrt(2.5e9), 1e-6);
  EXPECT_NEAR(s.coast.equivalent_torque, std::cbrt(1.25e8 / 4), 1e-6);
}

TEST(GearDuty, ATorqueBetweenClassLimitsCountsAtTheUpperLimit) {
  Table ts;
  ts.columns = {"t", "phi_crank", "coupling_torque"};
  segment(ts, 0, 0, 1, 1010);
  const GearSpectrum s = loadSpectrum(ts, 0, ts.rows.size(), 100.0, 3.0);
  ASSERT_EQ(s.drive.classes.size(), 1u);
  EXPECT_NEAR(s.drive.classes[0].torque, 1100, 1e-9);  // (1000, 1100]
}

// The run: a start from rest t = 0 ... 1 s, half a revolution at 4000 N·m; t = 1 ... 2 s one
// revolution at 1500 N·m (neither window); the steady window t = 2 ... 6 s: 3 revolutions at 1000 N·m,
// then 1 at 2000 N·m. The largest |T| is 4000 N·m, so the classes are 100 N·m wide and every torque
// lies on a class limit.
RunResult gearRun() {
  RunResult run;
  Table& ts = run.timeseries;
  ts.columns = {"t", "phi_crank", "coupling_torque"};
  ts.rows.push_back({0.0, 0.0, 4000});
  ts.rows.push_back({1.0, kTwoPi / 2, 4000});
  segment(ts, 1, kTwoPi / 2, 1, 1500);
  segment(ts, 2, 1.5 * kTwoPi, 3, 1000);
  segment(ts, 5, 4.5 * kTwoPi, 1, 2000);
  return run;
}

SteadyState gearWindow(const RunResult& run, bool reached = true) {
  SteadyState w;
  w.reached = reached;
  w.t_begin = 2.0;
  w.t_end = 6.0;
  w.row_begin = 7;  // 2 rows of the start, 5 of the second segment
  w.row_end = run.timeseries.rows.size();
  w.finite_rows = w.row_end;
  w.not_reached = reached ? "" : "steady state not reached within the run: run at least 12 s (simulation.t_end)";
  return w;
}

StartUp gearStart(bool from_rest = true) {
  StartUp s;
  s.applicable = true;
  s.from_rest = from_rest;
  s.starts = true;
  s.t_on = 0;
  s.start_end = 1.0;
  return s;
}

// u = 10, η = 0.9, M_n = 100 N·m: T_n = 900 N·m.
Scene gearScene(double K_A = 2.0, double T_2N = 1700, double T_2max = 4500, double starts = 0, double M_n = 100) {
  Scene s{};
  s.reducer.ratio = 10;
  s.reducer.efficiency = 0.9;
  s.sizing.motor_nominal_torque = M_n;
  s.sizing.starts_per_hour = starts;
  s.sizing.reducer.application_factor = K_A;
  s.sizing.reducer.rated_torque = T_2N;
  s.sizing.reducer.max_torque = T_2max;
  s.sizing.reducer.sn_exponent = 6.61;
  return s;
}

DriveSizing sized(const Scene& sc, bool from_rest = true, bool reached = true) {
  const RunResult run = gearRun();
  const StartUp su = gearStart(from_rest);
  DriveSizing s;
  s.motion = "turning";
  s.steady_reached = reached;
  s.steady_not_reached = gearWindow(run, reached).not_reached;
  s.gear = computeGearDuty(sc, run, gearWindow(run, reached), &su);
  return s;
}

std::vector<SizingCheck> checks(const DriveSizing& s) {
  std::vector<SizingCheck> out;
  appendDutyChecks(s, true, out);
  return out;
}

const SizingCheck& named(const std::vector<SizingCheck>& c, const std::string& name) {
  for (const SizingCheck& k : c)
    if (k.name == name) return k;
  throw std::runtime_error("no check " + name);
}

// Hand: steady window, p = 6.61, N_L = 4: T_eq = ((3·1000^p + 2000^p)/4)^(1/p) ≈ 1629 N·m; K_A = T_eq/900 ≈ 1.81.
const double kP = 6.61;
const double kSteadyTeq = std::pow((3 * std::pow(1000.0, kP) + std::pow(2000.0, kP)) / 4, 1 / kP);

TEST(GearDuty, ApplicationFactorOfContinuousRunningIsTheSteadyEquivalentTorqueOverUEtaMn) {
  const DriveSizing s = sized(gearScene());
  const GearDuty& g = s.gear;
  ASSERT_TRUE(g.duty_applies) << g.duty_not_applicable;
  EXPECT_NEAR(g.class_width, 100.0, 1e-9);
  EXPECT_NEAR(g.nominal_torque, 900.0, 1e-9);
  EXPECT_NEAR(g.steady.revolutions, 4.0, 1e-9);
  EXPECT_NEAR(g.start.revolutions, 0.5, 1e-9);
  EXPECT_NEAR(g.equivalent_torque, kSteadyTeq, 1e-6 * kSteadyTeq);
  EXPECT_NEAR(g.application_factor, kSteadyTeq / 900, 1e-6);
  EXPECT_NEAR(g.equivalent_torque_coast, 0.0, 1e-12);
  EXPECT_EQ(g.deciding_flank, "drive flank");
  EXPECT_NEAR(g.peak, 4000, 1e-9);
  for (const SizingCheck& k : checks(s)) EXPECT_EQ(k.verdict, "pass") << k.name << ": " << k.reason;
}

TEST(GearDuty, StartsPerHourAddTheStartsSpectrumToAnHourOfSteadyRunning) {
  const DriveSizing s = sized(gearScene(2.0, 1700, 4500, 10));
  // Hand: 10 starts of 0.5 rev at 4000 N·m and (3600 − 10·1 s)/4 s = 897.5 steady windows of 4 revolutions.
  const double n_steady = 897.5, N_L = 10 * 0.5 + n_steady * 4;
  const double sum = 10 * 0.5 * std::pow(4000.0, kP) + n_steady * (3 * std::pow(1000.0, kP) + std::pow(2000.0, kP));
  const double hand = std::pow(sum / N_L, 1 / kP);
  EXPECT_NEAR(s.gear.hour_revolutions, N_L, 1e-9);
  EXPECT_NEAR(s.gear.equivalent_torque, hand, 1e-6 * hand);
  EXPECT_GT(hand, kSteadyTeq);
}

TEST(GearDuty, EachGearCheckFailsWhenItsLimitIsExceeded) {
  const SizingCheck ka = named(checks(sized(gearScene(1.75))), "gear_application_factor");  // K_A 1.81 > 1.75
  EXPECT_EQ(ka.verdict, "FAIL") << ka.reason;
  EXPECT_NEAR(ka.value, kSteadyTeq / 900 / 1.75, 1e-6);
  EXPECT_NE(ka.what.find("ISO 6336-6"), std::string::npos);
  EXPECT_EQ(named(checks(sized(gearScene(2.0, 1600))), "gear_rated_torque").verdict, "FAIL");        // 1629 > 1600
  EXPECT_EQ(named(checks(sized(gearScene(2.0, 1700, 3900))), "gear_max_torque").verdict, "FAIL");    // 4000 > 3900
}

TEST(GearDuty, MissingInputsOrWindowsMakeTheChecksNotApplicableWithTheKeyToSet) {
  const SizingCheck no_ka = named(checks(sized(gearScene(0))), "gear_application_factor");
  EXPECT_EQ(no_ka.verdict, "not applicable");
  EXPECT_NE(no_ka.reason.find("sizing.reducer.application_factor"), std::string::npos) << no_ka.reason;
  const SizingCheck no_mn = named(checks(sized(gearScene(2.0, 1700, 4500, 0, 0))), "gear_application_factor");
  EXPECT_EQ(no_mn.verdict, "not applicable");
  EXPECT_NE(no_mn.reason.find("sizing.motor_nominal_torque"), std::string::npos) << no_mn.reason;
  EXPECT_NE(named(checks(sized(gearScene(2.0, 0))), "gear_rated_torque").reason.find("sizing.reducer.rated_torque"),
            std::string::npos);
  // Starts per hour without a start from rest in the run: the duty's spectrum is not known.
  const std::vector<SizingCheck> no_start = checks(sized(gearScene(2.0, 1700, 4500, 10), false));
  for (const char* name : {"gear_application_factor", "gear_rated_torque", "gear_max_torque"}) {
    EXPECT_EQ(named(no_start, name).verdict, "not applicable") << name;
    EXPECT_NE(named(no_start, name).reason.find("initial.crank_speed: 0"), std::string::npos) << named(no_start, name).reason;
  }
  const SizingCheck not_steady = named(checks(sized(gearScene(), true, false)), "gear_application_factor");
  EXPECT_EQ(not_steady.verdict, "not applicable");
  EXPECT_NE(not_steady.reason.find("simulation.t_end"), std::string::npos) << not_steady.reason;
}

TEST(GearDuty, NothingIsComputedWithoutAReducerRating) {
  Scene sc = gearScene(0, 0, 0);
  EXPECT_FALSE(sized(sc).gear.requested);
  EXPECT_TRUE(checks(sized(sc)).empty());
}

}  // namespace
}  // namespace rollerdyn
