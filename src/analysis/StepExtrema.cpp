#include "analysis/StepExtrema.h"

namespace rollerdyn {

StepExtrema::StepExtrema(int i_omega)
    : i_omega_(i_omega), dense_([this](double tq, double& w, double& eps) {
        w = integ_->interpolate(tq, 0, i_omega_);
        eps = integ_->interpolate(tq, 1, i_omega_);
      }) {}

void StepExtrema::install(OdeProblem& p) {
  if (i_omega_ < 0) return;
  p.on_step = [this](double t, const double* y, const double* ydot, bool after_step) {
    onStep(t, y, ydot, after_step);
  };
}

void StepExtrema::onStep(double t, const double* y, const double* ydot, bool after_step) {
  if (after_step && integ_) {
    finder_.stepTo(t, y[i_omega_], ydot[i_omega_], dense_);
    return;
  }
  finder_.dropAfter(t);
  finder_.restart(t, y[i_omega_], ydot[i_omega_]);
}

}  // namespace rollerdyn
