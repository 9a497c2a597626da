// The motor's duty after IEC 60034-1: S1 (continuous running, no starts per hour given) or S4
// (intermittent periodic duty with starting: sizing.starts_per_hour starts, the load's inertia run
// up each time, no electric braking). From the run's start from rest (StartUp.h):
//   Q_start   the rotor's heat of one start, the start-up answers' rotor energy loss
//             ∫ M·(ω0·f/f_n − ω_r) dt (s·P_airgap, one computation) [J]
//   t_D       the start's duration, switch-on to the start's end [s]
//   locked-rotor time: the rotor's losses at standstill are P_s = M_s·ω0 (s = 1, all the air-gap
//             power is heat; M_s the law's torque at standstill under the rated supply), so one
//             start heats the rotor like t_eq = Q_start / P_s at standstill; it must stay within
//             the catalogue's permissible locked-rotor time t_E (sizing.motor.locked_rotor_time).
//   starts per hour: an unloaded start without load inertia heats the rotor by ½·J_M·ω0² (the
//             rotor heat of a run-up without load torque equals the kinetic energy at ω0); the
//             catalogue's Z_0 such starts per hour (sizing.motor.no_load_starts) are the rotor's
//             heat budget for starts, of which the steady load uses its share (steady rotor losses
//             over the nominal ones, s·M·ω0 / s_n·M_n·ω0):
//             Z = Z_0·(½·J_M·ω0²/Q_start)·(1 − P_steady/P_n,rotor), and N <= Z.
//   ED        the starting time's share of the hour N·t_D/3600 s; the cyclic duration factor of S4
//             is (t_D + t_N)/(t_D + t_N + t_R), whose rest t_R the scene does not give: the motor is
//             taken energized between starts (ED = 100 %, the heating check's assumption, on the safe
//             side); N·t_D >= 3600 s is no duty at all.
// Approximations named: stator and iron losses are taken to scale like the rotor's; the rotor's
// heat capacity is the catalogue's, met by the same heat whatever the run-up's course.
#pragma once

#include <string>

namespace rollerdyn {

struct Scene;
struct DriveSizing;
struct StartUp;

struct MotorDuty {
  bool requested = false;             // sizing.motor.locked_rotor_time or no_load_starts given
  std::string duty_type;              // "S1" or "S4"
  std::string designation;            // e.g. "S4 - 30 starts/h - J_M = 0.5 kg·m² - J_ext = 12 kg·m²"
  double starts_per_hour = 0;         // N [1/h]
  bool start_known = false;           // the run holds a start from rest with its rotor heat
  std::string start_unknown;          // why not, and what to do
  double start_time = 0;              // t_D [s]
  double start_heat = 0;              // Q_start [J]
  double locked_rotor_torque = 0;     // M_s at the rotor, rated supply [N·m]
  double locked_rotor_losses = 0;     // P_s = M_s·ω0 [W]
  double equivalent_locked_time = 0;  // t_eq = Q_start / P_s [s]
  double locked_rotor_time = 0;       // t_E [s]; NaN: not given
  double rotor_inertia = 0;           // J_M [kg·m²]
  double load_inertia = 0;            // J_ext at the motor shaft [kg·m²]
  double no_load_start_heat = 0;      // ½·J_M·ω0² [J]
  double no_load_starts = 0;          // Z_0 [1/h]; NaN: not given
  double steady_loss_share = 0;       // P_steady / P_n,rotor [-]
  double permissible_starts = 0;      // Z [1/h]
  double starting_time_share = 0;     // N·t_D / 3600 s [-]
  double locked_time_ratio = 0;       // t_eq / t_E [-]
  double starts_ratio = 0;            // N / Z [-]
};

// `start_up`: the run's start-up answers (null: none); the sizing's motor figures give the steady
// and nominal rotor losses.
MotorDuty computeMotorDuty(const Scene& scene, const DriveSizing& sizing, const StartUp* start_up);

}  // namespace rollerdyn
