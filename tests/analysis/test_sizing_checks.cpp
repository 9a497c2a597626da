// The sign-off checks (analysis/SizingChecks.h) on hand-set figures: each limit at its boundary (a
// value just inside passes, just outside fails), and each precondition: without it the check is
// "not applicable" with the reason, never a pass or a FAIL.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "analysis/SizingChecks.h"

namespace rollerdyn {
namespace {

// A turning drive at steady state, started from rest in the run, every figure within its limit.
DriveSizing workingDrive() {
  DriveSizing s;
  s.motion = "turning";
  s.steady_reached = true;
  s.start_simulated = true;
  s.can_start_from_rest = 1;
  s.start_verdict = "the drive starts: ...";
  s.start_load_ratio = 0.5;
  s.motor.available = true;
  s.motor.rms_over_nominal = 0.8;
  s.motor.whole_run.thermal_over_nominal = 0.7;
  s.motor.whole_run.continuous_running = true;
  s.motor.whole_run.starts_per_hour = 40;
  s.motor.peak_over_breakdown = 0.5;
  s.coupling.available = true;
  s.coupling.rating = 1000;
  s.coupling.peak = s.coupling.peak_whole_run = 500;
  s.coupling.peak_over_rating = s.coupling.peak_over_rating_whole_run = 0.5;
  return s;
}

const SizingCheck& check(const std::vector<SizingCheck>& checks, const std::string& name) {
  for (const SizingCheck& c : checks)
    if (c.name == name) return c;
  throw std::runtime_error("no check " + name);
}

std::string verdict(const DriveSizing& s, const std::string& name) { return check(sizingChecks(s, true), name).verdict; }

TEST(SizingChecks, EveryCheckOfAWorkingDrivePasses) {
  const std::vector<SizingCheck> c = sizingChecks(workingDrive(), true);
  ASSERT_EQ(c.size(), 4u);
  for (const SizingCheck& k : c) EXPECT_EQ(k.verdict, "pass") << k.name << ": " << k.reason;
}

// IEC 60034-1 zone A: M_kr at 95 % voltage is 0.95² = 0.9025 of its rating. A steady peak of
// 0.929·M_kr (between 0.9025 and 0.95) must fail.
TEST(SizingChecks, TheBreakdownLimitIsNinetyFivePercentSquared) {
  DriveSizing s = workingDrive();
  s.motor.peak_over_breakdown = 0.9025 * (1 - 1e-9);
  EXPECT_EQ(verdict(s, "motor_breakdown"), "pass");
  s.motor.peak_over_breakdown = 0.9025 * (1 + 1e-9);
  EXPECT_EQ(verdict(s, "motor_breakdown"), "FAIL");
  s.motor.peak_over_breakdown = 0.929;
  EXPECT_EQ(verdict(s, "motor_breakdown"), "FAIL");
}

TEST(SizingChecks, HeatingAndCouplingLimitsAreOneInclusive) {
  DriveSizing s = workingDrive();
  s.motor.rms_over_nominal = 1.0;
  EXPECT_EQ(verdict(s, "motor_heating"), "pass");
  s.motor.rms_over_nominal = 1.0 + 1e-9;
  EXPECT_EQ(verdict(s, "motor_heating"), "FAIL");
  s = workingDrive();
  s.coupling.peak_over_rating_whole_run = 1.0;
  s.coupling.peak_whole_run = 1000;
  EXPECT_EQ(verdict(s, "coupling"), "pass");
  s.coupling.peak_over_rating_whole_run = 1.0 + 1e-9;
  s.coupling.peak_whole_run = 1000 * (1.0 + 1e-9);
  EXPECT_EQ(verdict(s, "coupling"), "FAIL");
}

// A run too short for a steady state never gets a steady-window pass or FAIL (a 3 s run of the
// circuit motor read "motor_breakdown 1.000 FAIL" and "motor_heating 2.644 FAIL" from a window that
// held the start). A coupling peak above the rating happened all the same: that FAIL stands.
TEST(SizingChecks, WithoutASteadyStateTheSteadyChecksDoNotApply) {
  DriveSizing s = workingDrive();
  s.steady_reached = false;
  s.steady_not_reached = "steady state not reached within the run (...): run at least 6 s (simulation.t_end)";
  s.motor.peak_over_breakdown = 1.0;
  s.motor.rms_over_nominal = 2.6;
  const std::vector<SizingCheck> c = sizingChecks(s, true);
  for (const char* name : {"motor_heating", "motor_breakdown", "coupling"}) {
    EXPECT_EQ(check(c, name).verdict, "not applicable") << name;
    EXPECT_NE(check(c, name).reason.find("run at least 6 s"), std::string::npos) << check(c, name).reason;
  }
  s.coupling.peak_over_rating_whole_run = 2.0;
  s.coupling.peak_whole_run = 2000;
  EXPECT_EQ(verdict(s, "coupling"), "FAIL");
}

// Starts per hour only for a drive that can start: a run at speed of a drive whose starting
// torque is below the load at the start angle read "motor_heating 0.809 pass" for ten starts an hour.
TEST(SizingChecks, ADutyOfStartsNeedsADriveThatCanStartAndASimulatedStart) {
  DriveSizing s = workingDrive();
  s.motor.whole_run.continuous_running = false;
  s.motor.whole_run.duty_starts_per_hour = 10;
  s.start_simulated = false;
  s.can_start_from_rest = 0;
  s.start_load_ratio = 1393.0 / 1032.0;
  s.stall_cause = "the motor's starting torque 1032 N·m at the crank ... is below the load torque 1393 N·m";
  const std::vector<SizingCheck> c = sizingChecks(s, true);
  EXPECT_EQ(check(c, "start").verdict, "FAIL");
  EXPECT_NEAR(check(c, "start").value, 1393.0 / 1032.0, 1e-12);
  EXPECT_NE(check(c, "start").reason.find("1393"), std::string::npos);
  EXPECT_EQ(check(c, "motor_heating").verdict, "not applicable");
  EXPECT_NE(check(c, "motor_heating").reason.find("cannot start from rest"), std::string::npos);
  EXPECT_EQ(check(c, "coupling").verdict, "not applicable");  // the start's peak is not in the run
  // A drive that can start, run at speed: the start's heat is not known, so neither is the duty.
  s.can_start_from_rest = 1;
  s.start_load_ratio = 0.5;
  const std::vector<SizingCheck> d = sizingChecks(s, true);
  EXPECT_EQ(check(d, "start").verdict, "pass");
  EXPECT_NE(check(d, "start").reason.find("not simulated"), std::string::npos);
  EXPECT_EQ(check(d, "motor_heating").verdict, "not applicable");
  EXPECT_NE(check(d, "motor_heating").reason.find("holds no start from rest"), std::string::npos);
}

// The start check from a run from rest follows the run, and never shows a figure that says the
// opposite of its verdict (torques that allow a start, held back by the inertia and the dead centre).
TEST(SizingChecks, TheStartCheckFollowsTheRunFromRest) {
  DriveSizing s = workingDrive();
  s.motion = "stalled";
  s.start_verdict = "the drive does not reach a steady turning motion within the run: ...";
  const SizingCheck c = check(sizingChecks(s, false), "start");
  EXPECT_EQ(c.verdict, "FAIL");
  EXPECT_TRUE(std::isnan(c.value));
  EXPECT_NE(c.reason.find("0.5"), std::string::npos) << c.reason;
  s.motion = "starting";
  EXPECT_EQ(check(sizingChecks(s, false), "start").verdict, "not applicable");
}

}  // namespace
}  // namespace rollerdyn
