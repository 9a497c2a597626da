// Steady-state metrics of one run, taken over the window found by detectSteadyState():
// the crank-speed coefficients of Loveikin and Pochka (2007) eq. (12)-(14) and the coupling swings of
// Loveikin, Pochka, Romasevych (2018) Table 1, plus a summary of every reaction column.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "analysis/RunResult.h"
#include "analysis/SteadyState.h"
#include "io/Table.h"

namespace rollerdyn {

// Coefficients judging how even the crank rotation is (Loveikin and Pochka (2007)).
struct MotionCoefficients {
  double delta = 0;  // coefficient of unevenness δ = (ω_max - ω_min)/ω_mean        Loveikin and Pochka (2007), eq. (12)
  double H = 0;      // coefficient of dynamics H = |ε|_max/ω_mean²                  Loveikin and Pochka (2007), eq. (13)
  double k_p = 0;    // generalised coefficient k_p = (ω_max - ω_min)²/ω_mean² + |ε|_max/ω_mean²
                     //                                                              Loveikin and Pochka (2007), eq. (14)
};
MotionCoefficients motionCoefficients(double omega_min, double omega_max, double omega_mean,
                                      double eps_abs_max);

// Extremes and mean of one column over a window. The mean is time-weighted (trapezoidal rule),
// so output rows unevenly spaced in time (e.g. the Baranov scheme, fixed steps in crank angle)
// do not bias it. All fields are NaN when the window is empty or holds a non-finite value.
struct ColumnStats {
  double min, max, mean, abs_max;
  double swing() const { return max - min; }  // "deviation" Δ of Loveikin, Pochka, Romasevych (2018) Table 1
};
// t and y must be the same length; rows [begin, end) are used.
ColumnStats columnStats(const std::vector<double>& t, const std::vector<double>& y,
                        std::size_t begin, std::size_t end);

struct WindowMetrics {
  std::size_t rows = 0;          // timeseries rows in the window
  double omega_min = 0, omega_max = 0;  // extremes of omega_crank: its rows and the extrema located
                                        // between them (RunResult::crank_speed_extrema) [rad/s]
  double omega_mean = 0;         // Δφ/Δt over the window (time-weighted, not the sample mean) [rad/s]
  double omega_midrange = 0;     // (ω_max + ω_min)/2: what Loveikin and Pochka's (2007) table prints as ω_mean
                                 // (e.g. (9.67 + 11.25)/2 = 10.46); kept to compare with it
  double eps_abs_max = 0;        // max |eps_crank| [rad/s²]
  bool eps_from_difference = false;  // eps_crank absent: ε from finite differences of omega_crank
  MotionCoefficients coefficients;
  // Swings (max - min) over the window, Loveikin, Pochka, Romasevych (2018) Table 1: ΔM_coupling [N·m], Δ(φ1 - φ2) [rad],
  // Δ(φ̇1 - φ̇2) [rad/s], Δ(φ̈1 - φ̈2) [rad/s²]. 0 when the column is absent (rigid drive).
  double coupling_torque_swing = 0, twist_swing = 0, twist_rate_swing = 0, twist_accel_swing = 0;
  std::vector<std::string> missing_columns;  // optional columns not in the timeseries
  // Every reactions column except t, in table order, over the same time window.
  std::vector<std::pair<std::string, ColumnStats>> reactions;
};

// Metrics of `run` over `window`. Reactions rows are chosen by time (t_begin <= t <= t_end), so
// the reactions table may have its own time grid.
WindowMetrics computeMetrics(const RunResult& run, const SteadyState& window);

}  // namespace rollerdyn
