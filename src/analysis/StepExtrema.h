// The crank speed's extrema inside CVODE's steps (CrankSpeedExtrema.h), the same for every model
// that CVODE integrates: the finder fed through OdeProblem::on_step, each step's end with ε from
// CVODE's interpolant and the extrema inside the step located on that interpolant.
//
// At a (re)start the chain begins afresh at (t, ω, f(t, y)), and the extrema after t are
// forgotten: a restart at t inside a step already observed (an event applied at an output time
// CVODE interpolated back to) replaces the motion beyond t, and what the step showed there
// belongs to the motion that no longer happens. A restart at a root or a stop time finds nothing
// to forget: CVODE observes that step's end at the root or the stop time itself.
#pragma once

#include <vector>

#include "analysis/CrankSpeedExtrema.h"
#include "numerics/CvodeIntegrator.h"

namespace rollerdyn {

class StepExtrema {
 public:
  // i_omega: the crank speed's index in CVODE's state; negative where it is none (a prescribed
  // speed has no extrema).
  explicit StepExtrema(int i_omega);
  StepExtrema(const StepExtrema&) = delete;
  StepExtrema& operator=(const StepExtrema&) = delete;

  // Sets the problem's step observer (refers to this object).
  void install(OdeProblem& p);
  // The integrator built from that problem, whose interpolant the steps are read on.
  void observe(const CvodeIntegrator& integ) { integ_ = &integ; }
  // The extrema up to the run's last output row t_last [s], handed over.
  std::vector<CrankSpeedExtremum> takeUpTo(double t_last) { return finder_.takeUpTo(t_last); }

 private:
  void onStep(double t, const double* y, const double* ydot, bool after_step);

  const int i_omega_;
  const CvodeIntegrator* integ_ = nullptr;  // set once the integrator exists
  CrankSpeedExtremaFinder finder_;
  // CVODE's interpolant of its last step: ω and ε inside it (called only after a step).
  const CrankSpeedExtremaFinder::Dense dense_;
};

}  // namespace rollerdyn
