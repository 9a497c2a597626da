// The motor's starts after IEC 60034-1 (analysis/MotorDuty.h) from a start whose rotor heat and
// torques are given, against hand calculations of
//   t_eq = Q_start/(M_s·ω0) <= t_E,  Z = Z_0·(½·J_M·ω0²/Q_start)·(1 − P_steady/P_n,rotor) >= N,
//   N·t_D/3600 s < 1;
// each check made to FAIL and to be "not applicable" with the key or the run to fix it.
#include <gtest/gtest.h>

#include <string>

#include "analysis/DriveSizing.h"
#include "analysis/MotorDuty.h"
#include "analysis/SizingChecks.h"
#include "analysis/StartUp.h"
#include "scene/Scene.h"

namespace rollerdyn {
namespace {

// ω0 = 100 rad/s, J_M = 0.5 kg·m², u = 10, η = 0.9; t_E = 10 s, Z_0 = 1000 per hour.
Scene dutyScene(double starts = 20, double t_E = 10, double Z_0 = 1000) {
  Scene s{};
  s.motor.omega_sync = 100;
  s.motor.rotor_inertia = 0.5;
  s.reducer.ratio = 10;
  s.reducer.efficiency = 0.9;
  s.sizing.starts_per_hour = starts;
  s.sizing.motor.locked_rotor_time = t_E;
  s.sizing.motor.no_load_starts = Z_0;
  return s;
}

// A start of t_D = 2 s putting Q_start = 30 kJ into the rotor; M_s = 500 N·m at the rotor, so
// 4500 N·m at the crank (× u·η).
StartUp dutyStart(bool from_rest = true) {
  StartUp s;
  s.applicable = true;
  s.from_rest = from_rest;
  s.starts = true;
  s.t_on = 0;
  s.start_end = 2.0;
  s.rotor_energy_loss = 30000;
  s.starting_torque_rated_crank = 4500;
  return s;
}

// Steady rotor losses 500 W of the nominal 2000 W; the drive's inertia 200 kg·m² at the crank.
DriveSizing dutySized(const Scene& sc, bool from_rest = true, bool reached = true) {
  DriveSizing s;
  s.motion = "turning";
  s.steady_reached = reached;
  s.steady_not_reached = reached ? "" : "steady state not reached within the run: run at least 12 s (simulation.t_end)";
  s.motor.whole_run.steady_rotor_losses = 500;
  s.motor.whole_run.nominal_rotor_losses = 2000;
  s.flywheel.inertia_effective = 200;
  const StartUp su = dutyStart(from_rest);
  s.motor_duty = computeMotorDuty(sc, s, &su);
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

TEST(MotorDuty, FiguresOfTheStartMatchTheHandValues) {
  const MotorDuty m = dutySized(dutyScene()).motor_duty;
  EXPECT_EQ(m.duty_type, "S4");
  ASSERT_TRUE(m.start_known) << m.start_unknown;
  EXPECT_NEAR(m.locked_rotor_torque, 500, 1e-9);           // 4500/(10·0.9)
  EXPECT_NEAR(m.locked_rotor_losses, 50000, 1e-6);         // 500·100
  EXPECT_NEAR(m.equivalent_locked_time, 0.6, 1e-12);       // 30000/50000
  EXPECT_NEAR(m.no_load_start_heat, 2500, 1e-9);           // ½·0.5·100²
  EXPECT_NEAR(m.steady_loss_share, 0.25, 1e-12);
  EXPECT_NEAR(m.permissible_starts, 62.5, 1e-9);           // 1000·2500/30000·0.75
  EXPECT_NEAR(m.starting_time_share, 20 * 2 / 3600.0, 1e-12);
  EXPECT_NEAR(m.load_inertia, 1.5, 1e-12);                 // 200/10² − 0.5
  for (const SizingCheck& k : checks(dutySized(dutyScene()))) EXPECT_EQ(k.verdict, "pass") << k.name << ": " << k.reason;
}

TEST(MotorDuty, EachDutyCheckFailsBeyondItsLimit) {
  const SizingCheck t = named(checks(dutySized(dutyScene(20, 0.5))), "motor_locked_rotor_time");  // 0.6 s > 0.5 s
  EXPECT_EQ(t.verdict, "FAIL") << t.reason;
  EXPECT_NEAR(t.value, 1.2, 1e-12);
  EXPECT_NE(t.what.find("IEC 60034-1"), std::string::npos);
  const SizingCheck z = named(checks(dutySized(dutyScene(70))), "motor_starts_per_hour");  // 70 > 62.5
  EXPECT_EQ(z.verdict, "FAIL") << z.reason;
  EXPECT_NEAR(z.value, 70 / 62.5, 1e-12);
  const SizingCheck share = named(checks(dutySized(dutyScene(2000))), "motor_starting_time");  // 2000·2 s > 3600 s
  EXPECT_EQ(share.verdict, "FAIL") << share.reason;
  EXPECT_NEAR(share.value, 4000 / 3600.0, 1e-12);
}

TEST(MotorDuty, MissingInputsOrAStartMakeTheChecksNotApplicableWithTheKeyToSet) {
  const SizingCheck no_tE = named(checks(dutySized(dutyScene(20, 0))), "motor_locked_rotor_time");
  EXPECT_EQ(no_tE.verdict, "not applicable");
  EXPECT_NE(no_tE.reason.find("sizing.motor.locked_rotor_time"), std::string::npos) << no_tE.reason;
  const SizingCheck no_Z0 = named(checks(dutySized(dutyScene(20, 10, 0))), "motor_starts_per_hour");
  EXPECT_EQ(no_Z0.verdict, "not applicable");
  EXPECT_NE(no_Z0.reason.find("sizing.motor.no_load_starts"), std::string::npos) << no_Z0.reason;
  // Duty S1: no starts per hour to judge, but one start must still fit the locked-rotor time.
  const DriveSizing s1 = dutySized(dutyScene(0));
  EXPECT_EQ(s1.motor_duty.duty_type, "S1");
  for (const char* name : {"motor_starts_per_hour", "motor_starting_time"}) {
    EXPECT_EQ(named(checks(s1), name).verdict, "not applicable") << name;
    EXPECT_NE(named(checks(s1), name).reason.find("sizing.starts_per_hour"), std::string::npos);
  }
  EXPECT_EQ(named(checks(s1), "motor_locked_rotor_time").verdict, "pass");
  // A run that begins turning holds no start: every duty check says how to get one.
  for (const SizingCheck& k : checks(dutySized(dutyScene(), false))) {
    EXPECT_EQ(k.verdict, "not applicable") << k.name;
    EXPECT_NE(k.reason.find("initial.crank_speed: 0"), std::string::npos) << k.reason;
  }
  const SizingCheck not_steady = named(checks(dutySized(dutyScene(), true, false)), "motor_starts_per_hour");
  EXPECT_EQ(not_steady.verdict, "not applicable");
  EXPECT_NE(not_steady.reason.find("simulation.t_end"), std::string::npos) << not_steady.reason;
}

TEST(MotorDuty, NothingIsComputedWithoutAMotorRating) {
  EXPECT_FALSE(dutySized(dutyScene(20, 0, 0)).motor_duty.requested);
  EXPECT_TRUE(checks(dutySized(dutyScene(20, 0, 0))).empty());
}

}  // namespace
}  // namespace rollerdyn
