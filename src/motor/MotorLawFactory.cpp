#include "motor/MotorLawFactory.h"

#include <stdexcept>
#include <string>

#include "motor/KlossDynamicLaw.h"
#include "motor/KlossLaw.h"

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
    case MotorModel::Park:
      break;
  }
  throw std::invalid_argument(std::string("motor.model ") + toString(model) + ": not available yet in this build");
}

}  // namespace rollerdyn
