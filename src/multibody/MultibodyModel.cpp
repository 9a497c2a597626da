#include "multibody/MultibodyModel.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "analysis/FrictionChecks.h"
#include "multibody/CamFollower.h"
#include "multibody/ElasticCoupling.h"
#include "multibody/CrankshaftTorsion.h"
#include "multibody/EnergyMeter.h"
#include "multibody/GuideFriction.h"
#include "motor/BreakdownTorque.h"
#include "physics/CrankInertia.h"
#include "motor/SharedMotorLaw.h"
#include "motor/Supply.h"
#include "multibody/MotorForce.h"
#include "multibody/RollerLoadForce.h"
#include "physics/CamMotionLaw.h"
#include "physics/SliderCrank.h"
#include "physics/TorsionalChain.h"

namespace rollerdyn {
namespace {

// A rotor of polar inertia J about z: a thin disc has Ixx = Iyy = J/2, which keeps the inertia
// physically valid (triangle inequality) whatever J is.
SimTK::Inertia disc(double J) { return SimTK::Inertia(0.5 * J, 0.5 * J, J); }

// Simbody rejects a body with inertia but no mass. The scenes give rotor inertias, not rotor
// masses, so rotors carry this token mass on their axis: on a fixed axis it changes no motion,
// and its weight (0.01 N) is far below anything reported.
constexpr double kRotorTokenMass = 1e-3;  // [kg]

SimTK::Vec3 crankPin(const Scene& scene, int j) {
  const double th = scene.crankPhase(j), r = scene.crank.radius;
  return SimTK::Vec3(r * std::cos(th), r * std::sin(th), 0);
}

// Cart j: a point mass at its centre of mass (rods' share included) on a slider.
SimTK::Body::Rigid cartBody(const Scene& sc, int j, int side) {
  const double m_cart = sc.cartMassWithRodShare(j);
  const SimTK::Vec3 com_cart(side * sc.carts.geometry.p, sc.carts.geometry.com_height, 0);
  // The cart only slides, so its rotational inertia never enters the motion; it is a point mass
  // at its centre of mass plus a token central inertia. Without the token, Simbody's central
  // inertia Inertia(com, m) - Inertia(com, m) can round to -3e-14 and be rejected (a 700 kg cart).
  const SimTK::Inertia token_central(1e-9 * m_cart);  // [kg·m²], isotropic
  return SimTK::Body::Rigid(
      SimTK::MassProperties(m_cart, com_cart, token_central.shiftFromMassCenter(com_cart, m_cart)));
}

}  // namespace

MultibodyModel::MultibodyModel(const Scene& scene, const MultibodyOptions& options)
    : scene_(scene), options_(options), matter_(system_), forces_(system_),
      breakdown_torque_(scene.motor.breakdown_torque) {
  buildDrive();
  buildCarts();
  buildForces();
  system_.realizeTopology();
  fillInventory();
  layOutColumns();
}

MultibodyModel::~MultibodyModel() = default;

void MultibodyModel::buildDrive() {
  const Scene& sc = scene_;
  const bool rigid = sc.coupling.type == CouplingType::Rigid;
  const std::string without_inertia = crankWithoutInertia(sc, "multibody model");
  if (!without_inertia.empty()) throw std::invalid_argument(without_inertia);
  const double J_motor_side = rigid ? sc.motorSideInertia() : 0.0;
  if (sc.crankshaft.torsionalChain()) {
    buildTorsionalChain(J_motor_side);
  } else {
    std::vector<int> all(sc.carts.count);
    for (int j = 0; j < sc.carts.count; ++j) all[j] = j;
    crank_ = SimTK::MobilizedBody::Pin(matter_.Ground(), SimTK::Transform(),
                                       crankBody(sc.crankSideInertia() + J_motor_side, all), SimTK::Transform());
    throw_of_cart_.assign(sc.carts.count, crank_);
  }
  if (options_.prescribe_crank_speed) SimTK::Motion::Steady(crank_, options_.crank_speed);

  if (rigid) {
    motor_ = crank_;  // one rotating body: a rigid coupling is not a stiff spring
  } else {
    SimTK::Body::Rigid motor_body(SimTK::MassProperties(kRotorTokenMass, SimTK::Vec3(0), disc(sc.motorSideInertia())));
    // Mobilized on the crankshaft, so its coordinate is the coupling twist (ElasticCoupling.h).
    motor_ = SimTK::MobilizedBody::Pin(crank_, SimTK::Transform(), motor_body, SimTK::Transform());
  }
}

SimTK::Body::Rigid MultibodyModel::crankBody(double J, const std::vector<int>& carts) const {
  const Scene& sc = scene_;
  // Split rods put half their mass on each crank pin (Loveikin, Pochka, Romasevych (2018) eq. (2)): point masses that
  // turn with the crankshaft, so their gravity torque is felt too.
  const double pin_mass = sc.rods.model == RodModel::Split ? 0.5 * sc.rods.mass : 0.0;
  SimTK::Inertia inertia = disc(J);
  double mass = kRotorTokenMass;
  SimTK::Vec3 first_moment(0);
  for (int j : carts) {
    if (!(pin_mass > 0)) break;
    inertia += SimTK::Inertia(crankPin(sc, j), pin_mass);
    mass += pin_mass;
    first_moment += pin_mass * crankPin(sc, j);
  }
  return SimTK::Body::Rigid(SimTK::MassProperties(mass, first_moment / mass, inertia));
}

void MultibodyModel::buildTorsionalChain(double J_motor_side) {
  // One body per throw in z order (physics/TorsionalChain.h); throw k+1 on a Pin on throw k, so its
  // coordinate is the segment's twist. All throws share the crankshaft's frame at zero twist, so a
  // crank pin's station is the same in its throw's frame as in the rigid shaft's.
  const TorsionalChainLayout chain = torsionalChainLayout(scene_);
  std::vector<SimTK::MobilizedBody> throws;
  for (size_t k = 0; k < chain.inertia.size(); ++k) {
    const double J = chain.inertia[k] + (k == 0 ? J_motor_side : 0.0);
    const SimTK::Body::Rigid body = crankBody(J, {chain.cart_of_throw[k]});
    if (k == 0)
      throws.push_back(SimTK::MobilizedBody::Pin(matter_.Ground(), SimTK::Transform(), body, SimTK::Transform()));
    else
      throws.push_back(SimTK::MobilizedBody::Pin(throws.back(), SimTK::Transform(), body, SimTK::Transform()));
  }
  crank_ = throws.front();
  throw_of_cart_.clear();
  for (int j = 0; j < scene_.carts.count; ++j) throw_of_cart_.push_back(throws[chain.throw_of_cart[j]]);
  auto* f = new CrankshaftTorsion(std::vector<SimTK::MobilizedBody>(throws.begin() + 1, throws.end()), chain.stiffness,
                                  chain.damping);
  torsion_force_ = f;
  addForceElement(f, "CrankshaftTorsion(" + std::to_string(throws.size() - 1) + " segments)");
}

void MultibodyModel::buildCarts() {
  const Scene& sc = scene_;
  for (int j = 0; j < sc.carts.count; ++j) {
    CartRig rig;
    rig.side = sc.carts.side[j];
    rig.p_CrankPin = crankPin(sc, j);
    rig.crank = throw_of_cart_[j];
    rig.rod_length = sc.rods.length;
    rig.cart = SimTK::MobilizedBody::Slider(matter_.Ground(), SimTK::Transform(), cartBody(sc, j, rig.side),
                                            SimTK::Transform());
    if (sc.hasCamDrive())
      driveCartByCam(rig, j);
    else if (sc.rods.model == RodModel::Distributed)
      linkCartByRodBody(rig);
    else
      SimTK::Constraint::Rod(rig.crank, rig.p_CrankPin, rig.cart, SimTK::Vec3(0), rig.rod_length);
    constraint_count_ += 1;  // one Constraint object per cart, whichever links it
    carts_.push_back(rig);
  }
}

void MultibodyModel::driveCartByCam(CartRig& rig, int j) {
  // Loveikin and Pochka (cam drive paper): the cam on the crankshaft pushes the cart; x_B = σ·x(φ2 + j·Δφ) replaces the rod.
  const Scene& sc = scene_;
  rig.p_CrankPin = SimTK::Vec3(0);
  rig.cam = SimTK::Constraint::CoordinateCoupler(
      matter_, new CamFollowerFunction(sc.cam.stroke, rig.side, sc.crankPhase(j)),
      std::vector<SimTK::MobilizedBodyIndex>{crank_.getMobilizedBodyIndex(), rig.cart.getMobilizedBodyIndex()},
      std::vector<SimTK::MobilizerQIndex>{SimTK::MobilizerQIndex(0), SimTK::MobilizerQIndex(0)});
}

void MultibodyModel::linkCartByRodBody(CartRig& rig) {
  const Scene& sc = scene_;
  const double l = rig.rod_length;
  // Rod frame: origin at the crank pin A, +x along the rod towards B, centre of mass at l/2.
  const double m = sc.rods.mass, I = sc.rods.inertia_com;
  const SimTK::Vec3 com(0.5 * l, 0, 0);
  // About its centre a slender rod has Iyy = Izz = I; a small Ixx keeps the inertia valid.
  const SimTK::Inertia central(1e-9 * I + 1e-12, I, I);
  SimTK::Body::Rigid rod_body(SimTK::MassProperties(m, com, central.shiftFromMassCenter(com, m)));
  rig.rod = SimTK::MobilizedBody::Pin(rig.crank, SimTK::Transform(rig.p_CrankPin), rod_body, SimTK::Transform());
  rig.rod_mass = m;
  // Close the loop at B: the rod end stays on the cart's z axis through B (a planar
  // revolute joint: two equations; a Ball would add a redundant z equation). One
  // PointOnLine rather than two PointInPlane: Simbody builds G·M⁻¹·Gᵀ column by column and
  // every column visits every Constraint object, so halving the objects halves that cost.
  SimTK::Constraint::PointOnLine(rig.cart, SimTK::UnitVec3(SimTK::ZAxis), SimTK::Vec3(0), rig.rod,
                                 SimTK::Vec3(l, 0, 0));
}

void MultibodyModel::addForceElement(SimTK::Force::Custom::Implementation* f, const std::string& inventory_name) {
  SimTK::Force::Custom(forces_, f);
  applied_order_.push_back(f);
  inventory_.force_elements.push_back(inventory_name);
}

void MultibodyModel::buildForces() {
  const Scene& sc = scene_;
  if (sc.hasMotor()) addMotorForce();
  if (sc.coupling.type == CouplingType::Elastic) addElasticCoupling();
  if (sc.hasGravity()) {
    gravity_ = SimTK::Force::Gravity(forces_, matter_, -SimTK::YAxis, sc.loads.gravity);
    applied_order_.push_back(nullptr);
    inventory_.force_elements.push_back("Gravity");
  }
  if (sc.hasRollerLoads()) addRollerLoads();
  if (sc.hasGuideFriction()) {
    auto* f = new GuideFriction(forces_, matter_, carts_, sc.loads, sc.carts.geometry);
    friction_force_ = f;
    addForceElement(f, "GuideFriction");
  }
  // Last: the meter reads the powers of the elements above.
  auto* meter = new EnergyMeter(forces_, {motor_force_, coupling_force_, load_force_, friction_force_, torsion_force_});
  SimTK::Force::Custom(forces_, meter);
  energy_meter_ = meter;
  applied_order_.push_back(meter);
}

void MultibodyModel::addElasticCoupling() {
  const Scene& sc = scene_;
  auto* f = new ElasticCoupling(motor_, couplingLaw(sc));
  coupling_force_ = f;
  addForceElement(f, std::string(sc.hasCouplingDamping() ? "ElasticCoupling(spring+damper" : "ElasticCoupling(spring") +
                         (sc.hasBacklash() ? "+backlash)" : ")"));
}

void MultibodyModel::addRollerLoads() {
  std::vector<Loads> per_cart;
  for (int j = 0; j < scene_.carts.count; ++j) per_cart.push_back(scene_.cartLoads(j));
  auto* f = new RollerLoadForce(carts_, per_cart, scene_.carts.geometry);
  load_force_ = f;
  addForceElement(f, "RollerLoads");
}

void MultibodyModel::addMotorForce() {
  const Scene& sc = scene_;
  std::shared_ptr<const MotorLaw> law = options_.motor_law;
  if (!law) law = sharedMotorLaw(sc);
  Supply supply = makeSupply(sc, law.get());
  breakdown_torque_ = rollerdyn::motorBreakdownTorque(sc, law.get());
  auto* f = new MotorForce(forces_, motor_, law, std::move(supply), reducerLaw(sc, breakdown_torque_));
  motor_force_ = f;
  addForceElement(f, sc.induction.model == MotorModel::Kloss && !options_.motor_law
                         ? "KlossMotor"
                         : "InductionMotor(" + law->description() + ")");
}

void MultibodyModel::fillInventory() {
  const SimTK::State& s = system_.getDefaultState();
  SimTK::State tmp = s;
  system_.realizeModel(tmp);
  system_.realize(tmp, SimTK::Stage::Instance);
  inventory_.bodies = matter_.getNumBodies() - 1;
  inventory_.mobilities = tmp.getNU();
  inventory_.constraints = constraint_count_;
  inventory_.constraint_equations = tmp.getNUDotErr();
  const int prescribed = options_.prescribe_crank_speed ? 1 : 0;
  inventory_.degrees_of_freedom = inventory_.mobilities - inventory_.constraint_equations - prescribed;
  inventory_.effects = scene_.effects();
}

int MultibodyModel::motorStateCount() const { return motor_force_ ? motor_force_->stateCount() : 0; }

bool MultibodyModel::hasFrictionLagStates() const { return friction_force_ && friction_force_->lagged(); }

std::string MultibodyModel::guideNormalsDescription() const {
  return friction_force_ ? rollerdyn::guideNormalsDescription(scene_, false) : "";
}

void MultibodyModel::auxiliaryRates(const SimTK::State& s, const SimTK::Vector& guide_normals_now,
                                    SimTK::Vector& zdot) const {
  zdot.resize(forces_.getZ(s).size());
  zdot = 0.0;
  energy_meter_->calcRates(s, zdot);
  if (motor_force_) motor_force_->calcRates(s, zdot);
  if (friction_force_) friction_force_->calcRates(s, guide_normals_now, zdot);
}

SimTK::Vector MultibodyModel::frictionPowerGradient(const SimTK::State& s) const {
  return friction_force_ ? friction_force_->dissipatedPowerGradient(s) : SimTK::Vector();
}

void MultibodyModel::addAppliedForces(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& body_forces,
                                      SimTK::Vector_<SimTK::Vec3>& particle_forces,
                                      SimTK::Vector& mobility_forces, bool include_friction) const {
  // No element is ever disabled here, and none caches position-only forces in the subsystem
  // (dependsOnlyOnPositions is false), so Simbody's sum is this loop, term for term.
  for (const SimTK::Force::Custom::Implementation* f : applied_order_) {
    if (f && f == friction_force_ && !include_friction) continue;
    if (f)
      f->calcForce(s, body_forces, particle_forces, mobility_forces);
    else
      body_forces += gravity_.getBodyForces(s);  // what Force::Gravity's calcForce adds
  }
}

double MultibodyModel::motorSpeed(const SimTK::State& s) const {
  return motor_.getBodyAngularVelocity(s)[2];
}

int MultibodyModel::energyStateCount() const { return energy_meter_->stateCount(); }

double MultibodyModel::motorTorque(const SimTK::State& s) const {
  return motor_force_ ? motor_force_->torque(s) : 0.0;
}

double MultibodyModel::couplingTorque(const SimTK::State& s) const {
  if (coupling_force_) return coupling_force_->torque(s);
  return couplingTorque(s, s.getUDot());  // needs Acceleration stage
}

double MultibodyModel::couplingTorque(const SimTK::State& s, const SimTK::Vector& udot) const {
  if (coupling_force_) return coupling_force_->torque(s);
  // Rigid coupling: the torque the motor-side inertia passes on to the crank side,
  // M_motor (+ brake) - J_n1·φ̈.
  const double M_drive = motor_force_ && motor_force_->supply().hasBrake()
                             ? motorTorque(s) + motor_force_->brakeTorque(s)
                             : motorTorque(s);
  return M_drive - scene_.motorSideInertia() * udot[crank_.getFirstUIndex(s)];
}

double MultibodyModel::constraintError(const SimTK::State& s) const {
  const SimTK::Vector& qerr = s.getQErr();
  return qerr.size() ? SimTK::max(SimTK::abs(qerr)) : 0.0;
}

EnergyAudit energyAuditBetween(const EnergySnapshot& first, const EnergySnapshot& last) {
  EnergyAudit a;
  a.motor_work = last.motor_work - first.motor_work;
  a.damping_dissipation = last.damping_dissipation - first.damping_dissipation;
  a.friction_dissipation = last.friction_dissipation - first.friction_dissipation;
  a.load_work = last.load_work - first.load_work;
  a.brake_dissipation = last.brake_dissipation - first.brake_dissipation;
  a.reducer_losses = last.reducer_losses - first.reducer_losses;
  a.kinetic_initial = first.kinetic;
  a.kinetic_final = last.kinetic;
  a.potential_initial = first.potential;
  a.potential_final = last.potential;
  return a;
}

EnergySnapshot MultibodyModel::energy(const SimTK::State& s) const {
  EnergySnapshot e;
  e.kinetic = system_.calcKineticEnergy(s);
  e.potential = system_.calcPotentialEnergy(s);
  e.motor_work = energy_meter_->motorWork(s);
  e.damping_dissipation = energy_meter_->dampingDissipation(s);
  e.friction_dissipation = energy_meter_->frictionDissipation(s);
  e.load_work = energy_meter_->loadWork(s);
  e.reducer_losses = energy_meter_->reducerLosses(s);
  if (motor_force_) e.brake_dissipation = motor_force_->brakeWork(s);
  return e;
}

}  // namespace rollerdyn
