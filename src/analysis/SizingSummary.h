// The drive-sizing answers (DriveSizing.h) as the `sizing` object of summary.json and as the
// short table `rollerdyn simulate` prints. Numbers that do not apply are null in JSON and "n/a"
// in the table; checks read "pass", "FAIL" or null (nothing to compare with).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "analysis/DriveSizing.h"

namespace rollerdyn {

// sizing: {window {t_begin, t_end, revolutions}, whole_run {t_begin, t_end}, motion,
// checks [{check, what, value, verdict (pass | FAIL | not applicable | null), window, reason}],
// motor {..., whole_run {...}} | null, flywheel {...},
// coupling {...} | null, joints {guide_roller_front, guide_roller_rear, rod_end, crank_pin,
// main_bearing: {what, worst {...}, per_cart [...]} | null}, life_exponent, notes}; each joint row
// with its loads, its motion (rotating | oscillating) and its lives L10_revolutions,
// L10_oscillations, L10_hours with life_basis, or null with life_reason (JointSizing.h); units in
// docs/outputs.md ("Drive sizing").
nlohmann::json sizingJson(const DriveSizing& sizing);

// sizing.fatigue: {below_knee, mean_correction, required_starts, required_hours, signals {coupling_torque,
// rod_force: {what, unit, curve, per_start and steady: {applies, t_begin, t_end, damage, cycles, column,
// dominant_cycles [{range, mean, count, amplitude_equivalent, damage}]} or {applies false, reason},
// damage_per_start, damage_per_hour [1/h], starts_to_failure, hours_to_failure [h]}}} | null
// (SignOffSummary.cpp).
nlohmann::json fatigueJson(const FatigueSizing& f);
// sizing.coupling_selection: ratings, factors, the run's torques and power and the four ratios | null.
nlohmann::json couplingSelectionJson(const CouplingSelection& c);
// Console lines of both, from summary.json's `sizing`; "" when neither was asked for.
std::string signOffText(const nlohmann::json& sizing);

// sizing.gear: {method, torque, exponent, class_width, nominal_torque, nominal_source,
// assumed_application_factor, rated_torque, max_torque, starts_per_hour, start and steady: {applies,
// reason | t_begin, t_end, revolutions, drive and coast: {cycles, equivalent_torque, classes [{torque,
// cycles}]}}, duty {applies, reason | basis, revolutions_per_hour, equivalent_torque_drive,
// equivalent_torque_coast, equivalent_torque, deciding_flank}, application_factor, peak, t_peak,
// application_ratio, rated_ratio, max_ratio} | null (DutySummary.cpp).
nlohmann::json gearDutyJson(const GearDuty& g);
// sizing.motor_duty: the motor's starts after IEC 60034-1 | null (DutySummary.cpp).
nlohmann::json motorDutyJson(const MotorDuty& m);
// Console lines of both, from summary.json's `sizing`; "" when neither was asked for.
std::string dutyText(const nlohmann::json& sizing);

// The runs that check the flywheel proposed for δ* (sizing.flywheel: an estimate, never run by
// simulate), from a summary.json object that holds scene_path, overrides, model and omega_crank:
// {flywheel_inertia (the proposal at the scene's flywheel location as printed [kg·m²]), location,
// started_at_speed, run_at_proposal (a `rollerdyn simulate` command: δ with that flywheel),
// smallest_from_runs (a `rollerdyn optimize` command), note (when the scene is not a file)}, or
// null when nothing is proposed. Goes into sizing.flywheel.check_by_runs.
nlohmann::json flywheelChecks(const nlohmann::json& summary);
// The flywheel lines of sizingText: the swing, the proposal with its basis, the runs that check
// it (FlywheelSummary.cpp, with flywheelChecks).
std::string flywheelText(const nlohmann::json& summary);

// The table for the terminal, from a summary.json object (its `sizing`); "" when it has none.
std::string sizingText(const nlohmann::json& summary);

// Flat sizing metrics for sweeps: name -> path in summary.json (e.g. motor_rms_over_nominal ->
// sizing.motor.rms_over_nominal), in column order.
const std::vector<std::pair<std::string, std::string>>& sizingMetricPaths();

}  // namespace rollerdyn
