// Friction of the guide rollers, f·(|N_front| + |N_rear|) per cart, from the ACTUAL guide
// reactions of the multibody model (not the quasi-static formula of Loveikin, Pochka, Romasevych
// (2018) eq. (14)-(25)), acting at the guide contacts (d/2 above the roller axles) against the
// cart's velocity (physics/RollerLoads.h). Built only when loads.guide_friction.coefficient > 0.
//
// The normal forces are constraint reactions, which depend on the friction: an implicit loop.
// loads.guide_friction.normal_force says how it is closed (docs/friction-and-reactions.md):
//
//   algebraic (minimal formulation; the default there): the loop is solved exactly at every
//     evaluation by the O(n) inverse-dynamics pass of the minimal formulation
//     (MinimalDynamics.h, physics/GuideFrictionLoop.h, the law the reduced model's kinetostatic
//     normals share). The normal forces it found are kept in a discrete variable of the state
//     (normalsInUse), from which this element applies the friction, so Simbody's own constrained
//     solve at a self-check row sees the same friction (and must return the same reactions).
//
//   lagged (both formulations): two auxiliary states per cart, N̂, follow the reactions N,
//         dN̂/dt = (N - N̂) / τ_N                 (τ_N = loads.guide_friction.normal_force_lag)
//     and the friction uses N̂: a pure function of the state, so the constrained formulation's
//     integrators can carry it. Physically a guide with a little compliance: the friction trails
//     the reaction by about τ_N. That is NOT a small error where the reactions change fast:
//     measured on balanced-4cart (10 s) at r/l = 0.95 (rods.length = 0.2105 m), the applied
//     friction differs from f·(|N_front| + |N_rear|) of the same instant by up to 348 N, with
//     friction forces up to 2682 N (13 %; 36 N with τ_N = 0.2 ms); at the shipped r/l = 0.25 by
//     up to 2.9 N of 143 N (2 %). The lag states also cost steps: every cart reversal flips the friction within
//     ~v_s/a and N̂ relaxes within τ_N, a transient the error control resolves (docs/friction-and-
//     reactions.md, "Cost"). Kept because the constrained formulation has no other way to close
//     the loop, and as the reference of the earlier releases.
//
// Rejected alternatives, measured on model/balanced-4cart.yaml: friction from the reactions of
// the last accepted step (an auto-update discrete variable) left a crank-speed error floor of
// ~2e-6 that no accuracy setting removed, because Simbody's Runge-Kutta integrators reuse the
// start-of-step derivative computed before the update, and it tripled the cost of tight runs;
// in the constrained formulation, solving friction and reactions together exactly needs a second
// constrained solve per evaluation (twice the cost).
#pragma once

#include <vector>

#include "multibody/CartRig.h"
#include "multibody/GuideReactions.h"

namespace rollerdyn {

class GuideFriction : public SimTK::Force::Custom::Implementation {
 public:
  GuideFriction(const SimTK::GeneralForceSubsystem& forces, const SimTK::SimbodyMatterSubsystem& matter,
                std::vector<CartRig> carts, const Loads& loads, const CartGeometry& geometry)
      : forces_(forces), matter_(matter), carts_(std::move(carts)), loads_(loads), geometry_(geometry) {}

  bool lagged() const { return loads_.guide_normal_force == GuideNormalForce::Lagged; }

  // Friction force on cart j along world x [N].
  double frictionForce(const SimTK::State& s, int j) const;
  // Friction along world x per unit of |N_front| + |N_rear| on cart j: σ·f·φ_f(v') [-]
  // (physics/RollerLoads.h). State realized to Velocity.
  double frictionPerNormal(const SimTK::State& s, int j) const;
  // The same for cart j moving at v [m/s] (world x).
  double frictionPerNormal(int j, double v) const;
  // Power dissipated by guide friction [W] (≥ 0).
  double dissipatedPower(const SimTK::State& s) const;
  // Lagged law: ∂(dissipated power)/∂N̂ [W/N] for each normal-force state (N_front, N_rear per
  // cart), for the Newton matrix of an integrator that carries the friction-dissipation integral
  // as a state. State realized to Velocity.
  SimTK::Vector dissipatedPowerGradient(const SimTK::State& s) const;
  // The normal forces the friction uses: N_front, N_rear per cart [N] (lagged: the states N̂;
  // algebraic: the loop's solution kept in the state).
  SimTK::Vector normalsInUse(const SimTK::State& s) const;
  // Sets them (lagged: N̂, e.g. at t = 0 the loop's solution; algebraic: the loop's solution of
  // this state). Invalidates the Dynamics stage.
  void setNormalsInUse(SimTK::State& s, const SimTK::Vector& normals) const;
  // Error weights of N̂ for the integrator (lagged law; state realized to Model stage). An error
  // δ in N̂ matters only as a friction error f·δ; Simbody counts 1 m/s as a unit change of a
  // cart's speed, so one unit of N̂ is the error whose friction would change the speed of a cart
  // of mass m_cart by 1 m/s within 1 s: weight = f / (m_cart·1 m/s²). With the default weight 1
  // the integrator resolved N̂'s millisecond transients to full accuracy: 4x the steps on
  // balanced-4cart for no visible change of the motion (crank-speed error 1e-8 either way).
  void setErrorWeights(SimTK::State& s, double cart_mass) const;
  // Guide normal forces N from the joint reactions of a state realized to Acceleration.
  SimTK::Vector currentNormals(const SimTK::State& s) const;
  // Adds cart j's friction for the normal forces n (N_front, N_rear per cart) to body_forces.
  void addCartForce(const SimTK::State& s, const SimTK::Vector& n, int j,
                    SimTK::Vector_<SimTK::SpatialVec>& body_forces) const;

  void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& body_forces,
                 SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector&) const override;
  SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }
  void realizeTopology(SimTK::State& s) const override;
  void realizeAcceleration(const SimTK::State& s) const override;
  // Lagged law: dN̂/dt = (N - N̂)/τ_N for the guide normal forces `normals_now` (N), written into
  // zdot (indexed like the force subsystem's z). Nothing for the algebraic law.
  void calcRates(const SimTK::State& s, const SimTK::Vector& normals_now, SimTK::Vector& zdot) const;

 private:
  // Friction force along world x on cart j for the normal forces n.
  double frictionFrom(const SimTK::State& s, const SimTK::Vector& n, int j) const;
  const SimTK::GeneralForceSubsystem& forces_;
  const SimTK::SimbodyMatterSubsystem& matter_;
  std::vector<CartRig> carts_;
  Loads loads_;
  CartGeometry geometry_;
  mutable SimTK::ZIndex z_start_;                       // lagged: N̂
  mutable SimTK::DiscreteVariableIndex normals_index_;  // algebraic: the loop's normal forces
};

}  // namespace rollerdyn
