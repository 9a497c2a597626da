#include "analysis/MotorDuty.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "analysis/DriveSizing.h"
#include "analysis/StartUp.h"
#include "scene/Scene.h"
#include "io/FieldFormat.h"

namespace rollerdyn {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double givenOrNaN(double v) { return v > 0 ? v : kNaN; }

std::string g3(double v) { return significant(v, 3); }

// The duty type with its ratings, the inertias at the motor shaft, and the designation that names them.
void describeDuty(MotorDuty& m, const Scene& sc, const DriveSizing& s) {
  const MotorDutyRatings& in = sc.sizing.motor;
  m.starts_per_hour = sc.sizing.starts_per_hour;
  m.duty_type = m.starts_per_hour > 0 ? "S4" : "S1";
  m.locked_rotor_time = givenOrNaN(in.locked_rotor_time);
  m.no_load_starts = givenOrNaN(in.no_load_starts);
  const double w0 = sc.motor.omega_sync, u = sc.reducer.ratio;
  m.rotor_inertia = sc.motor.rotor_inertia;
  m.no_load_start_heat = 0.5 * m.rotor_inertia * w0 * w0;
  // The drive's inertia at the motor shaft: the time mean of 2T/ω_crank² (crank axis) over u².
  m.load_inertia = std::isfinite(s.flywheel.inertia_effective) && u > 0
                       ? std::max(0.0, s.flywheel.inertia_effective / (u * u) - m.rotor_inertia)
                       : kNaN;
  m.designation = m.duty_type == "S4"
                      ? "S4 - " + g3(m.starts_per_hour) + " starts/h - J_M = " + g3(m.rotor_inertia) +
                            " kg·m² - J_ext = " + (std::isfinite(m.load_inertia) ? g3(m.load_inertia) : std::string("n/a")) +
                            " kg·m² at the motor shaft (energized between starts, no electric braking)"
                      : "S1, continuous running (sizing.starts_per_hour not given); one start from cold or warm";
}

// Why the run tells no start's rotor heat.
std::string startUnknownReason(const StartUp* start_up) {
  const bool applicable = start_up && start_up->applicable;
  return applicable && !start_up->from_rest
             ? "the run holds no start from rest (it begins turning, initial.crank_speed): run it from rest "
               "(initial.crank_speed: 0)"
         : applicable && !start_up->starts
             ? "the drive does not run up in this run" +
                   (start_up->stall_cause.empty() ? std::string() : " (" + start_up->stall_cause + ")") +
                   ", so a start's rotor heat is not known: see the start check"
             : "the run holds no start of the motor, so the rotor heat of a start is not known";
}

// The start's rotor heat against the locked rotor's, and the starts per hour the motor permits.
void judgeStartHeat(MotorDuty& m, const Scene& sc, const DriveSizing& s, const StartUp& start_up) {
  const double w0 = sc.motor.omega_sync, u = sc.reducer.ratio, eta = sc.reducer.efficiency;
  m.start_time = start_up.start_end - start_up.t_on;
  m.start_heat = start_up.rotor_energy_loss;
  // M_s under the rated supply at the rotor: the start-up answers' figure at the crank over u·η.
  if (u > 0 && eta > 0) m.locked_rotor_torque = start_up.starting_torque_rated_crank / (u * eta);
  m.locked_rotor_losses = m.locked_rotor_torque * w0 > 0 ? m.locked_rotor_torque * w0 : kNaN;
  m.equivalent_locked_time = m.start_heat / m.locked_rotor_losses;
  m.locked_time_ratio = m.equivalent_locked_time / m.locked_rotor_time;
  const MotorWholeRun& r = s.motor.whole_run;
  m.steady_loss_share = r.steady_rotor_losses / r.nominal_rotor_losses;
  m.permissible_starts = m.no_load_starts * m.no_load_start_heat / m.start_heat * std::max(0.0, 1.0 - m.steady_loss_share);
  if (m.starts_per_hour > 0) {
    m.starting_time_share = m.starts_per_hour * m.start_time / 3600.0;
    m.starts_ratio = m.starts_per_hour / m.permissible_starts;
  }
}

}  // namespace

MotorDuty computeMotorDuty(const Scene& sc, const DriveSizing& s, const StartUp* start_up) {
  MotorDuty m;
  m.requested = sc.sizing.motor.anyGiven();
  if (!m.requested) return m;
  m.start_time = m.start_heat = m.locked_rotor_torque = m.locked_rotor_losses = m.equivalent_locked_time = kNaN;
  m.steady_loss_share = m.permissible_starts = m.starting_time_share = m.locked_time_ratio = m.starts_ratio = kNaN;
  describeDuty(m, sc, s);
  m.start_known = start_up && start_up->applicable && start_up->from_rest && std::isfinite(start_up->rotor_energy_loss) &&
                  start_up->start_end > start_up->t_on;
  if (m.start_known)
    judgeStartHeat(m, sc, s, *start_up);
  else
    m.start_unknown = startUnknownReason(start_up);
  return m;
}

}  // namespace rollerdyn
