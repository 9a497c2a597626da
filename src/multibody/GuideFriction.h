// Friction of the guide rollers, f·(|N_front| + |N_rear|) per cart, from the ACTUAL guide
// reactions of the multibody model (not the quasi-static formula of Loveikin, Pochka, Romasevych (2018) eq. (14)-(25)).
//
// The normal forces are constraint reactions, which Simbody computes only after the applied
// forces are known, and friction is an applied force: an implicit loop. We close it with two
// auxiliary state variables per cart, N̂, that follow the reactions N of the slider joint:
//     dN̂/dt = (N - N̂) / τ_N                     (τ_N = loads.guide_friction.normal_force_lag)
// and friction uses N̂. The friction law is then a pure function of the state, so the
// integrator's error control covers it and results converge as the accuracy is tightened.
// Physically it is a guide with a little compliance: the friction force trails the normal
// force by about τ_N (2 ms against a crank period of ~0.6 s), which changes it by
// ~f·τ_N·dN/dt, a fraction of a newton.
//
// Rejected alternatives, measured on model/balanced-4cart.yaml: friction from the reactions of
// the last accepted step (an auto-update discrete variable) left a crank-speed error floor of
// ~2e-6 that no accuracy setting removed, because Simbody's Runge-Kutta integrators reuse the
// start-of-step derivative computed before the update, and it tripled the cost of tight runs;
// solving friction and reactions together exactly needs a second constrained solve per
// evaluation (twice the cost).
//
// Friction acts at the guide contacts (d/2 above the roller axles) and opposes the cart's
// velocity (physics/RollerLoads.h). Built only when loads.guide_friction.coefficient > 0.
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

  // Friction force on cart j along world x [N].
  double frictionForce(const SimTK::State& s, int j) const;
  // Power dissipated by guide friction [W] (≥ 0).
  double dissipatedPower(const SimTK::State& s) const;
  // ∂(dissipated power)/∂N̂ [W/N] for each normal-force state (N_front, N_rear per cart): how
  // the friction-dissipation integral's rate depends on N̂, for the Newton matrix of an
  // integrator that carries that integral as a state. State realized to Velocity.
  SimTK::Vector dissipatedPowerGradient(const SimTK::State& s) const;
  // The normal forces N̂ the friction law uses (state variables): N_front, N_rear per cart.
  SimTK::Vector frictionNormals(const SimTK::State& s) const;
  // Set N̂ (used at t = 0 to start from the reactions themselves).
  void setFrictionNormals(SimTK::State& s, const SimTK::Vector& normals) const;
  // Error weights of N̂ for the integrator (state realized to Model stage). An error δ in N̂
  // matters only as a friction error f·δ; Simbody counts 1 m/s as a unit change of a cart's
  // speed, so one unit of N̂ is the error whose friction would change the speed of a cart of
  // mass m_cart by 1 m/s within 1 s: weight = f / (m_cart·1 m/s²). With the default weight 1
  // the integrator resolved N̂'s millisecond transients to full accuracy: 4x the steps on
  // balanced-4cart for no visible change of the motion (crank-speed error 1e-8 either way).
  void setErrorWeights(SimTK::State& s, double cart_mass) const;
  // Guide normal forces N from the joint reactions of a state realized to Acceleration.
  SimTK::Vector currentNormals(const SimTK::State& s) const;

  void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& body_forces,
                 SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector&) const override;
  SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }
  void realizeTopology(SimTK::State& s) const override;
  void realizeAcceleration(const SimTK::State& s) const override;
  // dN̂/dt = (N - N̂)/τ_N for the guide normal forces `normals_now` (N), written into zdot
  // (indexed like the force subsystem's z).
  void calcRates(const SimTK::State& s, const SimTK::Vector& normals_now, SimTK::Vector& zdot) const;

 private:
  // Friction force along world x on cart j for the normal forces n.
  double frictionFrom(const SimTK::State& s, const SimTK::Vector& n, int j) const;
  const SimTK::GeneralForceSubsystem& forces_;
  const SimTK::SimbodyMatterSubsystem& matter_;
  std::vector<CartRig> carts_;
  Loads loads_;
  CartGeometry geometry_;
  mutable SimTK::ZIndex z_start_;
};

}  // namespace rollerdyn
