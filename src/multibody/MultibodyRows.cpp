// The rows the multibody model writes: the timeseries (motion, drive, shaft) and the reactions
// (guide normals, rod and crank-pin forces per cart, the crankshaft's bearing), in the columns
// laid out from the force elements it built.
#include "multibody/MultibodyModel.h"

#include "motor/MotorColumns.h"
#include "multibody/CrankshaftTorsion.h"
#include "multibody/ElasticCoupling.h"
#include "multibody/GuideFriction.h"
#include "multibody/GuideReactions.h"
#include "multibody/MotorForce.h"
#include "physics/CouplingLaw.h"

namespace rollerdyn {

void MultibodyModel::layOutColumns() {
  WrittenColumns w;
  w.multibody = true;
  w.carts = int(carts_.size());
  if (motor_force_) addMotorColumns(&motor_force_->law(), motor_force_->supply(), w);
  w.reducer_losses = recordsReducerLosses();
  w.backlash = coupling_force_ && coupling_force_->law().hasBacklash();
  w.shaft_segments = torsion_force_ ? torsion_force_->segmentCount() : 0;
  timeseries_layout_ = ColumnLayout(OutputFile::Timeseries, w);
  // The main bearings' own columns come after the run, from the shaft's statics
  // (analysis/CrankshaftBearings.h).
  reactions_layout_ = ColumnLayout(OutputFile::Reactions, w);
}

void MultibodyModel::observe(const SimTK::State& s, std::vector<double>& ts,
                             std::vector<double>& re) const {
  observeMotion(s, s.getUDot(), ts);
  observeReactions(s, re);
}

void MultibodyModel::observeMotion(const SimTK::State& s, const SimTK::Vector& udot,
                                   std::vector<double>& ts) const {
  const ColumnLayout& L = timeseries_layout_;
  L.reset(ts);
  L.set(ts, Column::t, s.getTime());
  setShaftMotion(s, udot, ts);
  L.set(ts, Column::coupling_torque, couplingTorque(s, udot));
  L.set(ts, Column::motor_torque, motorTorque(s));
  setCartMotion(s, udot, ts);
  setDriveColumns(s, ts);
}

void MultibodyModel::setShaftMotion(const SimTK::State& s, const SimTK::Vector& udot, std::vector<double>& ts) const {
  // With an elastic coupling the motor side is mobilized on the crankshaft: its q, u, u̇ are the
  // twist and its rates; with a rigid coupling motor_ is the crankshaft and they are zero.
  const bool elastic = motor_.getMobilizedBodyIndex() != crank_.getMobilizedBodyIndex();
  const double phi2 = crank_.getOneQ(s, 0), w2 = crank_.getOneU(s, 0);
  const double e2 = udot[crank_.getFirstUIndex(s)];
  const double twist = elastic ? motor_.getOneQ(s, 0) : 0.0;
  const double twist_rate = elastic ? motor_.getOneU(s, 0) : 0.0;
  const double twist_accel = elastic ? udot[motor_.getFirstUIndex(s)] : 0.0;
  const double phi1 = phi2 + twist, w1 = w2 + twist_rate, e1 = e2 + twist_accel;
  const ColumnLayout& L = timeseries_layout_;
  L.set(ts, Column::phi_motor, phi1);
  L.set(ts, Column::phi_crank, phi2);
  L.set(ts, Column::omega_motor, w1);
  L.set(ts, Column::omega_crank, w2);
  L.set(ts, Column::eps_crank, e2);
  L.set(ts, Column::eps_motor, e1);
  L.set(ts, Column::twist, twist);
  L.set(ts, Column::twist_rate, twist_rate);
  L.set(ts, Column::twist_accel, twist_accel);
}

void MultibodyModel::setCartMotion(const SimTK::State& s, const SimTK::Vector& udot, std::vector<double>& ts) const {
  const ColumnLayout& L = timeseries_layout_;
  for (size_t j = 0; j < carts_.size(); ++j) {
    const CartRig& c = carts_[j];
    L.set(ts, Column::x_cart, int(j) + 1, c.x(s));
    L.set(ts, Column::v_cart, int(j) + 1, c.v(s));
    L.set(ts, Column::a_cart, int(j) + 1, udot[c.cart.getFirstUIndex(s)]);
  }
}

void MultibodyModel::setDriveColumns(const SimTK::State& s, std::vector<double>& ts) const {
  const ColumnLayout& L = timeseries_layout_;
  if (motor_force_) {
    const MotorForce& m = *motor_force_;
    const double current = L.has(Column::stator_current) ? m.evaluate(s).stator_current : 0.0;
    setMotorColumns(L, current, m.supplyState(s), m.brakeTorque(s), ts);
  }
  if (L.has(Column::reducer_loss_torque)) L.set(ts, Column::reducer_loss_torque, motor_force_->reducerLossTorque(s));
  if (L.has(Column::tooth_contact))
    L.set(ts, Column::tooth_contact,
          static_cast<double>(toothContact(coupling_force_->law(), coupling_force_->twist(s))));
  for (int k = 0; torsion_force_ && k < torsion_force_->segmentCount(); ++k)
    L.set(ts, Column::shaft_torque, k + 1, torsion_force_->torque(s, k));
}

bool MultibodyModel::recordsReducerLosses() const {
  return motor_force_ && motor_force_->reducer().model == ReducerLossModel::PowerFlow;
}

void MultibodyModel::setCartReactions(int cart, const CartReactions& r, std::vector<double>& re) const {
  const ColumnLayout& L = reactions_layout_;
  L.set(re, Column::N_front, cart, r.N_front);
  L.set(re, Column::N_rear, cart, r.N_rear);
  L.set(re, Column::F_rod, cart, r.F_rod);
  L.set(re, Column::friction, cart, r.friction);
  L.set(re, Column::crankpin_x, cart, r.crankpin_x);
  L.set(re, Column::crankpin_y, cart, r.crankpin_y);
}

void MultibodyModel::setCamReactions(int j, const GuideNormals& n, double friction, double Fx_on_cart,
                                     std::vector<double>& re) const {
  // "F_rod" > 0 pulls the cart towards the shaft, like a rod in tension; the pusher puts the
  // opposite force on the cam.
  setCartReactions(j + 1, {n.front, n.rear, -carts_[j].side * Fx_on_cart, friction, -Fx_on_cart, 0.0}, re);
}

void MultibodyModel::setRodReactions(const SimTK::State& s, int j, const GuideNormals& n, double friction,
                                     const SimTK::Vec3& F_rod_on_cart, const SimTK::Vec3& a_S,
                                     std::vector<double>& re) const {
  const CartRig& c = carts_[j];
  // Pin A in ground, and the unit vector B -> A along the rod: tension pulls the cart to A.
  const SimTK::Vec3 p_A = c.crank.findStationLocationInGround(s, c.p_CrankPin);
  const SimTK::UnitVec3 e_BA(p_A - c.cart.getBodyOriginLocation(s));
  // Force of the rod on the crank pin: rod free body m·a_S = F_A + (-F_B) + m·g.
  SimTK::Vec3 F_rod_on_crank = -F_rod_on_cart;
  if (!c.rod.isEmptyHandle())
    F_rod_on_crank += -c.rod_mass * a_S + c.rod_mass * SimTK::Vec3(0, -scene_.loads.gravity, 0);
  setCartReactions(j + 1, {n.front, n.rear, ~F_rod_on_cart * e_BA, friction, F_rod_on_crank[0], F_rod_on_crank[1]},
                   re);
}

double MultibodyModel::guideFrictionForce(const SimTK::State& s, int j) const {
  return friction_force_ ? friction_force_->frictionForce(s, j) : 0.0;
}

void MultibodyModel::observeCartReactions(const SimTK::State& s, int j,
                                          const SimTK::Vector_<SimTK::SpatialVec>& reactions,
                                          const SimTK::Vector_<SimTK::SpatialVec>& applied,
                                          std::vector<double>& re) const {
  const CartRig& c = carts_[size_t(j)];
  const SimTK::MobilizedBodyIndex ic = c.cart.getMobilizedBodyIndex();
  const GuideNormals n = solveGuideNormals(reactions[ic], c.side, scene_.carts.geometry);
  const double friction = guideFrictionForce(s, j);
  if (!c.cam.isEmptyHandle()) {
    // Cam drive: the coupler acts on the mobilities [crank, cart] (in that order); Simbody
    // returns constraint forces with the sign opposite to applied forces. The cam force on
    // the cart is horizontal.
    const SimTK::Vector f = c.cam.getConstrainedMobilityForcesAsVector(s);
    setCamReactions(j, n, friction, -f[1], re);
    return;
  }
  // Force of the rod on the cart at B from the cart's free body: m·a = applied + guide + rod.
  const double m_cart = c.cart.getBodyMass(s);
  const SimTK::Vec3 a_cart(c.cart.getOneUDot(s, 0), 0, 0);
  const SimTK::Vec3 F_rod_on_cart = m_cart * a_cart - applied[ic][1] - reactions[ic][1];
  // The rod's centre of mass is at its middle.
  SimTK::Vec3 a_S(0);
  if (!c.rod.isEmptyHandle()) a_S = c.rod.findStationAccelerationInGround(s, SimTK::Vec3(0.5 * c.rod_length, 0, 0));
  setRodReactions(s, j, n, friction, F_rod_on_cart, a_S, re);
}

void MultibodyModel::observeReactions(const SimTK::State& s, std::vector<double>& re) const {
  const double torque_coupling = couplingTorque(s);
  SimTK::Vector_<SimTK::SpatialVec> reactions;
  matter_.calcMobilizerReactionForces(s, reactions);
  const SimTK::Vector_<SimTK::SpatialVec>& applied = system_.getRigidBodyForces(s, SimTK::Stage::Dynamics);
  const ColumnLayout& L = reactions_layout_;
  L.reset(re);
  L.set(re, Column::t, s.getTime());
  for (int j = 0; j < int(carts_.size()); ++j) observeCartReactions(s, j, reactions, applied, re);
  const SimTK::Vec3 bearing = reactions[crank_.getMobilizedBodyIndex()][1];
  L.set(re, Column::bearing_x, bearing[0]);
  L.set(re, Column::bearing_y, bearing[1]);
  L.set(re, Column::coupling_torque, torque_coupling);
}

}  // namespace rollerdyn
