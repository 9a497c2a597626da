#include "physics/SelfLocking.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "scene/Scene.h"

namespace rollerdyn {

LockingMargins lockingMargins(const Scene& scene) {
  LockingMargins m;
  if (scene.hasCamDrive()) return m;
  const double r = scene.crank.radius, l = scene.rods.length;
  if (!(r > 0.0) || !(l > r)) return m;
  m.applicable = true;
  m.beta_max = std::asin(r / l);  // Loveikin, Pochka, Romasevych (2018) eq. (31) at sin θ = 1
  m.transmission_angle_min = 0.5 * M_PI - m.beta_max;
  m.rod_force_factor = 1.0 / std::cos(m.beta_max);
  const CartGeometry& g = scene.carts.geometry;
  const double f = scene.loads.guide_friction;
  if (f > 0.0) {
    const double t = std::tan(m.beta_max);
    const double tipping = g.b > 0.0 ? (std::abs(g.p) * t + 0.5 * g.d) / g.b : std::numeric_limits<double>::infinity();
    m.self_locking_index = f * std::max(t, tipping);
  }
  m.friction_amplification = m.self_locking_index < 1.0 ? 1.0 / (1.0 - m.self_locking_index)
                                                         : std::numeric_limits<double>::infinity();
  return m;
}

}  // namespace rollerdyn
