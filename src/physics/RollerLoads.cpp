#include "physics/RollerLoads.h"

#include <cmath>

#include "scene/Scene.h"

namespace rollerdyn {

double smoothSign(double v, double v_s) { return std::tanh(v / v_s); }

double rollerHorizontalForce(const Loads& loads, double v_local) {
  const double total = loads.roller_force_front + loads.roller_force_rear;
  if (loads.roller_force_direction == RollerForceDirection::AsPrinted) return total;
  return -total * smoothSign(v_local, loads.velocity_smoothing);
}

double frictionDirection(const Loads& loads, double v_local) {
  return -smoothSign(v_local, loads.velocity_smoothing);
}

}  // namespace rollerdyn
