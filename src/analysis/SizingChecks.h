// The checks a drive is signed off with (DriveSizing::checks), each computed once here from the
// figures of one DriveSizing, with the window that decides it and its preconditions. The console,
// summary.json, the report and Python only render them.
//   start            the motor starts the machine from rest: decided by the run when it starts
//                    the machine from rest, else from the torques at standstill under the starting
//                    method's supply against the loads (StartUp::can_start_from_rest), said so;
//   motor_heating    thermal equivalent torque / M_n ≤ 1 (DriveSizing.h says how);
//   motor_breakdown  steady peak |M| / M_kr < 0.95² (IEC 60034-1 zone A);
//   coupling         peak |M| / rated torque ≤ 1 over the whole run and the steady window.
// Preconditions, never a pass or FAIL without them ("not applicable" with the reason and what to
// do instead): the steady window's checks need a steady state reached; a duty with starts per hour
// needs a drive that can start and a start simulated from rest for its heat; a coupling passes only
// from a run that holds the start (whose peak usually decides it) and reached its steady running.
// A drive that does not turn fails the motor checks with the cause (StartUp::stall_cause).
#pragma once

#include <vector>

#include "analysis/DriveSizing.h"

namespace rollerdyn {

// The breakdown check's limit: M_kr at 95 % of the rated voltage, over M_kr [-].
inline constexpr double kBreakdownMargin = 0.95 * 0.95;
// Window names of the checks.
inline constexpr const char* kWindowSteady = "steady window";
inline constexpr const char* kWindowWhole = "whole run";
inline constexpr const char* kWindowDuty = "duty cycle (steady running and starts)";

// `turning`: the crank turns in the window (RunMotion.h).
std::vector<SizingCheck> sizingChecks(const DriveSizing& s, bool turning);

// The fatigue checks (fatigue_starts_<signal>, fatigue_hours_<signal>: required starts or hours
// times Miner's damage, ≤ 1) and the coupling selection after DIN 740-2 (coupling_rated_torque,
// coupling_max_torque, coupling_vibratory_torque, coupling_damping_power), appended to `out`
// where their inputs are given (SignOffChecks.cpp).
void appendSignOffChecks(const DriveSizing& s, bool turning, std::vector<SizingCheck>& out);

// The gear checks after ISO 6336-6 (gear_application_factor, gear_rated_torque, gear_max_torque;
// GearDuty.h) and the motor's starts after IEC 60034-1 (MotorDuty.h), appended to `out` where their
// section is asked for (DutyChecks.cpp).
void appendDutyChecks(const DriveSizing& s, bool turning, std::vector<SizingCheck>& out);

}  // namespace rollerdyn
