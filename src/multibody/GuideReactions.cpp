#include "multibody/GuideReactions.h"

#include <Eigen/Dense>

namespace rollerdyn {

GuideNormals solveGuideNormals(const SimTK::SpatialVec& reaction_on_cart, int side,
                               const CartGeometry& g) {
  const double force_y = reaction_on_cart[1][1];
  const double moment_z = reaction_on_cart[0][2];
  if (g.b <= 0.0) return {-0.5 * force_y, -0.5 * force_y};
  Eigen::Matrix2d A;
  A << -1.0, -1.0, -side * (g.p - g.b), -side * (g.p + g.b);
  const Eigen::Vector2d n = A.partialPivLu().solve(Eigen::Vector2d(force_y, moment_z));
  return {n(0), n(1)};
}

}  // namespace rollerdyn
