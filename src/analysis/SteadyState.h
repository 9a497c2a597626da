// Steady-state detection: which part of a run the steady-state metrics (Loveikin and Pochka (2007) eq. (12)-(14),
// Loveikin, Pochka, Romasevych (2018) Table 1) are taken over. Both papers read their numbers "on the steady-state part of
// the motion" without saying how it is found; this is the rule used here.
//
// The crank angle is split into whole revolutions: revolution k (0-based) runs from the time
// phi_crank first reaches phi_0 + 2πk to the time it first reaches phi_0 + 2π(k+1), phi_0 being
// the angle at the first row (crossing times are interpolated linearly between output rows).
// Every load and inertia of the machine is 2π-periodic in the crank angle, so once the motion is
// periodic every revolution takes the same time and the mean crank speed per revolution,
// 2π / (revolution time), is constant; during a start-up it keeps changing.
//
// Steady state is *reached* when each of the last N = steady_window_revolutions revolutions has
// its mean speed, its lowest and its highest crank speed within `relative_tolerance`·|final
// revolution's mean| of the final revolution's (at least two revolutions are needed to judge:
// with one there is nothing to compare). Comparing with the final revolution rather than with the
// neighbour bounds the total drift over the window, so a slow ramp cannot pass by changing little
// per revolution. The extremes count because δ and every peak the sizing reads are taken from
// them: a revolution can repeat its mean while its waveform still settles (a drive whose coupling
// mode decays slowly kept its mean to 1e-3 one revolution after the start while its largest speed
// was still 0.2 % of the mean above the later revolutions'). A revolution's extremes are those of
// its output rows and of the crank speed's extrema the integrator located inside its steps
// (CrankSpeedExtrema.h); the rows alone miss a sharp extreme by a different amount every revolution.
//
// Default tolerance 1e-3 (relative), why:
//  * the papers print mean crank speeds to 4 significant figures (Loveikin and Pochka (2007): 10.46 rad/s, i.e.
//    ±0.005/10.46 ≈ 5e-4); a drift below 1e-3 is invisible at the precision of the reference
//    tables the metrics are compared with, and it changes δ (≈ 0.15 … 0.5) by under 1e-3 of
//    its value;
//  * it sits far above the measurement noise of a revolution time: linear interpolation of a
//    crossing between output rows h apart errs by about |ε|h²/(8ω) in time, e.g. 17 rad/s²,
//    h = 0.01 s, ω = 10 rad/s → 2e-5 s on a 0.6 s revolution (3e-5 relative), and integrator
//    accuracies are 1e-4 … 1e-8;
//  * it is not so loose that a start-up passes early: an exponential approach
//    ω_s(1 - e^{-t/τ}) passes when e^{-t/τ} ≈ 1e-3, i.e. after ≈ 7τ.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "analysis/CrankSpeedExtrema.h"
#include "analysis/RunResult.h"
#include "io/Table.h"

namespace rollerdyn {

// Default relative tolerance on per-revolution mean crank speed; argued above.
inline constexpr double kSteadyStateRelativeTolerance = 1e-3;

// One whole crank revolution found in a run.
struct CrankRevolution {
  double t_begin = 0, t_end = 0;  // interpolated crossing times [s]
  double omega_mean = 0;          // 2π/(t_end - t_begin), signed with the direction of rotation [rad/s]
  double omega_min = 0, omega_max = 0;  // lowest and highest crank speed within it [rad/s]
};

struct SteadyState {
  bool reached = false;          // the last `window_revolutions` revolutions agree within tolerance
  int after_revolutions = -1;    // 0-based index of the first revolution from which every later
                                 // revolution's mean speed is within tolerance of the final one;
                                 // -1 when there is no whole revolution
  double t_settled = 0;          // start time of revolution `after_revolutions` [s] (NaN if none)
  int revolutions_counted = 0;   // whole revolutions in the run
  int window_revolutions = 0;    // whole revolutions in the metrics window (0: the 20 % fallback)
  double relative_tolerance = kSteadyStateRelativeTolerance;
  // Metrics window: time span and the half-open range of timeseries rows inside it.
  double t_begin = 0, t_end = 0;
  std::size_t row_begin = 0, row_end = 0;
  std::size_t finite_rows = 0;   // rows before the first non-finite t / phi_crank / omega_crank
  std::vector<CrankRevolution> revolutions;
  std::string note;              // why the detection fell back or could not judge; empty otherwise
  // When no steady state was reached: what is missing and how long to run, e.g. "steady state not
  // reached within the run (t = 0 ... 3 s): run at least 6 s (simulation.t_end) ..."; the one
  // sentence every check that needs the steady window gives as its reason. Empty when reached.
  std::string not_reached;
};

// The advice above for a window `s` of a run whose finite rows end at `t_last` [s], started at
// `t_first` [s], with `window_revolutions` wanted: at least twice the run, and at least the run
// plus the revolutions the judgement needs at the last revolution's duration (a lower bound: a
// drive whose speed still drifts needs longer).
std::string steadyStateNotReached(const SteadyState& s, double t_first, double t_last, int window_revolutions);

// Finds the steady-state window of a timeseries with columns t, phi_crank (omega_crank is only
// checked for finiteness). `window_revolutions` is scene.simulation.steady_window_revolutions,
// rounded down, at least 1. When the run has fewer than one whole revolution the window is the
// last 20 % of the run time and reached = false. Never throws on missing columns or short
// tables: it returns an empty window and explains in `note`.
// `extrema`: the run's RunResult::crank_speed_extrema (empty: the rows' extremes alone).
SteadyState detectSteadyState(const Table& timeseries, double window_revolutions,
                              double relative_tolerance = kSteadyStateRelativeTolerance,
                              const std::vector<CrankSpeedExtremum>& extrema = {});

// The steady state of the machine's running when the motor is switched off at `t_off` within the
// run (motor.stop.t_off; +inf or NaN: never): detectSteadyState on the rows before t_off, since
// the coast-down after it is no steady state. Rows at t_off already show the switched-off state.
// `finite_rows` still counts the whole run's finite rows, so whole-run figures keep the
// coast-down. The summary, the sizing and the start-up answers all read this one window.
SteadyState detectRunningSteadyState(const Table& timeseries, double window_revolutions, double t_off,
                                     const std::vector<CrankSpeedExtremum>& extrema = {});

// The same two for a run in memory: its timeseries with the crank speed's extrema its integrator
// located (RunResult::crank_speed_extrema), at the default tolerance. Every caller that has the run
// uses these, so no window is judged without the extrema the summary's was judged with.
SteadyState detectSteadyState(const RunResult& run, double window_revolutions);
SteadyState detectRunningSteadyState(const RunResult& run, double window_revolutions, double t_off);

}  // namespace rollerdyn
