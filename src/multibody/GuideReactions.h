// Normal forces of the two guide rollers of a cart from the reaction of its prismatic joint.
// The slider joint is what holds the cart on its guides: its reaction (vertical force F_y and
// moment M_z about the hinge B) is carried by two vertical contact forces, N_front at
// x' = p - b and N_rear at x' = p + b (Loveikin, Pochka, Romasevych (2018) fig. 3). N > 0 when the guide presses the
// roller downward, the sense of eq. (10):
//     F_y = -(N_front + N_rear),   M_z = -σ·[(p - b)·N_front + (p + b)·N_rear]
// solved with Eigen. With b = 0 the split is undetermined and the total is shared equally.
#pragma once

#include "Simbody.h"
#include "scene/Scene.h"

namespace rollerdyn {

struct GuideNormals {
  double front = 0;  // N_j1 [N]
  double rear = 0;   // N_j2 [N]
};

// reaction_on_cart: spatial force (moment, force) the slider joint exerts on the cart at B,
// in ground axes, as returned by SimbodyMatterSubsystem::calcMobilizerReactionForces.
GuideNormals solveGuideNormals(const SimTK::SpatialVec& reaction_on_cart, int side,
                               const CartGeometry& geometry);

}  // namespace rollerdyn
