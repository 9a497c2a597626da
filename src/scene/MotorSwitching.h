// How the motor is switched on, brought up to speed and switched off (scene sections
// motor.start and motor.stop): the starting method and its settings, the switch-off with an
// optional mechanical brake, and a restart. Read once by the parser; the supply these settings
// produce over time is src/motor/Supply.h.
//
// Without either section the motor is connected direct on line at t = 0 at its rated supply and
// never switched off: the scenes' behaviour before starting methods existed.
#pragma once

#include <limits>

namespace rollerdyn {

enum class StartMethod {  // motor.start.method
  DirectOnLine,           // full rated voltage at t_on
  StarDelta,              // stator in star (phase voltage U_n/√3) at t_on, delta after the changeover
  SoftStarter,            // voltage ramped from U_0 to U_n over t_ramp, optionally current-limited
                          // until the motor is up to speed (or the starter trips)
  FrequencyConverter,     // V/f ramp: frequency from f_0 to f_n over t_ramp, U/U_n = boost + (1 − boost)·f/f_n
};

struct MotorStart {
  StartMethod method = StartMethod::DirectOnLine;  //                           motor.start.method
  double t_on = 0;              // switch-on time [s]                               motor.start.t_on
  double phase = 0;             // point on the wave at switch-on: angle of the supply voltage
                                // space phasor (phase a at its positive peak = 0) [rad]
                                //                                                  motor.start.phase_deg
  // Star-delta: the changeover at a time OR at a rotor speed (exactly one is finite).
  double changeover_time = std::numeric_limits<double>::quiet_NaN();   // [s] motor.start.changeover_time
  double changeover_speed = std::numeric_limits<double>::quiet_NaN();  // rotor speed [rad/s]
                                                                       //  motor.start.changeover_speed
  double changeover_gap = 0;    // dead time of the open transition, stator disconnected [s]
                                //                                                  motor.start.changeover_gap
  // Soft starter and frequency converter.
  double ramp_time = 0;         // t_ramp [s]                                       motor.start.ramp_time
  double initial_voltage = 1;   // soft starter: U_0/U_n at t_on [-]                motor.start.initial_voltage
  double current_limit = 0;     // soft starter: RMS stator phase current it holds the start to,
                                // after the ramp too, until the motor draws no more than that at
                                // the rated voltage (then the bypass closes) [A]; 0 = no limit
                                //                                                  motor.start.current_limit
  double max_start_time = 20;   // soft starter with a current limit: the start still limited this
                                // long after t_on trips the starter (motor disconnected, a failed
                                // start) [s]; 0 = never trips                     motor.start.max_start_time
  double initial_frequency = 0; // frequency converter: f_0 at t_on [Hz]            motor.start.initial_frequency
  double boost = 0;             // frequency converter: U/U_n at zero frequency [-] motor.start.boost
};

struct MotorStop {
  double t_off = std::numeric_limits<double>::infinity();  // switch-off time [s]; inf: never
                                                           //                       motor.stop.t_off
  double brake_torque = 0;      // mechanical brake on the motor shaft, at the rotor [N·m]; 0: none
                                //                                                  motor.stop.brake_torque
  double brake_delay = 0;       // the brake engages this long after t_off [s]      motor.stop.brake_delay
  double t_restart = std::numeric_limits<double>::infinity();  // reconnection direct on line at
                                // the rated supply [s] (brake released); inf: never motor.stop.t_restart
};

}  // namespace rollerdyn
