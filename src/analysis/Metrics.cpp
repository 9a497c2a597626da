#include "analysis/Metrics.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>

namespace rollerdyn {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

using ConstVecMap = Eigen::Map<const Eigen::VectorXd>;

ConstVecMap segment(const std::vector<double>& v, std::size_t begin, std::size_t end) {
  return ConstVecMap(v.data() + begin, static_cast<Eigen::Index>(end - begin));
}

// Linear interpolation of y(t) at time tq within rows [0, n); t ascending.
double interpolateAt(const std::vector<double>& t, const std::vector<double>& y, std::size_t n,
                     double tq) {
  if (n == 0) return kNaN;
  if (tq <= t[0]) return y[0];
  if (tq >= t[n - 1]) return y[n - 1];
  std::size_t hi = 1;
  while (hi < n - 1 && t[hi] < tq) ++hi;
  const double dt = t[hi] - t[hi - 1];
  const double frac = dt > 0 ? (tq - t[hi - 1]) / dt : 1.0;
  return y[hi - 1] + frac * (y[hi] - y[hi - 1]);
}

// dω/dt by central differences (one-sided at the ends of [0, n)), for runs without eps_crank.
std::vector<double> differentiate(const std::vector<double>& t, const std::vector<double>& y,
                                  std::size_t n) {
  std::vector<double> d(y.size(), kNaN);
  if (n < 2) return d;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t lo = i == 0 ? 0 : i - 1;
    const std::size_t hi = i + 1 == n ? n - 1 : i + 1;
    d[i] = (y[hi] - y[lo]) / (t[hi] - t[lo]);
  }
  return d;
}

}  // namespace

MotionCoefficients motionCoefficients(double omega_min, double omega_max, double omega_mean,
                                      double eps_abs_max) {
  MotionCoefficients c;
  const double range = omega_max - omega_min;
  const double mean_sq = omega_mean * omega_mean;
  c.delta = range / omega_mean;                          // Loveikin and Pochka (2007), eq. (12)
  c.H = eps_abs_max / mean_sq;                           // Loveikin and Pochka (2007), eq. (13)
  c.k_p = range * range / mean_sq + eps_abs_max / mean_sq;  // Loveikin and Pochka (2007), eq. (14)
  return c;
}

ColumnStats columnStats(const std::vector<double>& t, const std::vector<double>& y,
                        std::size_t begin, std::size_t end) {
  ColumnStats s{kNaN, kNaN, kNaN, kNaN};
  if (end <= begin || end > y.size() || end > t.size()) return s;
  const auto ys = segment(y, begin, end);
  const auto ts = segment(t, begin, end);
  if (!ys.allFinite() || !ts.allFinite()) return s;
  s.min = ys.minCoeff();
  s.max = ys.maxCoeff();
  s.abs_max = ys.cwiseAbs().maxCoeff();
  const Eigen::Index m = ys.size();
  const double span = m > 1 ? ts(m - 1) - ts(0) : 0.0;
  if (span > 0) {
    // Trapezoidal rule: ∫y dt / Δt.
    const Eigen::VectorXd dt = ts.tail(m - 1) - ts.head(m - 1);
    s.mean = 0.5 * (ys.head(m - 1) + ys.tail(m - 1)).dot(dt) / span;
  } else {
    s.mean = ys.mean();
  }
  return s;
}

namespace {

// The timeseries rows a window's metrics read: the times, the finite rows [0, n), the window [b, e).
struct WindowRows {
  const std::vector<double>& t;
  std::size_t n, b, e;
};

// Extremes of the crank speed (rows and located extrema), its midrange, and max |ε|.
void addCrankSpeedExtremes(WindowMetrics& m, const RunResult& run, const SteadyState& w, const WindowRows& r) {
  const Table& ts = run.timeseries;
  const std::vector<double> omega = ts.column("omega_crank");
  const ColumnStats os = columnStats(r.t, omega, r.b, r.e);
  m.omega_min = os.min;
  m.omega_max = os.max;
  // The extrema the integrator located between the rows (CrankSpeedExtrema.h): the rows alone
  // miss a sharp extreme by up to |ω̈|·h²/8.
  if (std::isfinite(os.min) && r.e > r.b)
    for (const CrankSpeedExtremum& x : run.crank_speed_extrema)
      if (x.t >= w.t_begin && x.t <= w.t_end) {
        m.omega_min = std::min(m.omega_min, x.omega);
        m.omega_max = std::max(m.omega_max, x.omega);
      }
  m.omega_midrange = 0.5 * (m.omega_min + m.omega_max);

  std::vector<double> eps;
  if (ts.has("eps_crank")) {
    eps = ts.column("eps_crank");
  } else {
    eps = differentiate(r.t, omega, r.n);
    m.eps_from_difference = true;
  }
  m.eps_abs_max = columnStats(r.t, eps, r.b, r.e).abs_max;
}

// Coupling swings, Loveikin, Pochka, Romasevych (2018) Table 1.
void addCouplingSwings(WindowMetrics& m, const Table& ts, bool have_time, const WindowRows& r) {
  auto swingOf = [&](const char* name) {
    if (!have_time || !ts.has(name)) {
      m.missing_columns.push_back(name);
      return 0.0;
    }
    return columnStats(r.t, ts.column(name), r.b, r.e).swing();
  };
  m.coupling_torque_swing = swingOf("coupling_torque");
  m.twist_swing = swingOf("twist");
  m.twist_rate_swing = swingOf("twist_rate");
  m.twist_accel_swing = swingOf("twist_accel");
}

// Reactions over the same time span, on the reactions table's own rows.
void addReactions(WindowMetrics& m, const Table& rx, const SteadyState& w) {
  if (!rx.has("t") || rx.rows.empty()) return;
  const std::vector<double> rt = rx.column("t");
  std::size_t rb = 0;
  while (rb < rt.size() && !(rt[rb] >= w.t_begin)) ++rb;
  std::size_t re = rb;
  while (re < rt.size() && rt[re] <= w.t_end) ++re;
  for (const std::string& name : rx.columns) {
    if (name == "t") continue;
    m.reactions.emplace_back(name, columnStats(rt, rx.column(name), rb, re));
  }
}

}  // namespace

WindowMetrics computeMetrics(const RunResult& run, const SteadyState& w) {
  WindowMetrics m;
  const Table& ts = run.timeseries;
  m.omega_min = m.omega_max = m.omega_mean = m.omega_midrange = m.eps_abs_max = kNaN;
  m.coefficients = {kNaN, kNaN, kNaN};

  const bool have_time = ts.has("t");
  const std::vector<double> t = have_time ? ts.column("t") : std::vector<double>{};
  const std::size_t n = std::min(w.finite_rows, t.size());
  const std::size_t b = std::min(w.row_begin, n), e = std::min(w.row_end, n);
  m.rows = e - b;
  const WindowRows rows{t, n, b, e};

  if (have_time && ts.has("omega_crank")) addCrankSpeedExtremes(m, run, w, rows);
  if (have_time && ts.has("phi_crank") && w.t_end > w.t_begin && n > 0) {
    // Time-weighted mean speed Δφ/Δt; over whole revolutions this is 2π·N/Δt exactly.
    const std::vector<double> phi = ts.column("phi_crank");
    m.omega_mean = (interpolateAt(t, phi, n, w.t_end) - interpolateAt(t, phi, n, w.t_begin)) /
                   (w.t_end - w.t_begin);
  }
  m.coefficients = motionCoefficients(m.omega_min, m.omega_max, m.omega_mean, m.eps_abs_max);
  addCouplingSwings(m, ts, have_time, rows);
  addReactions(m, run.reactions, w);
  return m;
}

}  // namespace rollerdyn
