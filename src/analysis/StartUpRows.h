// The start-up's rows (StartUp.h), internal to the start-up's files: where the steady window and
// the start interval lie on a run's output grid, and how a column is read over such rows (its
// extreme, its integral by the trapezoidal rule).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "analysis/RunResult.h"
#include "analysis/StartUp.h"
#include "analysis/SteadyState.h"
#include "io/Table.h"
#include "scene/Scene.h"

namespace rollerdyn {

// Rows [begin, end) of a run's output grid.
struct RowSpan {
  std::size_t begin = 0, end = 0;
};

// A column of the table, or empty when absent.
std::vector<double> columnOr(const Table& t, const std::string& name);

// ∫ f dt over rows [a, b) by the trapezoidal rule (pairs of rows both inside).
template <class F>
double integrate(const std::vector<double>& t, std::size_t a, std::size_t b, F f) {
  double sum = 0;
  for (std::size_t i = a + 1; i < b && i < t.size(); ++i) sum += 0.5 * (f(i - 1) + f(i)) * (t[i] - t[i - 1]);
  return sum;
}

// The first row at or after time `when` (t sorted; t.size() when none).
std::size_t firstRowAtOrAfter(const std::vector<double>& t, double when);

// How a peak is taken over rows of a column.
enum class Extreme { Largest, Smallest, LargestMagnitude };

// The extreme of column c over rows, or NaN where it has no such rows.
double extremeOf(const std::vector<double>& c, RowSpan rows, Extreme kind);

// The steady window of the running part of the run, against which the start is measured.
struct SteadyWindow {
  SteadyState state;         // the steady state on the rows before the switch-off
  RowSpan rows;              // its rows; without a steady state, the last whole revolution's
  double duration = 0;       // [s]; 0 for fewer than two rows
  double lowest_speed = 0;   // the crank's lowest speed in it [rad/s]
  std::size_t n_running = 0; // rows before the switch-off
};

// The steady window: on the rows before the switch-off. Sets r.t_off, the window's times and the
// steady mean crank speed. `t`, `w`: the run's times and crank speeds.
SteadyWindow findSteadyWindow(const Scene& sc, const RunResult& run, const std::vector<double>& t,
                              const std::vector<double>& w, StartUp& r);

// The start interval [t_on, start_end) (sets r.start_end) and its rows. A drive that runs up: until
// its crank speed settles (SteadyState::t_settled, the first revolution from which every later
// one's mean speed is within tolerance of the final one), so the start is the same however long
// the run continues after it (the steady window is the run's last revolutions and moves with
// simulation.t_end). A drive that does not start: the whole running part of the run, since no part
// of it is steady. Call after the run-up is judged (r.starts, r.still_starting, r.run_up_time).
RowSpan findStartRows(const std::vector<double>& t, const SteadyWindow& window, StartUp& r);

}  // namespace rollerdyn
