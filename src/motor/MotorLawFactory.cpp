#include "motor/MotorLawFactory.h"

#include <stdexcept>
#include <string>

#include "motor/CircuitLaw.h"
#include "motor/KlossDynamicLaw.h"
#include "motor/KlossLaw.h"
#include "motor/ParkLaw.h"

namespace rollerdyn {

std::unique_ptr<MotorLaw> makeMotorLaw(const Scene& scene) { return makeMotorLaw(scene, scene.induction.model); }

std::unique_ptr<MotorLaw> makeMotorLaw(const Scene& scene, MotorModel model) {
  switch (model) {
    case MotorModel::Kloss:
      return std::make_unique<KlossLaw>(scene.motor);
    case MotorModel::KlossDynamic: {
      const double te = scene.induction.torque_time_constant > 0
                            ? scene.induction.torque_time_constant
                            : KlossDynamicLaw::defaultTimeConstant(scene.motor, scene.induction.frequency);
      return std::make_unique<KlossDynamicLaw>(scene.motor, te);
    }
    case MotorModel::Circuit:
      return std::make_unique<CircuitLaw>(sceneMachine(scene));
    case MotorModel::Park:
      return std::make_unique<ParkLaw>(sceneMachine(scene));
  }
  throw std::logic_error("makeMotorLaw: unknown motor.model");
}

CatalogueFit fitSceneCatalogue(const Scene& scene, int cages) {
  const InductionMotor& im = scene.induction;
  return fitCatalogue(im.catalogue, {im.voltage, im.frequency, im.pole_pairs}, cages);
}

InductionMachineParameters sceneMachine(const Scene& scene) {
  const InductionMotor& im = scene.induction;
  if (im.circuit.given()) return InductionMachineParameters::fromScene(im);
  if (im.catalogue.given()) return fitSceneCatalogue(scene, im.catalogue.cages).machine;
  throw std::invalid_argument("the motor has neither an equivalent circuit (motor.circuit.*) nor catalogue data "
                              "(motor.catalogue.*)");
}

}  // namespace rollerdyn
