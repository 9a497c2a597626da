#include "multibody/IntegratorFactory.h"

#include <stdexcept>

namespace rollerdyn {

const std::vector<std::string>& integratorNames() {
  static const std::vector<std::string> names = {
      "RungeKuttaMerson", "RungeKutta3", "RungeKuttaFeldberg", "RungeKutta2",
      "ExplicitEuler",    "Verlet",      "SemiExplicitEuler2", "CPodes"};
  return names;
}

std::unique_ptr<SimTK::Integrator> makeIntegrator(const std::string& name, const SimTK::System& system,
                                                  double accuracy, double constraint_tolerance) {
  std::unique_ptr<SimTK::Integrator> integ;
  if (name == "RungeKuttaMerson") integ.reset(new SimTK::RungeKuttaMersonIntegrator(system));
  else if (name == "RungeKutta3") integ.reset(new SimTK::RungeKutta3Integrator(system));
  else if (name == "RungeKuttaFeldberg") integ.reset(new SimTK::RungeKuttaFeldbergIntegrator(system));
  else if (name == "RungeKutta2") integ.reset(new SimTK::RungeKutta2Integrator(system));
  else if (name == "ExplicitEuler") integ.reset(new SimTK::ExplicitEulerIntegrator(system));
  else if (name == "Verlet") integ.reset(new SimTK::VerletIntegrator(system));
  else if (name == "SemiExplicitEuler2") integ.reset(new SimTK::SemiExplicitEuler2Integrator(system));
  else if (name == "CPodes") integ.reset(new SimTK::CPodesIntegrator(system, SimTK::CPodes::BDF, SimTK::CPodes::Newton));
  else {
    std::string list;
    for (const auto& n : integratorNames()) list += (list.empty() ? "" : ", ") + n;
    throw std::invalid_argument("unknown integrator '" + name + "'; expected one of: " + list);
  }
  integ->setAccuracy(accuracy);
  integ->setConstraintTolerance(constraint_tolerance);
  integ->setInternalStepLimit(1000000);
  return integ;
}

}  // namespace rollerdyn
