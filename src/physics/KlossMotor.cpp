#include "physics/KlossMotor.h"

#include "scene/Scene.h"

namespace rollerdyn {

double klossRotorTorque(const KlossMotor& m, double omega_rotor) {
  const double s = 1.0 - omega_rotor / m.omega_sync;
  const double sk = m.critical_slip;
  return 2.0 * m.breakdown_torque * s * sk / (s * s + sk * sk);
}

double klossCrankTorque(const KlossMotor& m, double ratio, double efficiency, double omega1) {
  return klossRotorTorque(m, omega1 * ratio) * ratio * efficiency;
}

}  // namespace rollerdyn
