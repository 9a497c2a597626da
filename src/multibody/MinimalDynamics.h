// Accelerations of the multibody model from its projected equations of motion (null-space
// method): with u = N·ν̇ and u̇ = N·ν̈ + Ṅ·ν̇ (MinimalCoordinates.h), premultiplying
//     M·u̇ + c = f + f_constraint
// by Nᵀ removes the constraint forces (Nᵀ·f_constraint = 0: N spans the null space of the
// velocity constraints, so ideal constraints do no work on it):
//     (Nᵀ·M·N)·ν̈ = -Nᵀ·r0,    r0 = M·(Ṅ·ν̇) + c - f.
// Simbody's O(n) operators form it: r0 by one inverse-dynamics pass
// (SimbodyMatterSubsystem::calcResidualForceIgnoringConstraints with u̇ = Ṅ·ν̇), M·N by one
// SimbodyMatterSubsystem::multiplyByM per column of N (at most two). Nᵀ·M·N is at most 2x2.
// No n-by-n or m-by-m matrix is formed; the cost per evaluation is linear in the carts.
//
// The residual with the full u̇, r = r0 + M·N·ν̈, is then the generalized constraint force on
// every mobility, from which the loop force at each cart's hinge B follows (see
// guideNormals), and the cart's free body gives the guide reaction: the inverse-dynamics pass
// that feeds the guide-friction law (GuideFriction.h) the same normal forces Simbody's
// constrained solve gives.
#pragma once

#include <Eigen/Core>

#include "Simbody.h"
#include "multibody/MinimalCoordinates.h"
#include "multibody/MultibodyModel.h"

namespace rollerdyn {

class MinimalDynamics {
 public:
  MinimalDynamics(const MultibodyModel& model, const SimTK::State& state);

  // Realizes `s` (q, u, z set, e.g. by MinimalCoordinates::apply) to Velocity, sums the applied
  // forces of every force element and solves the projected equations with the N and Ṅ·ν̇ of
  // `coords`.
  void evaluate(const SimTK::State& s, const MinimalCoordinates& coords);

  // After evaluate: ν̈ (crank acceleration first if free, then twist acceleration) [rad/s²].
  const Eigen::Vector2d& independentAccelerations() const { return nu_dot_; }
  // After evaluate: every u̇ [rad/s², m/s²].
  const SimTK::Vector& udot() const { return udot_; }
  // After evaluate: guide normal forces N_front, N_rear per cart [N], from the inverse-dynamics
  // pass (GuideReactions.h sign convention).
  SimTK::Vector guideNormals(const SimTK::State& s) const;

 private:
  const MultibodyModel& model_;
  Eigen::Vector2d nu_dot_ = Eigen::Vector2d::Zero();
  SimTK::Vector udot_, residual_, mn_[2];
  SimTK::Vector_<SimTK::SpatialVec> no_body_forces_;
  // Applied forces f of all force elements at the last evaluate (ground axes): body forces
  // [N·m, N] per mobilized body, particle forces [N], mobility forces [N·m or N] per u.
  SimTK::Vector_<SimTK::SpatialVec> f_body_;
  SimTK::Vector_<SimTK::Vec3> f_particle_;
  SimTK::Vector f_mobility_;
};

}  // namespace rollerdyn
