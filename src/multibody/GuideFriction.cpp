#include "multibody/GuideFriction.h"

#include <cmath>

#include "physics/RollerLoads.h"

namespace rollerdyn {

void GuideFriction::realizeTopology(SimTK::State& s) const {
  const SimTK::Vector zero(2 * int(carts_.size()), 0.0);
  if (lagged()) {
    z_start_ = forces_.allocateZ(s, zero);
  } else {
    // Changing the normal forces changes the friction, i.e. the Dynamics stage and above.
    normals_index_ = forces_.allocateDiscreteVariable(s, SimTK::Stage::Dynamics, new SimTK::Value<SimTK::Vector>(zero));
  }
}

SimTK::Vector GuideFriction::normalsInUse(const SimTK::State& s) const {
  if (lagged()) return forces_.getZ(s)(z_start_, 2 * int(carts_.size()));
  return SimTK::Value<SimTK::Vector>::downcast(forces_.getDiscreteVariable(s, normals_index_)).get();
}

void GuideFriction::setNormalsInUse(SimTK::State& s, const SimTK::Vector& normals) const {
  if (lagged())
    forces_.updZ(s)(z_start_, 2 * int(carts_.size())) = normals;
  else
    SimTK::Value<SimTK::Vector>::updDowncast(forces_.updDiscreteVariable(s, normals_index_)).upd() = normals;
}

double GuideFriction::frictionPerNormal(const SimTK::State& s, int j) const {
  return frictionPerNormal(j, carts_[j].v(s));
}

double GuideFriction::frictionPerNormal(int j, double v) const {
  const CartRig& c = carts_[j];
  return c.side * frictionDirection(loads_, c.side * v) * loads_.guide_friction;
}

void GuideFriction::setErrorWeights(SimTK::State& s, double cart_mass) const {
  if (!lagged()) return;
  const double unit_acceleration = 1.0;  // [m/s²]
  s.updZWeights(forces_.getMySubsystemIndex())(z_start_, 2 * int(carts_.size())) =
      loads_.guide_friction / (cart_mass * unit_acceleration);
}

double GuideFriction::frictionFrom(const SimTK::State& s, const SimTK::Vector& n, int j) const {
  return frictionPerNormal(s, j) * (std::abs(n[2 * j]) + std::abs(n[2 * j + 1]));
}

double GuideFriction::frictionForce(const SimTK::State& s, int j) const {
  return frictionFrom(s, normalsInUse(s), j);
}

double GuideFriction::dissipatedPower(const SimTK::State& s) const {
  const SimTK::Vector n = normalsInUse(s);
  double p = 0;
  for (size_t j = 0; j < carts_.size(); ++j) p -= frictionFrom(s, n, int(j)) * carts_[j].v(s);
  return p;
}

SimTK::Vector GuideFriction::dissipatedPowerGradient(const SimTK::State& s) const {
  // dissipatedPower = -Σ_j frictionFrom_j·v_j with frictionFrom_j = σ_j·dir_j·f·(|N̂_front,j| + |N̂_rear,j|):
  // each N̂ enters through its magnitude, so ∂/∂N̂ = -σ_j·dir_j·f·sign(N̂)·v_j.
  const SimTK::Vector n = normalsInUse(s);
  SimTK::Vector grad(n.size());
  for (size_t j = 0; j < carts_.size(); ++j) {
    const CartRig& c = carts_[j];
    const double v = c.v(s);
    const double per_unit_magnitude = -c.side * frictionDirection(loads_, c.side * v) * loads_.guide_friction * v;
    for (int k : {2 * int(j), 2 * int(j) + 1}) grad[k] = per_unit_magnitude * double((n[k] > 0) - (n[k] < 0));
  }
  return grad;
}

SimTK::Vector GuideFriction::currentNormals(const SimTK::State& s) const {
  SimTK::Vector_<SimTK::SpatialVec> reactions;
  matter_.calcMobilizerReactionForces(s, reactions);
  SimTK::Vector n(2 * int(carts_.size()));
  for (size_t j = 0; j < carts_.size(); ++j) {
    const GuideNormals g =
        solveGuideNormals(reactions[carts_[j].cart.getMobilizedBodyIndex()], carts_[j].side, geometry_);
    n[2 * j] = g.front;
    n[2 * j + 1] = g.rear;
  }
  return n;
}

void GuideFriction::realizeAcceleration(const SimTK::State& s) const {
  if (lagged()) calcRates(s, currentNormals(s), forces_.updZDot(s));
}

void GuideFriction::calcRates(const SimTK::State& s, const SimTK::Vector& normals_now,
                              SimTK::Vector& zdot) const {
  if (!lagged()) return;
  const int m = 2 * int(carts_.size());
  zdot(z_start_, m) = (normals_now - normalsInUse(s)) / loads_.guide_friction_lag;
}

void GuideFriction::addCartForce(const SimTK::State& s, const SimTK::Vector& n, int j,
                                 SimTK::Vector_<SimTK::SpatialVec>& body_forces) const {
  const CartRig& c = carts_[j];
  const double per_normal = frictionPerNormal(s, j);  // world x
  c.cart.applyForceToBodyPoint(s, c.guideFront(geometry_), SimTK::Vec3(per_normal * std::abs(n[2 * j]), 0, 0),
                               body_forces);
  c.cart.applyForceToBodyPoint(s, c.guideRear(geometry_), SimTK::Vec3(per_normal * std::abs(n[2 * j + 1]), 0, 0),
                               body_forces);
}

void GuideFriction::calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& body_forces,
                              SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector&) const {
  const SimTK::Vector n = normalsInUse(s);
  for (size_t j = 0; j < carts_.size(); ++j) addCartForce(s, n, int(j), body_forces);
}

}  // namespace rollerdyn
