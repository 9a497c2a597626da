#include "scene/NominalTorqueSource.h"

#include "scene/MotorModels.h"

namespace rollerdyn {

NominalTorqueSource nominalTorqueSource(const Scene& sc) {
  const SizingInputs& z = sc.sizing;
  if (z.motor_nominal_torque > 0) return NominalTorqueSource::SizingTorque;
  if (z.motor_nominal_power > 0 && z.motor_omega_nominal > 0) return NominalTorqueSource::SizingPower;
  if (isMachineLaw(sc.induction.model) &&
      sc.induction.catalogue.given() && sc.induction.catalogue.omega_nominal > 0)
    return NominalTorqueSource::Catalogue;
  if (z.motor_overload_ratio > 1) return NominalTorqueSource::OverloadRatio;
  return NominalTorqueSource::None;
}

}  // namespace rollerdyn
