// One cart's share of the crank side's reduced inertia, the inertia its crank throw feels
// (Loveikin, Pochka, Romasevych (2018) eq. (9); distributed rods after Loveikin and Pochka (2007)
// eq. (9)):
//   J_j(θ) = m_B·x_B'(θ)² + m_rod·(x_S'² + y_S'²) + I_S·β'²     (the rod terms for distributed rods)
// with m_B the cart's mass with its rod share (Scene::cartMassWithRodShare). The reduced model sums
// it over the carts (J_n2); the crankshaft's torsional chain puts each on its own throw.
#pragma once

#include "physics/SliderCrank.h"
#include "scene/Scene.h"

namespace rollerdyn {

inline double cartReducedInertia(double m_B, const ConnectingRods& rods, const SliderCrankPose& p) {
  double J = m_B * p.dx_B * p.dx_B;
  if (rods.model == RodModel::Distributed)
    J += rods.mass * (p.dx_S * p.dx_S + p.dy_S * p.dy_S) + rods.inertia_com * p.dbeta * p.dbeta;
  return J;
}

}  // namespace rollerdyn
