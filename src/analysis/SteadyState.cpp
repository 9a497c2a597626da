#include "analysis/SteadyState.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace rollerdyn {

namespace {

constexpr double kTwoPi = 6.283185307179586476925286766559;
// Share of the run used as the window when not even one whole revolution was completed.
constexpr double kFallbackShare = 0.2;

// Half-open row range [begin, end) of rows with t_begin <= t <= t_end (t ascending).
void setRowRange(const std::vector<double>& t, std::size_t n, SteadyState& s) {
  const auto first = t.begin();
  const auto last = t.begin() + static_cast<std::ptrdiff_t>(n);
  s.row_begin = static_cast<std::size_t>(std::lower_bound(first, last, s.t_begin) - first);
  s.row_end = static_cast<std::size_t>(std::upper_bound(first, last, s.t_end) - first);
  if (s.row_end < s.row_begin) s.row_end = s.row_begin;
}

// Whole revolutions: the times of the first crossings of phi_0 + 2πk in the direction `dir` of net rotation.
std::vector<double> revolutionCrossings(const std::vector<double>& t, const std::vector<double>& phi, std::size_t n,
                                        double dir) {
  std::vector<double> crossings{t[0]};
  for (std::size_t i = 1; i < n; ++i) {
    const double u_prev = dir * (phi[i - 1] - phi[0]);
    const double u = dir * (phi[i] - phi[0]);
    double target = kTwoPi * static_cast<double>(crossings.size());
    while (u >= target && u_prev < target) {
      const double frac = (target - u_prev) / (u - u_prev);
      crossings.push_back(t[i - 1] + frac * (t[i] - t[i - 1]));
      target = kTwoPi * static_cast<double>(crossings.size());
    }
  }
  return crossings;
}

// Widens each revolution's lowest and highest speed by speeds given in time order (a cursor over
// the revolutions).
class ExtremesWidener {
 public:
  explicit ExtremesWidener(std::vector<CrankRevolution>& revolutions) : revolutions_(revolutions) {}
  void widen(double tq, double w) {
    while (r_ < revolutions_.size() && revolutions_[r_].t_end < tq) ++r_;
    if (r_ == revolutions_.size() || tq < revolutions_[r_].t_begin) return;
    revolutions_[r_].omega_min = std::min(revolutions_[r_].omega_min, w);
    revolutions_[r_].omega_max = std::max(revolutions_[r_].omega_max, w);
  }

 private:
  std::vector<CrankRevolution>& revolutions_;
  std::size_t r_ = 0;
};

// The run's whole crank revolutions, each with its mean speed and its lowest and highest speed.
std::vector<CrankRevolution> wholeRevolutions(const std::vector<double>& t, const std::vector<double>& phi,
                                              const std::vector<double>& omega, std::size_t n,
                                              const std::vector<CrankSpeedExtremum>& extrema) {
  const double dir = phi[n - 1] >= phi[0] ? 1.0 : -1.0;
  const std::vector<double> crossings = revolutionCrossings(t, phi, n, dir);
  std::vector<CrankRevolution> revolutions;
  for (std::size_t k = 0; k + 1 < crossings.size(); ++k)
    revolutions.push_back({crossings[k], crossings[k + 1], dir * kTwoPi / (crossings[k + 1] - crossings[k]),
                           std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()});
  // Each revolution's extremes: its rows and the extrema located inside the integrator's steps.
  ExtremesWidener by_rows(revolutions);
  for (std::size_t i = 0; i < n; ++i) by_rows.widen(t[i], omega[i]);
  ExtremesWidener by_located(revolutions);
  for (const CrankSpeedExtremum& x : extrema) by_located.widen(x.t, x.omega);
  return revolutions;
}

// Settling index: the first revolution of the run's final stretch of revolutions that repeat its
// last one.
int settledAfter(const std::vector<CrankRevolution>& revolutions, double relative_tolerance) {
  // Walk back from the final revolution while the revolutions repeat it: mean, lowest and highest
  // speed each within the tolerance of the mean speed.
  const CrankRevolution& last = revolutions.back();
  const double tol = relative_tolerance * std::abs(last.omega_mean);
  const auto repeats = [&](const CrankRevolution& k) {
    const auto within = [&](double a, double b) { return std::abs(a - b) < tol || (!std::isfinite(a) && a == b); };
    return within(k.omega_mean, last.omega_mean) && within(k.omega_min, last.omega_min) &&
           within(k.omega_max, last.omega_max);
  };
  int after = static_cast<int>(revolutions.size()) - 1;
  while (after > 0 && repeats(revolutions[after - 1])) --after;
  return after;
}

// Appends one reason to a note ("; " between reasons).
void appendNote(std::string& note, const std::string& why) { note = note.empty() ? why : note + "; " + why; }

// The finite prefix of the rows: a run that blew up has nothing steady after the blow-up. A row
// counts while t, phi_crank and (when the table has it) omega_crank are finite.
std::size_t finiteRowCount(const Table& ts) {
  const int it = ts.index("t"), ip = ts.index("phi_crank"), iw = ts.has("omega_crank") ? ts.index("omega_crank") : -1;
  std::size_t n = 0;
  while (n < ts.rows.size() && std::isfinite(ts.rows[n][it]) && std::isfinite(ts.rows[n][ip]) &&
         (iw < 0 || std::isfinite(ts.rows[n][iw])))
    ++n;
  return n;
}

// Analyse only the finite prefix (finiteRowCount), noting where the run has non-finite values;
// false when fewer than two rows remain.
bool takeFiniteRows(SteadyState& s, const Table& ts, const std::vector<double>& t) {
  const std::size_t n = finiteRowCount(ts);
  s.finite_rows = n;
  if (n < t.size())
    s.note = "non-finite values from t = " + std::to_string(t[n]) + " s; analysed rows before it";
  if (n >= 2) return true;
  s.note = s.note.empty() ? "fewer than two rows" : s.note + "; fewer than two finite rows";
  return false;
}

// Stalled or very slow run: no periodicity to judge; take the last 20 % of the run.
void takeFallbackWindow(SteadyState& s, const std::vector<double>& t, std::size_t n, int wanted) {
  s.window_revolutions = 0;
  s.t_end = t[n - 1];
  s.t_begin = t[n - 1] - kFallbackShare * (t[n - 1] - t[0]);
  setRowRange(t, n, s);
  appendNote(s.note, "no whole crank revolution; window = last 20 % of the run");
  s.not_reached = steadyStateNotReached(s, t[0], t[n - 1], std::max(wanted, 2));
}

// The window over the last whole revolutions, and whether the run settled before it.
void takeRevolutionWindow(SteadyState& s, const std::vector<double>& t, std::size_t n, int wanted,
                          double relative_tolerance) {
  const int count = s.revolutions_counted;
  const int after = settledAfter(s.revolutions, relative_tolerance);
  s.after_revolutions = after;
  s.t_settled = s.revolutions[after].t_begin;

  const int needed = std::max(wanted, 2);  // one revolution cannot be compared with anything
  s.reached = count >= needed && after <= count - needed;
  if (count < needed)
    appendNote(s.note, "only " + std::to_string(count) + " whole revolution(s), " + std::to_string(needed) +
                           " needed to judge steady state");

  s.window_revolutions = std::min(wanted, count);
  s.t_begin = s.revolutions[count - s.window_revolutions].t_begin;
  s.t_end = s.revolutions.back().t_end;
  setRowRange(t, n, s);
  s.not_reached = steadyStateNotReached(s, t[0], t[n - 1], needed);
}

// The running ends at the switch-off: a longer run would not help, a later switch-off would.
void adviseLaterSwitchOff(SteadyState& s, double t_off) {
  const std::size_t at = s.not_reached.rfind("run at least ");
  if (at == std::string::npos) return;
  char later[160];
  std::snprintf(later, sizeof later,
                "switch the motor off later (motor.stop.t_off = %.4g s): the running before it is too short", t_off);
  s.not_reached = s.not_reached.substr(0, at) + later;
}

}  // namespace

SteadyState detectSteadyState(const Table& ts, double window_revolutions, double relative_tolerance,
                              const std::vector<CrankSpeedExtremum>& extrema) {
  SteadyState s;
  s.relative_tolerance = relative_tolerance;
  s.t_settled = std::numeric_limits<double>::quiet_NaN();
  if (!ts.has("t") || !ts.has("phi_crank")) {
    s.note = "timeseries lacks column t or phi_crank";
    return s;
  }
  const std::vector<double> t = ts.column("t");
  const std::vector<double> phi = ts.column("phi_crank");
  const std::vector<double> omega =
      ts.has("omega_crank") ? ts.column("omega_crank") : std::vector<double>(t.size(), 0.0);
  if (!takeFiniteRows(s, ts, t)) return s;
  const std::size_t n = s.finite_rows;
  s.revolutions = wholeRevolutions(t, phi, omega, n, extrema);
  s.revolutions_counted = static_cast<int>(s.revolutions.size());
  const int wanted = std::max(1, static_cast<int>(std::floor(window_revolutions)));
  if (s.revolutions_counted < 1)
    takeFallbackWindow(s, t, n, wanted);
  else
    takeRevolutionWindow(s, t, n, wanted, relative_tolerance);
  return s;
}

SteadyState detectSteadyState(const RunResult& run, double window_revolutions) {
  return detectSteadyState(run.timeseries, window_revolutions, kSteadyStateRelativeTolerance, run.crank_speed_extrema);
}

SteadyState detectRunningSteadyState(const RunResult& run, double window_revolutions, double t_off) {
  return detectRunningSteadyState(run.timeseries, window_revolutions, t_off, run.crank_speed_extrema);
}

std::string steadyStateNotReached(const SteadyState& s, double t_first, double t_last, int window_revolutions) {
  if (s.reached) return "";
  const double span = t_last - t_first;
  double at_least = t_first + 2.0 * span;
  if (!s.revolutions.empty()) {
    const CrankRevolution& last = s.revolutions.back();
    at_least = std::max(at_least, t_last + (window_revolutions + 1) * (last.t_end - last.t_begin));
  }
  // Round up to two significant figures so the advice reads as a setting.
  const double scale = std::pow(10.0, std::floor(std::log10(std::max(at_least, 1e-9))) - 1.0);
  at_least = std::ceil(at_least / scale - 1e-9) * scale;
  char buf[400];
  std::snprintf(buf, sizeof buf,
                "steady state not reached within the run (t = %.4g ... %.4g s: the last %d revolutions' mean, lowest "
                "and highest crank speeds do not agree within %.2g %% of the mean, or there are fewer than %d): run "
                "at least %.3g s (simulation.t_end)",
                t_first, t_last, window_revolutions, 100.0 * s.relative_tolerance, window_revolutions, at_least);
  return buf;
}

SteadyState detectRunningSteadyState(const Table& ts, double window_revolutions, double t_off,
                                     const std::vector<CrankSpeedExtremum>& extrema) {
  if (!std::isfinite(t_off) || !ts.has("t") || !ts.has("phi_crank"))
    return detectSteadyState(ts, window_revolutions, kSteadyStateRelativeTolerance, extrema);
  const int it = ts.index("t");
  const auto first_off = std::find_if(ts.rows.begin(), ts.rows.end(),
                                      [&](const std::vector<double>& row) { return row[it] >= t_off - 1e-12; });
  if (first_off == ts.rows.end()) return detectSteadyState(ts, window_revolutions, kSteadyStateRelativeTolerance, extrema);
  Table running;
  running.columns = ts.columns;
  running.rows.assign(ts.rows.begin(), first_off);
  std::vector<CrankSpeedExtremum> before;
  for (const CrankSpeedExtremum& x : extrema)
    if (x.t < t_off) before.push_back(x);
  SteadyState s = detectSteadyState(running, window_revolutions, kSteadyStateRelativeTolerance, before);
  // Whole-run figures read finite_rows: count them over every row.
  if (s.finite_rows == running.rows.size()) s.finite_rows = finiteRowCount(ts);
  char why[96];
  std::snprintf(why, sizeof why, "steady window searched before the switch-off at t = %.4g s", t_off);
  appendNote(s.note, why);
  adviseLaterSwitchOff(s, t_off);
  return s;
}

}  // namespace rollerdyn
