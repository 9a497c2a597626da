#include "analysis/CouplingSelection.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "analysis/CrankOrders.h"
#include "analysis/RunResult.h"
#include "analysis/StartUp.h"
#include "scene/Scene.h"

namespace rollerdyn {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kTwoPi = 6.283185307179586;
constexpr int kMaxOrder = 24;

double givenOrNaN(double v) { return v > 0 ? v : kNaN; }

// max |y| over the rows with t_begin <= t <= t_end; NaN when none.
double peakAbs(const Table& ts, const std::string& col, double t_begin, double t_end) {
  double p = kNaN;
  const int it = ts.index("t"), iy = ts.index(col);
  for (const auto& r : ts.rows)
    if (r[it] >= t_begin && r[it] <= t_end && std::isfinite(r[iy])) p = std::isfinite(p) ? std::max(p, std::abs(r[iy])) : std::abs(r[iy]);
  return p;
}

// The steady window's rows as a table of their own.
Table steadyRows(const Table& ts, const SteadyState& w) {
  Table t;
  t.columns = ts.columns;
  const std::size_t e = std::min(w.row_end, ts.rows.size());
  for (std::size_t i = std::min(w.row_begin, e); i < e; ++i) t.rows.push_back(ts.rows[i]);
  return t;
}

// The steady window's swing, excitation order and frequency.
void steadyFigures(CouplingSelection& c, const Table& steady) {
  const std::vector<double> T = steady.column("coupling_torque");
  const auto [lo, hi] = std::minmax_element(T.begin(), T.end());
  c.steady_amplitude = 0.5 * (*hi - *lo);
  if (!steady.has("phi_crank") || steady.rows.size() < 3) return;
  const std::vector<double> t = steady.column("t"), phi = steady.column("phi_crank");
  const double revs = (phi.back() - phi.front()) / kTwoPi;
  const double omega = (phi.back() - phi.front()) / (t.back() - t.front());
  const int R = static_cast<int>(std::floor(revs + 1e-9));
  if (R < 1 || !(omega > 0)) return;
  const CrankOrderAmplitudes a = crankOrderAmplitudes(steady, "coupling_torque", R, kMaxOrder);
  if (!a.valid) return;
  int k_best = 0;
  for (int k = 1; k < static_cast<int>(a.amplitude.size()); ++k)
    if (k_best == 0 || a.amplitude[k] > a.amplitude[k_best]) k_best = k;
  c.excitation_order = k_best;
  c.excitation_frequency = k_best * omega / kTwoPi;
  c.S_f = frequencyFactor(c.excitation_frequency);
}

// P_W = mean of k·Δω² over the steady rows (trapezoidal rule), the damper's loss of the model.
void dampingPower(CouplingSelection& c, const Scene& sc, const Table& steady) {
  if (sc.coupling.type == CouplingType::Rigid) {
    c.damping_basis = "the coupling is rigid in this scene (coupling.type), so the model has no damper to heat";
    return;
  }
  if (!steady.has("twist_rate") || steady.rows.size() < 2) {
    c.damping_basis = "the run has no twist rate Δω over the steady window";
    return;
  }
  const std::vector<double> t = steady.column("t"), w = steady.column("twist_rate");
  const double k = sc.coupling.damping;
  double integral = 0;
  for (std::size_t i = 1; i < t.size(); ++i) integral += 0.5 * k * (w[i] * w[i] + w[i - 1] * w[i - 1]) * (t[i] - t[i - 1]);
  c.damping_power_run = integral / (t.back() - t.front());
  c.damping_basis = "mean of k·Δω² over the steady window, k = coupling.damping";
}

}  // namespace

double frequencyFactor(double f_hz) { return f_hz > 10.0 ? std::sqrt(f_hz / 10.0) : 1.0; }

namespace {

// The ratings and factors given (sizing.coupling.*); every figure of the run NaN until measured.
void takeRatings(CouplingSelection& c, const CouplingRatings& in) {
  c.rated_torque = givenOrNaN(in.rated_torque);
  c.max_torque = givenOrNaN(in.max_torque);
  c.vibratory_torque = givenOrNaN(in.vibratory_torque);
  c.damping_power = givenOrNaN(in.damping_power);
  c.S_t = in.temperature_factor;
  c.S_z = in.start_factor;
  c.S_A = in.shock_factor;
  c.start_peak = c.steady_peak = c.steady_amplitude = c.excitation_frequency = c.damping_power_run = kNaN;
  c.rated_ratio = c.max_ratio = c.vibratory_ratio = c.damping_ratio = kNaN;
}

// The steady window's peak, amplitude, excitation and damping power.
void measureSteadyRunning(CouplingSelection& c, const Scene& sc, const Table& ts, const SteadyState& w) {
  c.steady_reached = w.reached;
  if (!w.reached) {
    c.damping_basis = "no steady window";
    return;
  }
  const Table steady = steadyRows(ts, w);
  if (steady.rows.empty()) return;
  c.steady_peak = peakAbs(ts, "coupling_torque", w.t_begin, w.t_end);
  steadyFigures(c, steady);
  dampingPower(c, sc, steady);
}

// Each rating's ratio after DIN 740-2: the run's torque (or power) times its factors over the rating.
void rateAgainstRatings(CouplingSelection& c) {
  const double T_S = std::isfinite(c.start_peak) ? std::max(c.start_peak, std::isfinite(c.steady_peak) ? c.steady_peak : 0.0)
                                                 : c.steady_peak;
  c.rated_ratio = c.steady_peak * c.S_t / c.rated_torque;
  c.max_ratio = T_S * c.S_A * c.S_z * c.S_t / c.max_torque;
  c.vibratory_ratio = c.steady_amplitude * c.S_t * c.S_f / c.vibratory_torque;
  c.damping_ratio = c.damping_power_run * c.S_t / c.damping_power;
}

}  // namespace

CouplingSelection computeCouplingSelection(const Scene& sc, const RunResult& run, const SteadyState& w,
                                           const StartUp* start_up) {
  CouplingSelection c;
  c.requested = sc.sizing.coupling.anyGiven();
  if (!c.requested) return c;
  takeRatings(c, sc.sizing.coupling);
  const Table& ts = run.timeseries;
  if (!ts.has("t") || !ts.has("coupling_torque")) return c;
  c.start_in_run = start_up && start_up->applicable && start_up->from_rest && start_up->start_end > start_up->t_on;
  if (c.start_in_run) c.start_peak = peakAbs(ts, "coupling_torque", start_up->t_on, start_up->start_end);
  measureSteadyRunning(c, sc, ts, w);
  rateAgainstRatings(c);
  return c;
}

}  // namespace rollerdyn
