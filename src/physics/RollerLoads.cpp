#include "physics/RollerLoads.h"

#include <cmath>

#include "scene/Scene.h"

namespace rollerdyn {

double smoothSign(double v, double v_s) { return std::tanh(v / v_s); }

double rollerHorizontalForce(const Loads& loads, double v_local) {
  const double total = loads.roller_force_front + loads.roller_force_rear;
  const double sign_v = smoothSign(v_local, loads.velocity_smoothing);
  const double rolling = loads.rolling_resistance * (loads.roller_normal_front + loads.roller_normal_rear);
  if (loads.roller_force_direction == RollerForceDirection::AsPrinted) return total - rolling * sign_v;
  return -(total + rolling) * sign_v;
}

double rollerLoadPower(const Loads& loads, double v_local) {
  return -rollerHorizontalForce(loads, v_local) * v_local;
}

double frictionDirection(const Loads& loads, double v_local) {
  return -smoothSign(v_local, loads.velocity_smoothing);
}

}  // namespace rollerdyn
