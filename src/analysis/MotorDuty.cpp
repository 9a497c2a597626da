#include "analysis/MotorDuty.h"

#include "analysis/DriveSizing.h"

namespace rollerdyn {

MotorDuty computeMotorDuty(const Scene&, const DriveSizing&, const StartUp*) { return MotorDuty{}; }

}  // namespace rollerdyn
