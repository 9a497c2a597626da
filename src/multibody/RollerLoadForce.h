// Technological loads of the compacting rollers on every cart (Loveikin, Pochka, Romasevych (2018) fig. 3: F_j1, F_j2
// horizontal, R_j1, R_j2 vertical), applied at the roller contacts so their moments load the
// guide rollers as in eq. (10). The horizontal direction follows loads.roller_force_direction
// (physics/RollerLoads.h). Each cart has its own loads (Scene::cartLoads). Built only when the
// scene has roller loads.
#pragma once

#include <vector>

#include "multibody/CartRig.h"

namespace rollerdyn {

class RollerLoadForce : public SimTK::Force::Custom::Implementation {
 public:
  // loads: one entry per cart.
  RollerLoadForce(std::vector<CartRig> carts, std::vector<Loads> loads, const CartGeometry& geometry)
      : carts_(std::move(carts)), loads_(std::move(loads)), geometry_(geometry) {}

  // Horizontal roller force on cart j along world x [N].
  double horizontalForce(const SimTK::State& s, int j) const;
  // Power the loads take out of the mechanism [W] (work done on the concrete).
  double loadPower(const SimTK::State& s) const;

  void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& body_forces,
                 SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector&) const override;
  SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }

 private:
  std::vector<CartRig> carts_;
  std::vector<Loads> loads_;  // per cart
  CartGeometry geometry_;
};

}  // namespace rollerdyn
