#include "physics/IntegrationScales.h"

#include <algorithm>
#include <cmath>

namespace rollerdyn {

IntegrationScales integrationScales(const Scene& sc, double prescribed_crank_speed, double breakdown_torque) {
  IntegrationScales k;
  k.cvode_rtol = kAccuracyToCvodeTolerance * sc.simulation.accuracy;
  k.angle = 1.0;
  k.speed = std::isfinite(prescribed_crank_speed) ? std::max(std::abs(prescribed_crank_speed), 1.0)
            : sc.motor.enabled                    ? sc.motor.omega_sync / sc.reducer.ratio
                                                  : std::max(std::abs(sc.initial.crank_speed), 1.0);
  k.torque = std::max({breakdown_torque * sc.reducer.ratio * sc.reducer.efficiency,
                       sc.rollerForceSum() * std::max(sc.crank.radius, sc.hasCamDrive() ? sc.cam.stroke : 0.0), 1.0});
  k.max_step = sc.hasCamDrive() ? (M_PI / 6.0) / k.speed / 8.0 : 0.0;
  k.twist = k.twist_rate = 0.0;
  if (sc.coupling.type == CouplingType::Elastic && sc.coupling.stiffness > 0) {
    k.twist = k.torque / sc.coupling.stiffness;
    k.twist_rate = k.twist * std::sqrt(sc.coupling.stiffness / std::max(sc.motorSideInertia(), 1e-300));
  }
  return k;
}

}  // namespace rollerdyn
