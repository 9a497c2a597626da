#include "analysis/MotorSizing.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "analysis/WindowMoments.h"
#include "motor/BreakdownTorque.h"
#include "motor/SharedMotorLaw.h"
#include "physics/ReducerLosses.h"
#include "scene/MotorModels.h"
#include "io/FieldFormat.h"

namespace rollerdyn {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The nominal slip s_n = 1 - ω_n/ω0; NaN where the nominal speed is not known.
double nominalSlip(const Scene& sc) {
  const SizingInputs& z = sc.sizing;
  const MotorCatalogue& cat = sc.induction.catalogue;
  const double omega_nominal = z.motor_omega_nominal > 0                           ? z.motor_omega_nominal
                               : isMachineLaw(sc.induction.model) && cat.omega_nominal > 0 ? cat.omega_nominal
                                                                                               : 0.0;
  return omega_nominal > 0 ? 1.0 - omega_nominal / sc.motor.omega_sync : kNaN;
}

// Generating: the braking torque's first extremum above synchronous speed, the fitted law's
// pull-out torque of the generator branch. The catalogue gives none, and a circuit fitted to the
// motoring points extrapolates it (4.6 kN·m against 517 N·m motoring for 4A200M6U3: its stator
// resistance carries all the losses), so the check keeps the motoring M_kr for braking too
// (conservative) and only reports this figure.
double generatingBreakdownTorque(const MotorLaw& law, double w0) {
  double lowest = 0;
  for (int i = 1; i <= 2000; ++i) {
    const double M = law.steadyTorque(SupplyState{}, w0 * (1.0 + 5e-4 * i));
    if (M > lowest) break;  // past the extremum
    lowest = M;
  }
  return -lowest;
}

// The breakdown torques (motoring, generating) [N·m] the checks read: those of the motor the run
// simulated. A catalogue law (circuit, Park machine) has its own (the extremes of its steady
// curve); the Kloss keys belong to the Kloss laws (the trial's circuit run with
// motor.breakdown_torque = 700 was checked against 700 N·m while its motor broke down at 517).
void addBreakdownTorques(const Scene& sc, MotorSizing& m) {
  m.breakdown_torque = m.breakdown_torque_generating = sc.motor.breakdown_torque;
  if (isMachineLaw(sc.induction.model)) try {
      const std::shared_ptr<const MotorLaw> law = sharedMotorLaw(sc);
      m.breakdown_torque = motorBreakdownTorque(sc, law.get());
      m.breakdown_torque_generating = generatingBreakdownTorque(*law, sc.motor.omega_sync);
    } catch (const std::exception&) {
      // no law for this scene: the Kloss key stands
    }
}

// The catalogue's M_kr beside a Kloss law's motor.breakdown_torque, and the conflict when they
// differ by more than 10 %.
void addCatalogueBreakdownTorque(const Scene& sc, MotorSizing& m) {
  const MotorCatalogue& cat = sc.induction.catalogue;
  m.breakdown_torque_catalogue = kNaN;
  if (isMachineLaw(sc.induction.model) || !cat.given() || !(cat.omega_nominal > 0) || !(cat.breakdown_torque_ratio > 0))
    return;
  const double M_kr_cat = cat.breakdown_torque_ratio * cat.nominalTorque();
  m.breakdown_torque_catalogue = M_kr_cat;  // shown beside the Kloss M_kr, whether they agree or not
  if (std::abs(sc.motor.breakdown_torque / M_kr_cat - 1.0) > 0.1) {
    char buf[300];
    std::snprintf(buf, sizeof buf,
                  "UNRELIABLE: motor.breakdown_torque = %.4g N·m contradicts the motor's catalogue, "
                  "(M_k/M_n)·P_n/ω_n = %.4g N·m; the run and this verdict follow %.4g N·m",
                  sc.motor.breakdown_torque, M_kr_cat, sc.motor.breakdown_torque);
    m.data_conflict = buf;
  }
}

// The motor's ratings the checks read: breakdown torques (motoring, generating), the nominal
// torque and where it comes from, and the catalogue's M_kr where the Kloss key contradicts it.
void addMotorRatings(const Scene& sc, MotorSizing& m) {
  addBreakdownTorques(sc, m);
  m.nominal_torque = nominalMotorTorque(sc, &m.nominal_source);
  addCatalogueBreakdownTorque(sc, m);
}

// Every figure of the run not known until it is computed.
void clearRunFigures(MotorSizing& m) {
  const double nan = kNaN;
  m.torque_shaft_mean = m.torque_shaft_rms = m.torque_shaft_peak = nan;
  m.torque_crank_mean = m.torque_crank_rms = m.torque_crank_peak = nan;
  m.rms_over_nominal = m.peak_over_breakdown = nan;
  m.power_shaft_mean = m.power_shaft_peak = m.power_line_mean = m.power_line_peak = nan;
  m.slip_min = m.slip_max = m.energy_per_revolution = nan;
  MotorWholeRun& r = m.whole_run;
  r.torque_shaft_mean = r.torque_shaft_rms = r.torque_shaft_peak = r.rms_over_nominal = nan;
  r.rotor_losses_mean = r.thermal_over_nominal = r.power_line_mean = r.power_line_peak = nan;
  r.slip_min = r.slip_max = nan;
  r.steady_rotor_losses = r.nominal_rotor_losses = nan;
}

// The motor's rows: at the rotor, through the reducer's law.
struct MotorRows {
  std::vector<double> t, M_crank;  // time [s], motor torque at the crank axis [N·m]
  std::vector<double> M, P, P_line, s, losses;  // rotor torque, shaft power, line power, slip, rotor copper losses
};

MotorRows motorRows(const Scene& sc, const Table& ts, double s_n) {
  const double u = sc.reducer.ratio, w0 = sc.motor.omega_sync;
  MotorRows r{ts.column("t"), ts.column("motor_torque"), {}, {}, {}, {}, {}};
  const std::vector<double> w_crank_axis = ts.column("omega_motor");
  // The rotor torque through the reducer's law (the loss column is there under power_flow).
  const ReducerLaw reducer = reducerLaw(sc, motorBreakdownTorque(sc));
  const std::vector<double> L_crank =
      ts.has("reducer_loss_torque") ? ts.column("reducer_loss_torque") : std::vector<double>{};
  const std::size_t n = r.t.size();
  r.M.resize(n), r.P.resize(n), r.P_line.resize(n), r.s.resize(n), r.losses.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    r.M[i] = reducerShaftTorque(reducer, r.M_crank[i], L_crank.empty() ? 0.0 : L_crank[i]);  // rotor torque
    const double w_r = u * w_crank_axis[i];  // rotor speed
    r.P[i] = r.M[i] * w_r;
    r.s[i] = 1.0 - w_r / w0;
    r.P_line[i] = linePower(r.M[i], w0, s_n, sc.sizing.motor_efficiency);
    r.losses[i] = r.s[i] * r.M[i] * w0;  // rotor copper losses s·P_ag
  }
  return r;
}

// The slip's lowest and highest value over rows [b, e); left as they are with fewer than two rows.
void takeSlipRange(const std::vector<double>& s, std::size_t b, std::size_t e, double& slip_min, double& slip_max) {
  if (e < b + 2) return;
  const auto [lo, hi] = std::minmax_element(s.begin() + b, s.begin() + e);
  slip_min = *lo;
  slip_max = *hi;
}

// Motoring and braking peaks against the breakdown torque of each side: the second trial's
// 639 N·m braking peak was read against the motoring M_kr (517 N·m) of a machine whose braking
// breakdown torque is larger.
void addBreakdownPeaks(MotorSizing& m, const std::vector<double>& M, std::size_t b, std::size_t e) {
  m.torque_motoring_peak = m.torque_generating_peak = 0;
  for (std::size_t i = b; i < e && i < M.size(); ++i)
    if (std::isfinite(M[i])) {
      m.torque_motoring_peak = std::max(m.torque_motoring_peak, M[i]);
      m.torque_generating_peak = std::max(m.torque_generating_peak, -M[i]);
    }
  m.peak_over_breakdown = e > b ? std::max(m.torque_motoring_peak, m.torque_generating_peak) / m.breakdown_torque : kNaN;
}

// The torques, powers and slip over the steady window, rows [b, e).
void addSteadyWindowFigures(MotorSizing& m, const MotorRows& rows, std::size_t b, std::size_t e, double revolutions,
                            bool turning) {
  const std::vector<double>& t = rows.t;
  const std::vector<double>& M = rows.M;
  const Moments ms = moments(t, M, b, e), mc = moments(t, rows.M_crank, b, e), mp = moments(t, rows.P, b, e),
                ml = moments(t, rows.P_line, b, e);
  m.torque_shaft_mean = ms.mean;
  m.torque_shaft_rms = ms.rms;
  m.torque_shaft_peak = ms.peak;
  m.torque_crank_mean = mc.mean;
  m.torque_crank_rms = mc.rms;
  m.torque_crank_peak = mc.peak;
  m.rms_over_nominal = ms.rms / m.nominal_torque;
  addBreakdownPeaks(m, M, b, e);
  m.power_shaft_mean = mp.mean;
  m.power_shaft_peak = mp.max;
  m.power_line_mean = ml.mean;
  m.power_line_peak = ml.max;
  takeSlipRange(rows.s, b, e, m.slip_min, m.slip_max);
  if (turning && revolutions >= 0.5)
    m.energy_per_revolution = mp.mean * (t[e - 1] - t[b]) / revolutions;
}

// The torques, line power, rotor losses and slip over the whole run, rows [0, run_end).
void addWholeRunFigures(MotorWholeRun& r, const MotorRows& rows, std::size_t run_end, double nominal_torque) {
  const Moments rs = moments(rows.t, rows.M, 0, run_end), rl = moments(rows.t, rows.P_line, 0, run_end),
                rq = moments(rows.t, rows.losses, 0, run_end);
  r.torque_shaft_mean = rs.mean;
  r.torque_shaft_rms = rs.rms;
  r.torque_shaft_peak = rs.peak;
  r.rms_over_nominal = rs.rms / nominal_torque;
  r.rotor_losses_mean = rq.mean;
  r.power_line_mean = rl.mean;
  r.power_line_peak = rl.max;
  takeSlipRange(rows.s, 0, run_end, r.slip_min, r.slip_max);
}

// What one start puts into the rotor and how many starts per hour the rotor's heat balance
// allows, in words; empty where the start's heat is not known.
std::string startsSentence(const MotorWholeRun& r, double steady_losses, double nominal_losses, bool start_known) {
  char starts[400] = "";
  if (std::isfinite(r.starts_per_hour) && steady_losses >= nominal_losses)
    // "allows about 0 starts per hour" read as if the starts were the trouble (the three-cart
    // trial): steady running alone already overheats the rotor, and says so with its own figure.
    std::snprintf(starts, sizeof starts,
                  "one start puts %.3g kJ into the rotor (%.3g kJ more than %.3g s of steady running), but steady "
                  "running alone already heats the rotor beyond its rating (√(steady rotor losses / (s_n·M_n·ω0)) = "
                  "%.3g > 1), so the rotor's heat balance allows no start at this load",
                  r.start_heat * 1e-3, r.start_heat_above_steady * 1e-3, r.start_duration,
                  std::sqrt(steady_losses / nominal_losses));
  else if (std::isfinite(r.starts_per_hour))
    std::snprintf(starts, sizeof starts,
                  "one start puts %.3g kJ into the rotor (%.3g kJ more than %.3g s of steady running), so the rotor's "
                  "heat balance allows about %.3g starts per hour at this load",
                  r.start_heat * 1e-3, r.start_heat_above_steady * 1e-3, r.start_duration, r.starts_per_hour);
  else if (start_known && !(r.start_heat_above_steady > 0))
    // A gentle start (a frequency converter's ramp) puts no more heat into the rotor than the same
    // time of steady running: the starts do not limit the duty (was "the start's heat is not known").
    std::snprintf(starts, sizeof starts,
                  "one start puts %.3g kJ into the rotor, no more than %.3g s of steady running, so starts add "
                  "nothing to the rotor's heat at this load",
                  r.start_heat * 1e-3, r.start_duration);
  return starts;
}

// The duty S4: the steady losses plus that many starts' heat per hour.
void judgeDutyHeating(MotorWholeRun& r, double starts_per_hour, double steady_losses, double nominal_losses,
                      const std::string& starts) {
  const double duty_losses = std::max(0.0, steady_losses) + starts_per_hour * r.start_heat_above_steady / 3600.0;
  r.thermal_over_nominal = std::sqrt(duty_losses / nominal_losses);
  char duty[200];
  std::snprintf(duty, sizeof duty, "%.4g starts per hour (sizing.starts_per_hour)", starts_per_hour);
  r.thermal_basis = "√((steady rotor losses s·M·ω0 + starts per hour × what one start adds) / (s_n·M_n·ω0)) for " +
                    std::string(duty) + "; " + starts;
}

// No duty given (or no start to count): continuous running, the steady window's own losses (a
// locked rotor's s = 1 shows here, where the RMS of its torque would not). `starts`: what the
// starts add, or why that is not known.
void judgeContinuousHeating(MotorWholeRun& r, double starts_per_hour, double steady_losses, double nominal_losses,
                            const std::string& starts) {
  r.continuous_running = true;
  r.thermal_over_nominal = std::sqrt(std::max(0.0, steady_losses) / nominal_losses);
  const std::string eq = significant(r.thermal_over_nominal, 3);
  r.thermal_basis = std::string(starts_per_hour > 0 ? "continuous running (sizing.starts_per_hour given, but "
                                                      "there is no start to count)"
                                                    : "continuous running (sizing.starts_per_hour not given)") +
                    ": √(steady-window rotor losses s·M·ω0 / (s_n·M_n·ω0)) = " + eq + "; " + starts;
}

// The rotor's thermal equivalent against its nominal losses, and the sentence that says how it
// was found. The duty decides how often the start's heat comes: the run's length says nothing
// about it (a 10 s run is not a start every 10 s). With sizing.starts_per_hour the thermal
// equivalent is the steady losses plus that many starts' heat per hour; without it the drive runs
// continuously (S1) and the heating check reads the steady window, with the starts per hour the
// motor allows.
void judgeRotorHeating(const Scene& sc, const MotorSizing& m, double s_n, double steady_losses, double nominal_losses,
                       bool start_known, const StartUp* start_up, MotorWholeRun& r) {
  const SizingInputs& z = sc.sizing;
  const std::string starts = startsSentence(r, steady_losses, nominal_losses, start_known);
  const std::string unknown_start =
      start_up && start_up->applicable && !start_up->from_rest
          ? "the run holds no start from rest (it begins turning, initial.crank_speed), so the start's heat is not known"
          : "the start's heat is not known";
  const bool losses_known = s_n > 0 && m.nominal_torque > 0 && std::isfinite(steady_losses);
  if (losses_known && start_known && z.starts_per_hour > 0) {
    judgeDutyHeating(r, z.starts_per_hour, steady_losses, nominal_losses, starts);
  } else if (losses_known) {
    judgeContinuousHeating(r, z.starts_per_hour, steady_losses, nominal_losses, !starts.empty() ? starts : unknown_start);
  } else {
    r.thermal_over_nominal = r.rms_over_nominal;
    // Say which input is missing: the trial read "motor.omega_nominal not given" for a run whose
    // steady window merely held too few output rows.
    const std::string why = !(s_n > 0) ? "s_n not known: motor.omega_nominal not given"
                            : !(m.nominal_torque > 0) ? "the nominal torque M_n is not known"
                                                      : "the steady window holds too few output rows for its losses";
    r.thermal_basis = "RMS torque over the whole run / M_n (" + why + "; start-up heating at high slip is underestimated)";
  }
}

// The rotor's heating: its losses in the steady window against the nominal s_n·M_n·ω0, and the
// start's heat. The start's rotor heat is the start-up answers' rotor energy loss (StartUp.h): one
// computation for both. A start takes the place of that much time of steady running, so what it
// adds to the heat balance is its heat less the steady losses over its duration.
void addRotorHeating(const Scene& sc, MotorSizing& m, const MotorRows& rows, std::size_t b, std::size_t e, double s_n,
                     const StartUp* start_up) {
  MotorWholeRun& r = m.whole_run;
  r.start_heat = r.start_duration = r.start_heat_above_steady = r.starts_per_hour = kNaN;
  r.continuous_running = false;
  const Moments sq = moments(rows.t, rows.losses, b, e);
  const double nominal_losses = s_n * m.nominal_torque * sc.motor.omega_sync;  // s_n·M_n·ω0
  r.steady_rotor_losses = sq.mean;
  r.nominal_rotor_losses = nominal_losses > 0 ? nominal_losses : kNaN;
  const bool start_known = start_up && start_up->applicable && start_up->from_rest &&
                           std::isfinite(start_up->rotor_energy_loss) && std::isfinite(sq.mean);
  if (start_known) {
    r.start_heat = start_up->rotor_energy_loss;
    r.start_duration = start_up->start_end - start_up->t_on;
    r.start_heat_above_steady = std::max(0.0, r.start_heat - std::max(0.0, sq.mean) * r.start_duration);
    if (s_n > 0 && m.nominal_torque > 0 && r.start_heat_above_steady > 0)
      r.starts_per_hour = std::max(0.0, 3600.0 * (nominal_losses - sq.mean) / r.start_heat_above_steady);
  }
  r.duty_starts_per_hour = sc.sizing.starts_per_hour;
  judgeRotorHeating(sc, m, s_n, sq.mean, nominal_losses, start_known, start_up, r);
}

}  // namespace

MotorSizing sizeMotor(const Scene& sc, const Table& ts, std::size_t b, std::size_t e, std::size_t run_end,
                      double revolutions, bool turning, const StartUp* start_up) {
  MotorSizing m;
  const double s_n = nominalSlip(sc);
  addMotorRatings(sc, m);
  m.line_power_basis =
      sc.sizing.motor_efficiency > 0 && s_n > 0
          ? "air-gap power M·ω0 (shaft power plus rotor copper losses) × (1 - s_n)/η_m, stator and iron "
            "losses as at the nominal point (η_m = sizing.motor_efficiency; ÷ when generating)"
          : "air-gap power M·ω0: shaft power plus rotor copper losses s·M·ω0; stator and iron losses "
            "neglected (give sizing.motor_efficiency and motor.omega_nominal to include them)";
  clearRunFigures(m);
  if (!sc.motor.enabled || !ts.has("t") || !ts.has("motor_torque") || !ts.has("omega_motor"))
    return m;
  m.available = true;
  const MotorRows rows = motorRows(sc, ts, s_n);
  addSteadyWindowFigures(m, rows, b, e, revolutions, turning);
  addWholeRunFigures(m.whole_run, rows, run_end, m.nominal_torque);
  addRotorHeating(sc, m, rows, b, e, s_n, start_up);
  return m;
}

}  // namespace rollerdyn
