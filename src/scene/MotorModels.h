// What kind of torque law a motor.model is, where several places must treat the laws alike: the
// plausibility warnings, the keys without effect, the breakdown torque the scales read, the
// start-up's motor curve and the motor figure ask here, so a new law is classified once.
#pragma once

#include "scene/Scene.h"

namespace rollerdyn {

// Whether the law's torque follows the Kloss curve of motor.breakdown_torque and the critical slip
// (kloss, kloss_dynamic), rather than a machine of its own fitted to motor.catalogue or given as
// motor.circuit (circuit, park).
inline bool hasKlossCurve(MotorModel m) { return m == MotorModel::Kloss || m == MotorModel::KlossDynamic; }

}  // namespace rollerdyn
