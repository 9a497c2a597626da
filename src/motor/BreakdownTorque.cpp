#include "motor/BreakdownTorque.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "motor/SharedMotorLaw.h"
#include "scene/MotorModels.h"

namespace rollerdyn {

SteadyTorquePeak largestSteadyTorquePoint(const MotorLaw& law, const SupplyState& supply) {
  const double w_top = law.synchronousSpeed() * supply.frequency;
  constexpr int kScan = 400;
  int best = 0;
  double best_M = -std::numeric_limits<double>::infinity();
  for (int i = 0; i <= kScan; ++i) {
    const double M = law.steadyTorque(supply, w_top * i / kScan);
    if (M > best_M) best_M = M, best = i;
  }
  // Golden-section search on the bracket around the best scan point.
  double a = w_top * std::max(0, best - 1) / kScan, b = w_top * std::min(kScan, best + 1) / kScan;
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double c = b - g * (b - a), d = a + g * (b - a);
  double Mc = law.steadyTorque(supply, c), Md = law.steadyTorque(supply, d);
  for (int it = 0; it < 80 && b - a > 1e-12 * w_top; ++it) {
    if (Mc > Md) {
      b = d, d = c, Md = Mc, c = b - g * (b - a), Mc = law.steadyTorque(supply, c);
    } else {
      a = c, c = d, Mc = Md, d = a + g * (b - a), Md = law.steadyTorque(supply, d);
    }
  }
  if (best_M >= Mc && best_M >= Md) return {w_top * best / kScan, best_M};
  return Mc >= Md ? SteadyTorquePeak{c, Mc} : SteadyTorquePeak{d, Md};
}

double largestSteadyTorque(const MotorLaw& law, const SupplyState& supply) {
  return largestSteadyTorquePoint(law, supply).torque;
}

double motorBreakdownTorque(const Scene& sc, const MotorLaw* law) {
  const bool kloss = hasKlossCurve(sc.induction.model);
  if (kloss || !law) return sc.motor.breakdown_torque;
  return largestSteadyTorque(*law, SupplyState{});
}

double motorBreakdownTorque(const Scene& sc) {
  const bool kloss = hasKlossCurve(sc.induction.model);
  if (kloss || !sc.motor.enabled) return sc.motor.breakdown_torque;
  try {
    return motorBreakdownTorque(sc, sharedMotorLaw(sc).get());
  } catch (const std::exception&) {
    return sc.motor.breakdown_torque;  // no law for this scene: the run fails on its own, not here
  }
}

}  // namespace rollerdyn
