#include "analysis/StartUpRows.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "io/FieldFormat.h"

namespace rollerdyn {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// No steady state within the run: its last whole revolution stands in for it (said in the notes).
RowSpan lastRevolutionStandsIn(const SteadyState& ss, const std::vector<double>& t, StartUp& r) {
  r.steady_begin = ss.revolutions.back().t_begin;
  r.steady_end = ss.revolutions.back().t_end;
  r.notes.push_back("The run reaches no steady state (the last revolutions' mean crank speeds differ by more "
                    "than 1e-3): its last whole revolution, t = " + significant(r.steady_begin, 4) + " ... " +
                    significant(r.steady_end, 4) + " s, stands in for the steady window.");
  return {firstRowAtOrAfter(t, r.steady_begin), std::min(t.size(), firstRowAtOrAfter(t, r.steady_end) + 1)};
}

}  // namespace

std::vector<double> columnOr(const Table& t, const std::string& name) {
  return t.has(name) ? t.column(name) : std::vector<double>{};
}

std::size_t firstRowAtOrAfter(const std::vector<double>& t, double when) {
  return std::size_t(std::lower_bound(t.begin(), t.end(), when - 1e-12) - t.begin());
}

double extremeOf(const std::vector<double>& c, RowSpan rows, Extreme kind) {
  const bool lowest = kind == Extreme::Smallest, absolute = kind == Extreme::LargestMagnitude;
  double m = lowest ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
  for (std::size_t i = rows.begin; i < rows.end && i < c.size(); ++i) {
    const double v = absolute ? std::abs(c[i]) : c[i];
    m = lowest ? std::min(m, v) : std::max(m, v);
  }
  return std::isfinite(m) ? m : kNaN;
}

SteadyWindow findSteadyWindow(const Scene& sc, const RunResult& run, const std::vector<double>& t,
                              const std::vector<double>& w, StartUp& r) {
  SteadyWindow window;
  // A switch-off at or after the last row is none in this run (no stop to answer).
  r.t_off = std::isfinite(sc.motor_stop.t_off) && sc.motor_stop.t_off < t.back() ? sc.motor_stop.t_off : kNaN;
  window.n_running = t.size();
  if (std::isfinite(r.t_off)) window.n_running = std::min(window.n_running, firstRowAtOrAfter(t, r.t_off));
  const SteadyState& ss = window.state = detectRunningSteadyState(run, sc.simulation.steady_window_revolutions, r.t_off);
  r.steady_reached = ss.reached;
  r.steady_begin = ss.t_begin;
  r.steady_end = ss.t_end;
  const RowSpan rows = !ss.reached && !ss.revolutions.empty() ? lastRevolutionStandsIn(ss, t, r)
                                                              : RowSpan{ss.row_begin, std::min(ss.row_end, t.size())};
  const std::size_t w0 = rows.begin, w1 = rows.end;
  window.rows = rows;
  window.duration = w1 > w0 + 1 ? t[w1 - 1] - t[w0] : 0.0;
  r.steady_mean_speed =
      window.duration > 0 ? integrate(t, w0, w1, [&](std::size_t i) { return w[i]; }) / window.duration : kNaN;
  window.lowest_speed = std::numeric_limits<double>::infinity();
  for (std::size_t i = w0; i < w1; ++i) window.lowest_speed = std::min(window.lowest_speed, w[i]);
  return window;
}

RowSpan findStartRows(const std::vector<double>& t, const SteadyWindow& window, StartUp& r) {
  const SteadyState& ss = window.state;
  const double run_last = window.n_running == 0 ? t.back() : t[window.n_running - 1];
  if (r.starts && ss.reached && std::isfinite(ss.t_settled) && ss.t_settled > r.t_on && ss.t_settled <= r.steady_begin)
    r.start_end = std::max(ss.t_settled, r.t_on + r.run_up_time);
  else if (!r.starts && !r.still_starting)
    r.start_end = run_last;
  else
    r.start_end = r.steady_begin > r.t_on ? r.steady_begin : run_last;
  const std::size_t s0 = firstRowAtOrAfter(t, r.t_on), s1 = std::max(s0 + 1, firstRowAtOrAfter(t, r.start_end) + 1);
  return {s0, std::min(s1, t.size())};
}

}  // namespace rollerdyn
