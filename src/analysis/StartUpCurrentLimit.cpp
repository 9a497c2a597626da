#include "analysis/StartUpCurrentLimit.h"
#include "io/FieldFormat.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace rollerdyn {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Linear interpolation of column y at time `when` (rows sorted by t); NaN outside the rows.
double at(const std::vector<double>& t, const std::vector<double>& y, double when) {
  if (t.empty() || when < t.front() || when > t.back()) return kNaN;
  const std::size_t i = std::size_t(std::lower_bound(t.begin(), t.end(), when) - t.begin());
  if (i == 0 || t[i] == when) return y[i];
  const double a = (when - t[i - 1]) / (t[i] - t[i - 1]);
  return y[i - 1] + a * (y[i] - y[i - 1]);
}

// When the bypass closed: at the end of the ramp if the rotor was at ω_lim or faster then,
// else where the rotor speed first rises through ω_lim after it (interpolated between rows);
// NaN when neither happens before `until`.
double bypassTime(const std::vector<double>& t, const std::vector<double>& w_rotor, double ramp_end, double w_lim,
                  double until) {
  if (ramp_end > until || ramp_end > t.back()) return kNaN;
  const double w_end = at(t, w_rotor, ramp_end);
  if (w_end >= w_lim) return ramp_end;
  double t_prev = ramp_end, w_prev = w_end;
  for (std::size_t i = 0; i < t.size() && t[i] <= until; ++i) {
    if (t[i] <= ramp_end) continue;
    if (w_rotor[i] >= w_lim) {
      const double a = w_rotor[i] > w_prev ? (w_lim - w_prev) / (w_rotor[i] - w_prev) : 1.0;
      return t_prev + std::clamp(a, 0.0, 1.0) * (t[i] - t_prev);
    }
    t_prev = t[i], w_prev = w_rotor[i];
  }
  return kNaN;
}

// Why the limit kept the drive from starting, one sentence after "the drive does not start...: ".
std::string whyNotUpToSpeed(const StartUpCurrentLimit& c, double load_start) {
  if (std::isfinite(load_start) && c.standstill_torque_crank <= load_start)
    return "its limit I_lim = " + printfNumber("%g", c.limit) + " A allows the motor at standstill only U/U_n = " +
           printfNumber("%.3g", c.standstill_voltage) + ", where it gives " + printfNumber("%.4g", c.standstill_torque_crank) +
           " N·m at the crank against a load of " + printfNumber("%.4g", load_start) +
           " N·m at the start angle, so the motor cannot break away" +
           (std::isfinite(c.breakaway_limit) ? "; a limit above " + printfNumber("%.4g", c.breakaway_limit) +
                                                   " A breaks it away there (the torque grows with the square of the "
                                                   "voltage), or choose another starting method"
                                             : std::string());
  return "under its limit I_lim = " + printfNumber("%g", c.limit) + " A the motor broke away but reached at most " +
         printfNumber("%.4g", c.rotor_speed_max) + " rad/s at the rotor, short of the " + printfNumber("%.4g", c.bypass_speed) +
         " rad/s from which it draws no more than the limit at the rated voltage; raise the limit (more torque) or "
         "motor.start.max_start_time (more time)";
}

// The motor at standstill under the limit: the voltage the limit allows it, the torque that gives
// at the crank, and the limit that would break it away against the load at the start angle.
void standstillUnderLimit(const MotorLaw& law, double u, double eta, double load_torque_start,
                          StartUpCurrentLimit& c) {
  const SupplyState rated;
  const double I_standstill = law.steadyCurrent(rated, 0.0), M_standstill = law.steadyTorque(rated, 0.0) * u * eta;
  c.standstill_voltage = std::min(1.0, c.limit / I_standstill);
  SupplyState limited;
  limited.voltage = c.standstill_voltage;
  c.standstill_torque_crank = law.steadyTorque(limited, 0.0) * u * eta;
  c.breakaway_limit = std::isfinite(load_torque_start) && load_torque_start > 0 && M_standstill > 0
                          ? I_standstill * std::sqrt(load_torque_start / M_standstill)
                          : kNaN;
}

// How the limited start ended, and when: the starter tripped, its bypass closed, the motor was
// switched off, or the run ended with the limit still holding.
void limitOutcome(const RunResult& run, const Supply& supply, const MotorStart& ms, double t_off,
                  const std::vector<double>& t, const std::vector<double>& w_rotor, StartUpCurrentLimit& c) {
  c.end_time = kNaN;
  if (run.stats.status.rfind(Supply::kTripStatus, 0) == 0) {
    c.outcome = "tripped";
    c.end_time = supply.tripTime();
  } else {
    const double bypass = bypassTime(t, w_rotor, ms.t_on + ms.ramp_time, c.bypass_speed, std::min(t_off, t.back()));
    if (std::isfinite(bypass)) {
      c.outcome = "bypass";
      c.end_time = bypass;
    } else if (t_off <= t.back()) {
      c.outcome = "switched_off";
      c.end_time = t_off;
    } else {
      c.outcome = "limited_at_end";
    }
  }
}

// Over the switch-on ... end: the rows while connected.
void limitedRows(const Table& ts, const MotorStart& ms, const std::vector<double>& t,
                 const std::vector<double>& w_rotor, double end, StartUpCurrentLimit& c) {
  const std::vector<double> U = ts.has("supply_voltage_ratio") ? ts.column("supply_voltage_ratio") : std::vector<double>{};
  const std::vector<double> I = ts.has("stator_current") ? ts.column("stator_current") : std::vector<double>{};
  c.binding_from = c.voltage_min = c.current_peak = c.rotor_speed_max = kNaN;
  double v_min = std::numeric_limits<double>::infinity(), i_max = -1, w_max = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < t.size() && t[i] <= end + 1e-12; ++i) {
    if (t[i] < ms.t_on - 1e-12) continue;
    w_max = std::max(w_max, w_rotor[i]);
    if (U.empty() || !(U[i] > 0)) continue;
    if (!I.empty()) i_max = std::max(i_max, I[i]);
    // Where the limit holds U below the ramp's voltage.
    const double ramp = std::min(1.0, ms.initial_voltage + (1.0 - ms.initial_voltage) * (t[i] - ms.t_on) / ms.ramp_time);
    if (!(U[i] < ramp * (1.0 - 1e-9))) continue;
    if (std::isnan(c.binding_from)) c.binding_from = t[i];
    v_min = std::min(v_min, U[i]);
  }
  if (std::isfinite(v_min)) c.voltage_min = v_min;
  if (i_max >= 0) c.current_peak = i_max;
  if (std::isfinite(w_max)) c.rotor_speed_max = w_max;
}

// The verdict, where the limit decided the start.
void limitVerdict(const MotorStart& ms, const Supply& supply, StartUpCurrentLimit& c, StartUp& r) {
  const std::string trip_ahead =
      std::isfinite(supply.tripTime())
          ? "the starter trips at t = " + printfNumber("%.4g", supply.tripTime()) + " s (motor.start.max_start_time = " +
                printfNumber("%g", ms.max_start_time) + " s) unless the rotor reaches " + printfNumber("%.4g", c.bypass_speed) + " rad/s"
          : "it never trips (motor.start.max_start_time = 0)";
  if (c.outcome == "tripped") {
    c.stopped_the_start = true;
    r.starts = r.still_starting = false;
    // The one cause the status and the sizing print too (StartUp::stall_cause).
    r.stall_cause = "the soft starter tripped at t = " + printfNumber("%.4g", c.end_time) +
                    " s, its start still current-limited motor.start.max_start_time = " + printfNumber("%g", ms.max_start_time) +
                    " s after the switch-on: " + whyNotUpToSpeed(c, r.load_torque_start);
    r.verdict = "the drive does not start: " + r.stall_cause;
  } else if (c.outcome == "limited_at_end" && !r.starts && !r.still_starting) {
    c.stopped_the_start = true;
    r.stall_cause = "the soft starter still limits the current when the run ends, and " +
                    whyNotUpToSpeed(c, r.load_torque_start) + "; " + trip_ahead;
    r.verdict = "the drive does not start within the run: " + r.stall_cause;
  } else if (c.outcome == "limited_at_end") {
    r.verdict += "; the soft starter still limits the current when the run ends (U/U_n down to " +
                 printfNumber("%.3g", c.voltage_min) + "): its bypass closes when the rotor reaches " +
                 printfNumber("%.4g", c.bypass_speed) + " rad/s, and " + trip_ahead;
  }
}

}  // namespace

void addCurrentLimit(const Scene& sc, const RunResult& run, const MotorLaw& law, const Supply& supply, StartUp& r) {
  const MotorStart& ms = sc.motor_start;
  const Table& ts = run.timeseries;
  if (!r.applicable || !r.from_rest || ms.method != StartMethod::SoftStarter || !(ms.current_limit > 0) ||
      !ts.has("t") || ts.rows.size() < 2)
    return;
  StartUpCurrentLimit& c = r.current_limit;
  c.applies = true;
  c.limit = ms.current_limit;
  c.bypass_speed = supply.limitSpeed();
  c.max_start_time = ms.max_start_time > 0 ? ms.max_start_time : kNaN;
  const double u = sc.reducer.ratio, eta = sc.reducer.efficiency;
  standstillUnderLimit(law, u, eta, r.load_torque_start, c);

  const std::vector<double> t = ts.column("t");
  std::vector<double> w_rotor = ts.has("omega_motor") ? ts.column("omega_motor") : ts.column("omega_crank");
  for (double& w : w_rotor) w *= u;  // the tables' speeds are at the crank axis
  limitOutcome(run, supply, ms, sc.motor_stop.t_off, t, w_rotor, c);
  const double end = std::isfinite(c.end_time) ? c.end_time : t.back();
  c.held_time = end - ms.t_on;

  limitedRows(ts, ms, t, w_rotor, end, c);
  limitVerdict(ms, supply, c, r);
}

}  // namespace rollerdyn
