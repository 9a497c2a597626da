#include "multibody/RollerLoadForce.h"

#include "physics/RollerLoads.h"

namespace rollerdyn {

double RollerLoadForce::horizontalForce(const SimTK::State& s, int j) const {
  const CartRig& c = carts_[j];
  // rollerHorizontalForce works in the cart's local axis x' = σ·x.
  return c.side * rollerHorizontalForce(loads_[j], c.side * c.v(s));
}

double RollerLoadForce::loadPower(const SimTK::State& s) const {
  double p = 0;
  for (size_t j = 0; j < carts_.size(); ++j) p -= horizontalForce(s, int(j)) * carts_[j].v(s);
  return p;
}

void RollerLoadForce::calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& body_forces,
                                SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector&) const {
  for (size_t j = 0; j < carts_.size(); ++j) {
    const CartRig& c = carts_[j];
    const Loads& L = loads_[j];
    const double total = L.roller_force_front + L.roller_force_rear;
    const double fx = horizontalForce(s, int(j));
    // Split the horizontal force between the rollers in proportion to F_j1 : F_j2; both act at
    // the same depth e, so only the total matters for the moment.
    const double share_front = total != 0.0 ? L.roller_force_front / total : 0.5;
    c.cart.applyForceToBodyPoint(s, c.rollerFront(geometry_),
                                 SimTK::Vec3(fx * share_front, L.roller_normal_front, 0), body_forces);
    c.cart.applyForceToBodyPoint(s, c.rollerRear(geometry_),
                                 SimTK::Vec3(fx * (1.0 - share_front), L.roller_normal_rear, 0),
                                 body_forces);
  }
}

}  // namespace rollerdyn
