// The start-up answers (StartUp.h) as the `start_up` object of summary.json and as the block
// `rollerdyn simulate` prints. Numbers that do not apply are null in JSON and "n/a" in the text.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "analysis/StartUp.h"

namespace rollerdyn {

// start_up: null when no motor is switched on in the run; else {method, motor_law, motor_model,
// t_on, supply_switches, from_rest, starts, still_starting, verdict, starting_torque_crank, starting_torque_rated_crank,
// largest_torque_crank, load_torque_start, load_torque_mean, steady {mean_speed, reached,
// t_begin, t_end}, run_up_time, start_end, motor_torque {peak, min, steady_peak},
// coupling_torque {peak, steady_peak, ratio}, joints {kind: {peak, steady_peak, ratio, column}},
// stator_current {peak, rms, i2t, steady_rms} | null, rotor_energy_loss, stop {t_off,
// stopping_time, run_out_revolutions, run_out_cart_path} | null, current_limit {limit,
// bypass_speed, max_start_time, outcome, end_time, held_time, binding_from, voltage_min,
// current_peak, peak_over_limit, standstill_voltage, standstill_torque_crank, breakaway_limit,
// rotor_speed_max, stopped_the_start} | null (a soft starter's current limit, StartUpCurrentLimit;
// its speeds at the rotor), notes}. Units: N·m at the crank, rad/s at the crank, s, A, A²·s, J, m
// (docs/startup.md).
nlohmann::json startUpJson(const StartUp& s);

// The console block, from summary.json's start_up; "" when it is null or absent.
std::string startUpText(const nlohmann::json& summary);

// Whether a start needs figures of its own (the report's start-up figures): a motor law other
// than static Kloss, or a supply that switches. A static Kloss start direct on line is shown by
// the run's time figures (crank speed, motor and coupling torque against time) already.
bool startUpHasOwnFigures(const nlohmann::json& start_up);

}  // namespace rollerdyn
