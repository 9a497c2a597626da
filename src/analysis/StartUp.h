// The start-up and stopping answers of one run, computed once from its tables (so both models get
// the same figures from the same columns) with the scene's motor law (motor.model) and starting
// method (motor.start, motor.stop):
//   - does the drive start, and if not, why: the law's torque at standstill under the supply at
//     switch-on (MotorLaw::steadyTorque at ω_r = 0, × u·η) against the load torque at the start
//     angle, and the law's largest torque against the load averaged over a revolution;
//   - the run-up time: from the switch-on until the crank first reaches 95 % of the steady mean
//     crank speed;
//   - the peaks during the start against the steady state's: motor torque (largest and most
//     negative), |coupling torque|, and the joint reactions of every kind;
//   - the stator current (where the law has one): peak, RMS and I²t over the start;
//   - the rotor energy loss of the start, ∫ M·(ω0·f/f_n - ω_r) dt: the slip power, which for a
//     start without load equals J·ω0²/2, the classical result (J the inertia at the rotor);
//   - after a switch-off: the stopping time and how far the crank and the carts run on.
//
// Intervals. The start runs from the switch-on t_on until the crank speed settles (the first
// revolution from which the per-revolution mean speed stays within the steady-state tolerance,
// SteadyState.h), so it does not grow with simulation.t_end; for a drive that does not start it is
// the whole run before any switch-off. The steady window is that of SteadyState.h found on the
// rows before the switch-off (the coast-down after t_off is no steady state). Integrals over time
// use the trapezoidal rule on the output rows (simulation.output_step): a supply-frequency
// transient (20 ms period at 50 Hz) needs an output step of 1 ms or less for I²t and the rotor
// loss to be accurate to a few per cent.
//
// Notation: u reducer ratio, η reducer efficiency, ω_r rotor speed, ω0 synchronous rotor speed,
// M motor torque at the rotor (the timeseries' motor_torque is M·u·η at the crank).
#pragma once

#include <string>
#include <vector>

#include "analysis/RunMotion.h"
#include "analysis/RunResult.h"
#include "motor/MotorLaw.h"
#include "scene/Scene.h"

namespace rollerdyn {

// One kind of joint: the largest |force| during the start and in the steady window [N].
struct StartJointPeak {
  std::string joint;      // guide_roller_front, guide_roller_rear, rod_force, crank_pin, main_bearing
  std::string column;     // reactions column of the largest start value (crank pin, bearing: x|y resultant)
  double start_peak = 0;  // [N]
  double steady_peak = 0; // [N]
  double ratio = 0;       // start_peak / steady_peak [-]
};

// A soft starter's current limit over one start (motor.start.current_limit > 0, Supply.h): how
// long it held, at what voltage and current, and how it ended. Every double is NaN when it does
// not apply or cannot be computed.
struct StartUpCurrentLimit {
  bool applies = false;         // a current-limited soft start from rest in this run
  double limit = 0;             // I_lim [A]
  double bypass_speed = 0;      // ω_lim: the rotor speed from which the law's steady current at U_n
                                // stays within I_lim (Supply::limitSpeed) [rad/s]
  double max_start_time = 0;    // [s]; NaN: the starter never trips (motor.start.max_start_time = 0)
  std::string outcome;          // "bypass": the motor came up to speed and the bypass closed;
                                // "tripped": still limited at t_on + max_start_time;
                                // "switched_off": motor.stop.t_off came first;
                                // "limited_at_end": still limited when the run ended
  double end_time = 0;          // when the bypass closed, the starter tripped or the motor was
                                // switched off [s]; NaN when still limited at the run's end
  double held_time = 0;         // from the switch-on to end_time, or to the run's end [s]
  double binding_from = 0;      // first output row at which the limit held U below the ramp [s];
                                // NaN: it never acted
  double voltage_min = 0;       // smallest U/U_n while the limit held U below the ramp, before
                                // end_time (at standstill I_lim/I_1(0)) [-]; NaN: it never acted
  double current_peak = 0;      // largest stator current from the switch-on to end_time [A]
  double standstill_voltage = 0;       // U/U_n the limit allows at standstill, I_lim/I_1(0) (≤ 1) [-]
  double standstill_torque_crank = 0;  // the law's torque at standstill under it × u·η [N·m]
  double breakaway_limit = 0;   // the limit whose standstill torque equals the load at the start
                                // angle (torque ∝ U² at a given speed) [A]; NaN without loads
  double rotor_speed_max = 0;   // the largest rotor speed before end_time [rad/s]
  bool stopped_the_start = false;  // the limit is why the drive did not start: the starter
                                   // tripped, or it still held a drive that had not started
                                   // when the run ended (the verdict says how)
};

// Every double is NaN when it does not apply or cannot be computed.
struct StartUp {
  bool applicable = false;      // a motor is switched on within the run
  std::string method;           // starting method, in words
  std::string motor_law;        // MotorLaw::description()
  std::string model_word;       // motor.model: kloss, kloss_dynamic, circuit, park
  double t_on = 0;              // switch-on [s]
  bool supply_switches = false; // the starting method changes the supply during the run (Supply::constant false)
  bool from_rest = true;        // the machine is at rest when the motor is switched on at t = 0
                                // (false: the run begins already turning, initial.crank_speed)
  // Whether it can start (from the law and the loads, before looking at the run).
  double starting_torque_crank = 0;        // steadyTorque(supply at switch-on, ω_r = 0)·u·η [N·m]
  double starting_torque_rated_crank = 0;  // the same under the rated supply [N·m]
  double largest_torque_crank = 0;         // max over ω_r of steadyTorque(rated)·u·η [N·m]
  // The supply the starting method holds while the rotor stands still (every timed step of the
  // start applied; a step triggered by speed never comes at standstill): star for a star-delta
  // changeover by speed, the rated supply after a timed changeover or a ramp.
  std::string held_supply;                 // that supply in words
  bool held_supply_is_rated = true;        // that supply is the rated one (U_n, f_n, delta)
  double starting_torque_held_crank = 0;   // steadyTorque(held supply, ω_r = 0)·u·η [N·m]
  double largest_torque_held_crank = 0;    // max over ω_r of steadyTorque(held supply)·u·η [N·m]
  double load_torque_start = 0;            // load at the start angle (StartLoad) [N·m at the crank]
  double load_torque_mean = 0;             // load averaged over a revolution [N·m at the crank]
  // Whether the motor can start the machine from rest, from these torques and the loads alone
  // (before looking at the run): 1 yes, 0 no, -1 not known (the loads were not evaluated).
  int can_start_from_rest = -1;
  // How near the drive is to not starting: the larger of load at the start angle / starting torque
  // and mean load / largest torque, both under the held supply (> 1: it cannot start) [-]; NaN
  // when the loads are not known.
  double start_load_ratio = 0;
  // Why a drive does not start or does not run, in one sentence from the torques against the loads;
  // the run status, the start-up answers and the sizing all print this one (never their own). When
  // the torques allow a start: the load peaks near a dead centre with the inertia. "" when the
  // loads are not known.
  std::string stall_cause;
  // What the run did.
  bool starts = false;          // the crank reached 95 % of the steady mean speed
  bool still_starting = false;  // the run ended before the drive settled (motion "starting",
                                // RunMotion.h): whether it starts is not known yet
  std::string verdict;          // one or two sentences: starts in ..., or does not start because ...
  double steady_mean_speed = 0; // mean crank speed of the steady window [rad/s]
  bool steady_reached = false;  // SteadyState::reached for the window used
  double steady_begin = 0, steady_end = 0;  // the steady window [s]
  double run_up_time = 0;       // t(ω_crank ≥ 0.95·steady mean) - t_on [s]
  double start_end = 0;         // end of the start interval [s]: where the crank speed settles
                                // (SteadyState::t_settled, not before the run-up ends) for a drive
                                // that starts; the end of the running rows for one that does not;
                                // else the steady window's begin
  // Peaks, start against steady.
  double motor_torque_peak = 0, motor_torque_min = 0;  // largest and most negative M·u·η in the start [N·m, crank]
  double motor_torque_steady_peak = 0;                 // max |M·u·η| in the steady window [N·m]
  double coupling_torque_peak = 0, coupling_torque_steady_peak = 0;  // max |coupling torque| [N·m]
  std::vector<StartJointPeak> joints;
  // Stator current over the start (laws with a current).
  double current_peak = 0, current_rms = 0, current_i2t = 0;  // [A], [A], [A²·s]
  double current_steady_rms = 0;                              // [A]
  double rotor_energy_loss = 0;  // ∫ M·(ω0·f/f_n - ω_r) dt over the start, while connected [J]
  // Stopping.
  double t_off = 0;                  // switch-off [s]; NaN: never
  double stopping_time = 0;          // until |ω_crank| ≤ 1 % of ω0/u [s]; NaN: not within the run
  double run_out_revolutions = 0;    // crank revolutions from t_off to the stop (or the run's end) [-]
  double run_out_cart_path = 0;      // largest distance a cart travels in that time [m]
  std::vector<std::string> notes;    // what the law cannot show; approximations named
  // Keys the scene gives whose event this run's start never reached (a star-delta changeover speed
  // the motor never attained): "key has no effect on this run: why", joined by the run's summary
  // to the keys without effect (KeyEffects.h) so the one warning line names them.
  std::vector<std::string> keys_not_reached;
  StartUpCurrentLimit current_limit; // a soft starter's current limit (applies false without one)
};

// `law`: the scene's motor law (null: none, e.g. the motor disabled); `load`: the load torques at
// the start (studies/StartLoad.h), may be null; `motion`: the run's motion (RunMotion.h, found on
// the same running window) when known, so that the answers never contradict it: a stalled or
// rocking drive does not start, a drive still "starting" has no run-up time yet, a "turning"
// crank may dip backwards at a dead centre; "" judges from the rows alone.
StartUp computeStartUp(const Scene& scene, const RunResult& run, const MotorLaw* law, const StartLoad* load,
                       const std::string& motion = "");

}  // namespace rollerdyn
