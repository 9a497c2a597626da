// Friction of the guide rollers, f·(|N_front| + |N_rear|) per cart, from the ACTUAL guide
// reactions of the multibody model (not the quasi-static formula of seed 000 eq. (14)-(25)).
//
// The normal forces are constraint reactions, which Simbody computes only after the applied
// forces are known, and friction is an applied force: an implicit loop. We close it with a
// one-step lag: the normal forces are kept in an auto-update discrete variable whose update
// value is computed from the joint reactions at every acceleration realization; the integrator
// swaps it in when a step is accepted, so within a step the friction law is a smooth function
// of the state and its error is O(h·dN/dt·f), far below the integrator tolerance at f ~ 0.01.
// The energy audit integrates the friction power actually applied, so it stays exact.
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

  // Friction force on cart j along world x, from the lagged normal forces [N].
  double frictionForce(const SimTK::State& s, int j) const;
  // Power dissipated by guide friction [W] (≥ 0).
  double dissipatedPower(const SimTK::State& s) const;
  // Normal forces used by the friction law now (the lagged values).
  const SimTK::Vector& laggedNormals(const SimTK::State& s) const;
  // Replace the lagged normal forces (used once at t = 0 to start from consistent values).
  void setLaggedNormals(SimTK::State& s, const SimTK::Vector& normals) const;
  // Guide normal forces from the joint reactions of a state realized to Acceleration.
  SimTK::Vector currentNormals(const SimTK::State& s) const;

  void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& body_forces,
                 SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector&) const override;
  SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }
  void realizeTopology(SimTK::State& s) const override;
  void realizeAcceleration(const SimTK::State& s) const override;

 private:
  const SimTK::GeneralForceSubsystem& forces_;
  const SimTK::SimbodyMatterSubsystem& matter_;
  std::vector<CartRig> carts_;
  Loads loads_;
  CartGeometry geometry_;
  mutable SimTK::DiscreteVariableIndex normals_index_;
};

}  // namespace rollerdyn
