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
// every mobility, from which the loop force at each cart's hinge B follows (loopForce), and the
// cart's free body gives the guide reaction: the inverse-dynamics pass that gives the guide
// normal forces (and every reaction column, MinimalReactions.h) Simbody's constrained solve
// gives.
//
// Guide friction with the algebraic normal force (GuideFriction.h): every quantity above is
// linear in the friction forces, so the pass gives each cart's normal forces as an affine
// function of the crank acceleration and of its own friction, and the crank acceleration as an
// affine function of the frictions; physics/GuideFrictionLoop.h solves that loop directly.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "Simbody.h"
#include "multibody/GuideReactions.h"
#include "multibody/MinimalCoordinates.h"
#include "multibody/MultibodyModel.h"
#include "physics/GuideFrictionLoop.h"

namespace rollerdyn {

class MinimalDynamics {
 public:
  MinimalDynamics(const MultibodyModel& model, const SimTK::State& state);

  // Realizes `s` (q, u, z set, e.g. by MinimalCoordinates::apply) to Velocity, sums the applied
  // forces of every force element and solves the projected equations with the N and Ṅ·ν̇ of
  // `coords`. With the algebraic guide-friction law it solves the friction loop too and keeps
  // its normal forces in `s` (GuideFriction::setNormalsInUse). False when that loop has no
  // solution (loopFailure() says why; the accelerations are then those without friction).
  bool evaluate(SimTK::State& s, const MinimalCoordinates& coords);
  // The friction loop's solution at `s` whatever the scene's law (lagged: the values its
  // normal-force states relax to, used to start them at t = 0). Leaves the evaluation as
  // evaluate() would with the algebraic law, without writing into `s`.
  bool evaluateWithLoop(SimTK::State& s, const MinimalCoordinates& coords);

  // After evaluate: ν̈ (crank acceleration first if free, then twist acceleration) [rad/s²].
  const Eigen::Vector2d& independentAccelerations() const { return nu_dot_; }
  // After evaluate: every u̇ [rad/s², m/s²].
  const SimTK::Vector& udot() const { return udot_; }
  // After evaluate: the applied body forces of all force elements (ground axes, about each
  // body's origin) [N·m, N].
  const SimTK::Vector_<SimTK::SpatialVec>& appliedBodyForces() const { return f_body_; }
  // After evaluate: guide normal forces N_front, N_rear per cart [N], from the inverse-dynamics
  // pass (GuideReactions.h sign convention).
  SimTK::Vector guideNormals(const SimTK::State& s) const;
  // After evaluate: the force the loop exerts on cart j at its hinge B, ground x and y [N] (the
  // rod's, or the cam's, force on the cart).
  SimTK::Vec2 loopForce(const SimTK::State& s, int j) const;
  // After a failed evaluate: what the friction loop could not solve, and its details.
  const GuideLoopResult& loopResult() const { return loop_; }

 private:
  bool evaluateImpl(SimTK::State& s, const MinimalCoordinates& coords, bool solve_loop, bool keep_normals);
  // The projected equations without the friction loop: ν̈, u̇ and the constraint forces, and the
  // inverse of their 1x1 or 2x2 matrix (A_inv_).
  void solveProjected(SimTK::State& s, const MinimalCoordinates& coords, bool include_friction);
  // Realizes s to Velocity and sums the applied forces f; the residual r0 = M·(Ṅ·ν̇) + c - f at
  // ν̈ = 0 and the products M·N's columns.
  void residualAtBias(SimTK::State& s, const MinimalCoordinates& coords, bool include_friction);
  // ν̈ from Nᵀ·M·N·ν̈ = -Nᵀ·r0 (1x1 or 2x2; r0 = residual_, viewed), and that matrix's inverse
  // into A_inv_.
  void solveIndependentAccelerations(const MinimalCoordinates& coords, const Eigen::Map<Eigen::VectorXd>& residual);
  // Each cart's normal forces as affine functions of ε and of its friction, for the loop.
  void setUpFrictionLoop(const SimTK::State& s, const MinimalCoordinates& coords, double eps0);
  // The loop's frictions into the accelerations, constraint forces and applied forces.
  void applyLoopFriction(const MinimalCoordinates& coords);
  // Fills each cart's r_AB from the state's crank angle and cart positions (no Simbody accessor:
  // the crank turns about ground z, the carts slide along ground x with their origin at B).
  void placeLoops(const SimTK::State& s);
  // Cart j's guide normals for a loop-force x component Fx, rod-pin constraint force r_rod,
  // cart acceleration a and applied spatial force on the cart: linear in all four (placeLoops
  // first).
  GuideNormals cartNormals(int j, double Fx, double r_rod, double a, const SimTK::SpatialVec& applied) const;
  double loopForceY(int j, double Fx, double r_rod) const;

  // What the per-cart passes need, read once from the model (indices, constant mass properties)
  // or per evaluation (r_AB).
  struct CartData {
    int q_cart = 0, u_cart = 0, u_rod = -1;  // rod: distributed rods only
    SimTK::MobilizedBodyIndex body;
    int side = 1;
    bool cam = false, massless_rod = false;
    double mass = 0;
    SimTK::Vec3 p_com{0};        // centre of mass from B (cart frame = ground axes)
    SimTK::Vec3 p_pin{0};        // crank pin A in the crankshaft frame
    SimTK::Vec3 r_AB{0};         // A -> B in ground, this evaluation
  };
  // Cart c's indices and constant mass properties in s.
  static CartData cartDataOf(const CartRig& c, const SimTK::State& s);

  const MultibodyModel& model_;
  const int k_crank_;  // column of N for the crank speed, -1 when prescribed
  int q_crank_ = 0;
  std::vector<CartData> carts_;
  Eigen::Vector2d nu_dot_ = Eigen::Vector2d::Zero();
  Eigen::Matrix2d A_inv_ = Eigen::Matrix2d::Zero();  // inverse of the projected mass matrix Nᵀ·M·N
  SimTK::Vector udot_, residual_, mn_[2];
  SimTK::Vector_<SimTK::SpatialVec> no_body_forces_;
  // Applied forces f of all force elements at the last evaluate (ground axes): body forces
  // [N·m, N] per mobilized body, particle forces [N], mobility forces [N·m or N] per u.
  SimTK::Vector_<SimTK::SpatialVec> f_body_;
  SimTK::Vector_<SimTK::Vec3> f_particle_;
  SimTK::Vector f_mobility_;
  // Friction loop (algebraic law): per-cart terms, solution.
  std::vector<GuideLoopCart> loop_carts_;
  std::vector<double> loop_friction_;
  SimTK::Vector loop_normals_;
  GuideLoopResult loop_;
};

}  // namespace rollerdyn
