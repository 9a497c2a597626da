// The crank speed's local extrema, located inside the integrator's own steps rather than read off
// the output rows.
//
// Why: δ = (ω_max − ω_min)/ω_mean (Loveikin and Pochka (2007), eq. (12)) and the steady-state
// test read the crank speed's extremes. Read off output rows h apart, an extreme sharper than h
// is missed by up to |ω̈|·h²/8, and by a different amount in every revolution as the rows slide
// along the motion: a two-cart drive near its dead centres (ω = 6.6 … 21 rad/s, h = 5 ms) showed
// per-revolution minima from 6.66 to 8.02 rad/s for one periodic motion whose true minimum is
// 6.637 rad/s. The integrator's steps are sized by its error control, so they are short exactly
// where the motion is sharp.
//
// Rule: where ε changes sign strictly inside a step [t0, t1], ω has a local extremum there. It is
// located on the integrator's own interpolant of the step when the integrator has one of its
// order (CVODE's, through `dense`), by regula falsi on ε to 1e-12 of the step; otherwise on the
// cubic Hermite interpolant through (ω0, ε0) and (ω1, ε1), the one the multibody loop samples its
// rows from, whose derivative is a quadratic with a closed-form root. (Hermite on CVODE's long
// Adams steps undershot a sharp minimum by 0.07 rad/s, 1 % of it: hence the integrator's own.)
#pragma once

#include <functional>
#include <vector>

#include "io/Table.h"

namespace rollerdyn {

struct CrankSpeedExtremum {
  double t = 0;      // time of the extremum [s]
  double omega = 0;  // crank speed there [rad/s]
};

// Feeds one integrator step at a time and keeps every local extremum found inside the steps.
class CrankSpeedExtremaFinder {
 public:
  // The step from (t0, ω0, ε0) to (t1, ω1, ε1): ω [rad/s], ε = dω/dt [rad/s²], t1 > t0 [s].
  void step(double t0, double omega0, double eps0, double t1, double omega1, double eps1);
  // Starts the chain of steps afresh at (t, ω, ε), e.g. after an event restarted the integrator.
  void restart(double t, double omega, double eps);
  // The integrator's interpolant of its last step: ω and ε at any t inside it.
  using Dense = std::function<void(double t, double& omega, double& eps)>;
  // Continues the chain: the step from the last point given (restart or the end of the last step)
  // to (t, ω, ε); `dense`, when given, is the integrator's interpolant over that step.
  void stepTo(double t, double omega, double eps, const Dense& dense = nullptr);
  // An extremum the integrator found itself (a scheme whose ω is piecewise linear has them at its nodes).
  void record(double t, double omega) { extrema_.push_back({t, omega}); }
  // Forgets the extrema after t [s]: those of a step an event cut short at t.
  void dropAfter(double t);
  const std::vector<CrankSpeedExtremum>& extrema() const { return extrema_; }
  // The extrema up to the run's last output row t_last [s] (the integrator's last step may reach
  // beyond it), handed over to the RunResult.
  std::vector<CrankSpeedExtremum> takeUpTo(double t_last);

 private:
  std::vector<CrankSpeedExtremum> extrema_;
  bool have_last_ = false;
  double t_ = 0, omega_ = 0, eps_ = 0;
};

// The extrema as the table crank_speed_extrema.csv: columns t [s], omega_crank [rad/s], one row
// per extremum, so that an engineer can recompute δ and the steady window's extremes from files.
Table crankSpeedExtremaTable(const std::vector<CrankSpeedExtremum>& extrema);

}  // namespace rollerdyn
