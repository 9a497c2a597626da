#include "multibody/MinimalReactions.h"

#include "multibody/GuideFriction.h"
#include "multibody/GuideReactions.h"

namespace rollerdyn {
namespace {

// Acceleration of body b's centre of mass in ground from its spatial acceleration A_GB (about
// the body origin): a_origin + α × r + ω × (ω × r), r the origin -> centre of mass in ground.
SimTK::Vec3 centreOfMassAcceleration(const SimTK::State& s, const SimTK::MobilizedBody& b,
                                     const SimTK::SpatialVec& A_GB) {
  const SimTK::Vec3 r = b.getBodyTransform(s).R() * b.getBodyMassCenterStation(s);
  const SimTK::Vec3 w = b.getBodyAngularVelocity(s);
  return A_GB[1] + SimTK::cross(A_GB[0], r) + SimTK::cross(w, SimTK::cross(w, r));
}

}  // namespace

MinimalReactions::MinimalReactions(const MultibodyModel& model, const SimTK::State&) : model_(model) {}

SimTK::Vec3 MinimalReactions::netForce(const SimTK::State& s, const MinimalDynamics& dyn,
                                       const SimTK::MobilizedBody& b) const {
  const SimTK::MobilizedBodyIndex i = b.getMobilizedBodyIndex();
  return b.getBodyMass(s) * centreOfMassAcceleration(s, b, body_accelerations_[i]) - dyn.appliedBodyForces()[i][1];
}

void MinimalReactions::cartColumns(const SimTK::State& s, const MinimalDynamics& dyn, const SimTK::Vector& normals,
                                   int j, SimTK::Vec3& bearing, std::vector<double>& re) const {
  const CartRig& c = model_.carts()[size_t(j)];
  const GuideNormals n{normals[2 * j], normals[2 * j + 1]};
  const double friction = model_.guideFrictionForce(s, j);
  const SimTK::Vec2 F = dyn.loopForce(s, j);  // on the cart at B
  if (!c.cam.isEmptyHandle()) {
    // Cam drive: the coupler acts on mobilities only: no bearing load.
    model_.setCamReactions(j, n, friction, F[0], re);
    return;
  }
  const SimTK::Vec3 F_rod_on_cart(F[0], F[1], 0);
  SimTK::Vec3 a_S(0);
  if (!c.rod.isEmptyHandle()) {
    a_S = centreOfMassAcceleration(s, c.rod, body_accelerations_[c.rod.getMobilizedBodyIndex()]);
    bearing += netForce(s, dyn, c.rod);
  }
  bearing += F_rod_on_cart;  // the cart pushes the subtree with -F at B (or at the pin)
  model_.setRodReactions(s, j, n, friction, F_rod_on_cart, a_S, re);
}

void MinimalReactions::row(const SimTK::State& s, const MinimalDynamics& dyn, std::vector<double>& re) {
  const SimTK::Vector& udot = dyn.udot();
  model_.matter().calcBodyAccelerationFromUDot(s, udot, body_accelerations_);
  const SimTK::Vector normals = dyn.guideNormals(s);
  const ColumnLayout& L = model_.reactionsLayout();
  L.reset(re);
  L.set(re, Column::t, s.getTime());
  // The crankshaft subtree's free body: Σ (m·a - applied) over its bodies, minus the forces the
  // carts put on it through the loops.
  SimTK::Vec3 bearing = netForce(s, dyn, model_.crank());
  if (model_.elastic()) bearing += netForce(s, dyn, model_.motorSide());
  for (int j = 0; j < int(model_.carts().size()); ++j) cartColumns(s, dyn, normals, j, bearing, re);
  L.set(re, Column::bearing_x, bearing[0]);
  L.set(re, Column::bearing_y, bearing[1]);
  L.set(re, Column::coupling_torque, model_.couplingTorque(s, udot));
}

}  // namespace rollerdyn
