#include "analysis/CvodeSupplyEvents.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "physics/IntegrationScales.h"

namespace rollerdyn {

CvodeSupplyEvents::CvodeSupplyEvents(Model model)
    : model_(std::move(model)), active_(model_.supply && !model_.supply->constant()) {}

void CvodeSupplyEvents::install(OdeProblem& p) {
  p.root = [this](double, const double* y) { return model_.rotor_speed(y) - trigger_speed_; };
}

void CvodeSupplyEvents::arm(CvodeIntegrator& integ) {
  if (!active_) return;
  const SupplyPhase phase = model_.phase();
  const double te = std::min(model_.supply->nextEventTime(phase), model_.t_end);
  if (te > integ.time()) integ.setStopTime(te);
  trigger_speed_ = model_.supply->triggerSpeed(phase);
  integ.enableRoot(!std::isnan(trigger_speed_));
}

bool CvodeSupplyEvents::advanceTo(CvodeIntegrator& integ, double t_out) {
  while (true) {
    if (!integ.advanceTo(t_out)) return false;
    // CVODE returns at the stop time, or at the output time when it is the stop time: either way
    // the events due there are applied here.
    applyDue(integ);
    if (reachedOutputTime(integ.time(), t_out)) return true;
  }
}

void CvodeSupplyEvents::applyDue(CvodeIntegrator& integ) {
  if (!active_) return;
  Eigen::VectorXd y = integ.y();
  if (!model_.apply(integ.time(), y, integ.rootFound())) return;
  integ.restart(integ.time(), y);
  arm(integ);
}

}  // namespace rollerdyn
