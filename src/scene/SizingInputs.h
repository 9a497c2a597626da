// Optional ratings and targets a drive is sized against (scene section `sizing`). None changes
// the simulation: they only turn the run's torques and forces into pass/fail ratios, a flywheel
// size and bearing lives (src/analysis/DriveSizing.h). A value of 0 means "not given".
#pragma once

namespace rollerdyn {

struct SizingInputs {
  double motor_nominal_torque = 0;  // M_n at the rotor [N·m]                   sizing.motor_nominal_torque
  double motor_nominal_power = 0;   // P_n at the rotor shaft [W]; M_n = P_n/ω_n
                                    //                                           sizing.motor_nominal_power
  double motor_efficiency = 0;      // η_m, shaft power / power drawn from the line [-]
                                    //                                           sizing.motor_efficiency
  double motor_omega_nominal = 0;   // ω_n [rad/s], copied from motor.omega_nominal when given
  double motor_overload_ratio = 0;  // λ = M_kr/M_n [-], copied from motor.overload_ratio when given
  double starts_per_hour = 0;       // duty: motor starts per hour [1/h]; 0 = continuous running (S1)
                                    //                                           sizing.starts_per_hour
  double target_delta = 0;          // δ the flywheel should bring the run to [-]  sizing.target_delta
  double coupling_rated_torque = 0; // rated torque of the coupling, reduced to the crank axis [N·m]
                                    //                                           sizing.coupling_rated_torque
  // Basic dynamic load ratings C of the bearings [N]                      sizing.bearing_rating.*
  double rating_guide_roller = 0;   // one guide roller                         .guide_roller
  double rating_rod_end = 0;        // rod small end at the cart hinge B        .rod_end
  double rating_crank_pin = 0;      // rod big end on the crank pin             .crank_pin
  double rating_main_bearing = 0;   // crankshaft main bearing (one, carrying the whole bearing force)
                                    //                                          .main_bearing
};

}  // namespace rollerdyn
