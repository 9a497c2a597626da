#include "multibody/GuideFriction.h"

#include <cmath>

#include "physics/RollerLoads.h"

namespace rollerdyn {

void GuideFriction::realizeTopology(SimTK::State& s) const {
  normals_index_ = forces_.allocateAutoUpdateDiscreteVariable(
      s, SimTK::Stage::Dynamics, new SimTK::Value<SimTK::Vector>(SimTK::Vector(2 * int(carts_.size()), 0.0)),
      SimTK::Stage::Acceleration);
}

const SimTK::Vector& GuideFriction::laggedNormals(const SimTK::State& s) const {
  return SimTK::Value<SimTK::Vector>::downcast(forces_.getDiscreteVariable(s, normals_index_));
}

void GuideFriction::setLaggedNormals(SimTK::State& s, const SimTK::Vector& normals) const {
  SimTK::Value<SimTK::Vector>::updDowncast(forces_.updDiscreteVariable(s, normals_index_)) = normals;
}

double GuideFriction::frictionForce(const SimTK::State& s, int j) const {
  const CartRig& c = carts_[j];
  const SimTK::Vector& n = laggedNormals(s);
  const double magnitude = loads_.guide_friction * (std::abs(n[2 * j]) + std::abs(n[2 * j + 1]));
  return c.side * frictionDirection(loads_, c.side * c.v(s)) * magnitude;
}

double GuideFriction::dissipatedPower(const SimTK::State& s) const {
  double p = 0;
  for (size_t j = 0; j < carts_.size(); ++j) p -= frictionForce(s, int(j)) * carts_[j].v(s);
  return p;
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
  SimTK::Value<SimTK::Vector>::updDowncast(forces_.updDiscreteVarUpdateValue(s, normals_index_)) =
      currentNormals(s);
  forces_.markDiscreteVarUpdateValueRealized(s, normals_index_);
}

void GuideFriction::calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& body_forces,
                              SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector&) const {
  const SimTK::Vector& n = laggedNormals(s);
  for (size_t j = 0; j < carts_.size(); ++j) {
    const CartRig& c = carts_[j];
    const double dir = c.side * frictionDirection(loads_, c.side * c.v(s));  // world-x sign
    const double f = loads_.guide_friction;
    c.cart.applyForceToBodyPoint(s, c.guideFront(geometry_),
                                 SimTK::Vec3(dir * f * std::abs(n[2 * j]), 0, 0), body_forces);
    c.cart.applyForceToBodyPoint(s, c.guideRear(geometry_),
                                 SimTK::Vec3(dir * f * std::abs(n[2 * j + 1]), 0, 0), body_forces);
  }
}

}  // namespace rollerdyn
