// The supply's switching events (motor/Supply.h) in a CVODE run, the same for every model that
// CVODE integrates: CVODE stops at the next timed event (its stop time) and at a speed-triggered
// one (its root finding of ω_r - ω_switch, rising, on its interpolant); the model applies the
// event there (the law's states mapped across it) and CVODE restarts from the new state.
//
// What the events need of a model is its own: where the supply phase is kept, how the rotor speed
// is read from the state and how an event changes the state; the model hands them over as
// CvodeSupplyEvents::Model.
#pragma once

#include <functional>
#include <limits>

#include <Eigen/Core>

#include "motor/Supply.h"
#include "numerics/CvodeIntegrator.h"

namespace rollerdyn {

class CvodeSupplyEvents {
 public:
  // The model's own pieces of its events.
  struct Model {
    const Supply* supply = nullptr;  // none, or a constant supply: no events, the run as without
    double t_end = 0;                // the run's end [s]: CVODE never stops later
    std::function<double(const double* y)> rotor_speed;  // ω_r [rad/s] in the state y
    std::function<SupplyPhase()> phase;                   // the phase the equations run in
    // Applies the events due at t to y (speed_reached: CVODE found the trigger speed's root);
    // true when anything switched.
    std::function<bool(double t, Eigen::VectorXd& y, bool speed_reached)> apply;
  };

  explicit CvodeSupplyEvents(Model model);
  CvodeSupplyEvents(const CvodeSupplyEvents&) = delete;
  CvodeSupplyEvents& operator=(const CvodeSupplyEvents&) = delete;

  // Applies the events due at the start t0 to the initial state y0 (a speed trigger the initial
  // speed already meets), before CVODE is built from it.
  void applyAtStart(double t0, Eigen::VectorXd& y0) const { model_.apply(t0, y0, false); }
  // Sets the problem's event function, ω_r - ω_switch of the present phase (refers to this object).
  void install(OdeProblem& p);
  // Sets the integrator's stop time and event function for the supply's present phase.
  void arm(CvodeIntegrator& integ);
  // Advances to the output time t_out, applying the events due on the way; false when CVODE gave
  // up. A run without events is exactly CVODE's advance to t_out.
  bool advanceTo(CvodeIntegrator& integ, double t_out);

 private:
  // After a return of the integrator: applies the events due there, restarts it from the new
  // state and arms it again.
  void applyDue(CvodeIntegrator& integ);

  Model model_;
  bool active_;
  double trigger_speed_ = std::numeric_limits<double>::quiet_NaN();  // of the present phase [rad/s]
};

}  // namespace rollerdyn
