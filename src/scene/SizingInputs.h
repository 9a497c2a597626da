// Optional ratings and targets a drive is sized against (scene section `sizing`). None changes
// the simulation: they only turn the run's torques and forces into pass/fail ratios, a flywheel
// size and bearing lives (src/analysis/DriveSizing.h). A value of 0 means "not given".
#pragma once

namespace rollerdyn {

// An S-N (Woehler) curve of one part for Miner's rule (analysis/Fatigue.h), amplitudes of the
// signal itself (N·m of the coupling torque at the crank axis, N of a rod force):
//   N(S_a) = N_D·(S_D/S_a)^m above the knee; below it Haibach's slope 2m - 1 or a cut-off
// (FatigueInputs::haibach). 0 = not given.                    sizing.fatigue.<signal>.*
struct SnCurve {
  double endurance_amplitude = 0;  // S_D, amplitude at the knee [N·m or N]    .endurance_amplitude
  double knee_cycles = 0;          // N_D, cycles at the knee [-]              .knee_cycles
  double slope = 0;                // m, exponent of the sloped branch [-]     .slope
  double ultimate = 0;             // S_u for Goodman's mean correction; 0: none  .ultimate
  bool given() const { return endurance_amplitude > 0 && knee_cycles > 0 && slope > 0; }
};

struct FatigueInputs {
  SnCurve coupling_torque;         // sizing.fatigue.coupling_torque.*
  SnCurve rod_force;               // sizing.fatigue.rod_force.* (every cart's rod alike)
  bool haibach = true;             // below the knee: Haibach's slope 2m - 1 (true) or no damage
                                   //                                           sizing.fatigue.below_knee
  double required_starts = 0;      // starts the part must take [-]             sizing.fatigue.required_starts
  double required_hours = 0;       // hours of steady running it must take [h]  sizing.fatigue.required_hours
};

// A flexible coupling's catalogue ratings and the selection factors of the manufacturers' method
// after DIN 740-2 (analysis/CouplingSelection.h); torques reduced to the crank axis like
// coupling.stiffness. 0 = not given; the factors default to 1.            sizing.coupling.*
struct CouplingRatings {
  double rated_torque = 0;         // T_KN [N·m]                                .rated_torque
  double max_torque = 0;           // T_Kmax [N·m]                              .max_torque
  double vibratory_torque = 0;     // T_KW, permissible amplitude at 10 Hz [N·m] .vibratory_torque
  double damping_power = 0;        // P_KW, permissible damping power [W]       .damping_power
  double temperature_factor = 1;   // S_t [-]                                   .temperature_factor
  double start_factor = 1;         // S_z [-]                                   .start_factor
  double shock_factor = 1;         // S_A [-]                                   .shock_factor
  bool anyGiven() const {
    return rated_torque > 0 || max_torque > 0 || vibratory_torque > 0 || damping_power > 0;
  }
};

// The reducer's ratings for the gear application factor after ISO 6336-6 (analysis/GearDuty.h);
// torques at the crank axis like coupling.stiffness (the reducer's output shaft drives the crank).
// 0 = not given.                                                          sizing.reducer.*
struct ReducerRatings {
  double application_factor = 0;   // K_A the gears were designed with (ISO 6336-1 Table B.1) [-]
                                   //                                           .application_factor
  double rated_torque = 0;         // T_2N, the reducer's rated output torque (service factor 1) [N·m]
                                   //                                           .rated_torque
  double max_torque = 0;           // T_2max, the reducer's permissible peak output torque [N·m] .max_torque
  double sn_exponent = 6.61;       // p of the gears' torque S-N curve T^p·N = const [-]  .sn_exponent
  bool anyGiven() const { return application_factor > 0 || rated_torque > 0 || max_torque > 0; }
};

// The motor's catalogue limits for starts after IEC 60034-1 duty S4 (analysis/MotorDuty.h).
// 0 = not given.                                                          sizing.motor.*
struct MotorDutyRatings {
  double locked_rotor_time = 0;    // t_E, permissible locked-rotor (stall) time from warm [s]
                                   //                                           .locked_rotor_time
  double no_load_starts = 0;       // Z_0, permissible starts per hour without load and load inertia
                                   // [1/h]                                     .no_load_starts
  bool anyGiven() const { return locked_rotor_time > 0 || no_load_starts > 0; }
};

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
  FatigueInputs fatigue;            // sizing.fatigue.*
  CouplingRatings coupling;         // sizing.coupling.*
  ReducerRatings reducer;           // sizing.reducer.*
  MotorDutyRatings motor;           // sizing.motor.*
};

}  // namespace rollerdyn
