// Where the motor's nominal torque M_n comes from, decided once from the scene: the sizing
// (DriveSizing.h: heating, the report's rated point) reads M_n from it, and the keys-without-effect
// rule reads it to know whether motor.overload_ratio is what gives M_n.
#pragma once

#include "scene/Scene.h"

namespace rollerdyn {

enum class NominalTorqueSource {
  SizingTorque,   // sizing.motor_nominal_torque
  SizingPower,    // P_n/ω_n from sizing.motor_nominal_power and motor.omega_nominal
  Catalogue,      // P_n/ω_n of motor.catalogue, for a law fitted to it (motor.model circuit | park)
  OverloadRatio,  // M_kr/λ from motor.breakdown_torque and motor.overload_ratio
  None            // not given
};

// The first of the sources above the scene gives, in that order.
NominalTorqueSource nominalTorqueSource(const Scene& scene);

}  // namespace rollerdyn
