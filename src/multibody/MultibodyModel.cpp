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
#include "motor/MotorColumns.h"
#include "motor/BreakdownTorque.h"
#include "physics/CrankInertia.h"
#include "motor/SharedMotorLaw.h"
#include "motor/Supply.h"
#include "multibody/MinimalCoordinates.h"
#include "multibody/MinimalDynamics.h"
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
  SimTK::Force::Custom(forces_, f);
  torsion_force_ = f;
  applied_order_.push_back(f);
  inventory_.force_elements.push_back("CrankshaftTorsion(" + std::to_string(throws.size() - 1) + " segments)");
}

void MultibodyModel::buildCarts() {
  const Scene& sc = scene_;
  const double l = sc.rods.length;
  for (int j = 0; j < sc.carts.count; ++j) {
    CartRig rig;
    rig.side = sc.carts.side[j];
    rig.p_CrankPin = crankPin(sc, j);
    rig.crank = throw_of_cart_[j];
    rig.rod_length = l;
    const double m_cart = sc.cartMassWithRodShare(j);
    const SimTK::Vec3 com_cart(rig.side * sc.carts.geometry.p, sc.carts.geometry.com_height, 0);
    // The cart only slides, so its rotational inertia never enters the motion; it is a point mass
    // at its centre of mass plus a token central inertia. Without the token, Simbody's central
    // inertia Inertia(com, m) - Inertia(com, m) can round to -3e-14 and be rejected (a 700 kg cart).
    const SimTK::Inertia token_central(1e-9 * m_cart);  // [kg·m²], isotropic
    SimTK::Body::Rigid cart_body(
        SimTK::MassProperties(m_cart, com_cart, token_central.shiftFromMassCenter(com_cart, m_cart)));
    rig.cart = SimTK::MobilizedBody::Slider(matter_.Ground(), SimTK::Transform(), cart_body, SimTK::Transform());

    if (sc.hasCamDrive()) {
      // Loveikin and Pochka (cam drive paper): the cam on the crankshaft pushes the cart; x_B = σ·x(φ2 + j·Δφ) replaces the rod.
      rig.p_CrankPin = SimTK::Vec3(0);
      rig.cam = SimTK::Constraint::CoordinateCoupler(
          matter_, new CamFollowerFunction(sc.cam.stroke, rig.side, sc.crankPhase(j)),
          std::vector<SimTK::MobilizedBodyIndex>{crank_.getMobilizedBodyIndex(),
                                                 rig.cart.getMobilizedBodyIndex()},
          std::vector<SimTK::MobilizerQIndex>{SimTK::MobilizerQIndex(0), SimTK::MobilizerQIndex(0)});
      constraint_count_ += 1;
    } else if (sc.rods.model == RodModel::Distributed) {
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
      constraint_count_ += 1;
    } else {
      SimTK::Constraint::Rod(rig.crank, rig.p_CrankPin, rig.cart, SimTK::Vec3(0), l);
      constraint_count_ += 1;
    }
    carts_.push_back(rig);
  }
}

void MultibodyModel::buildForces() {
  const Scene& sc = scene_;
  EnergyMeter::Sources sources;
  if (sc.hasMotor()) {
    std::shared_ptr<const MotorLaw> law = options_.motor_law;
    if (!law) law = sharedMotorLaw(sc);
    Supply supply = makeSupply(sc, law.get());
    breakdown_torque_ = rollerdyn::motorBreakdownTorque(sc, law.get());
    auto* f = new MotorForce(forces_, motor_, law, std::move(supply), reducerLaw(sc, breakdown_torque_));
    SimTK::Force::Custom(forces_, f);
    motor_force_ = sources.motor = f;
    applied_order_.push_back(f);
    inventory_.force_elements.push_back(sc.induction.model == MotorModel::Kloss && !options_.motor_law
                                            ? "KlossMotor"
                                            : "InductionMotor(" + law->description() + ")");
  }
  if (sc.coupling.type == CouplingType::Elastic) {
    auto* f = new ElasticCoupling(motor_, couplingLaw(sc));
    SimTK::Force::Custom(forces_, f);
    coupling_force_ = sources.coupling = f;
    applied_order_.push_back(f);
    inventory_.force_elements.push_back(std::string(sc.hasCouplingDamping() ? "ElasticCoupling(spring+damper"
                                                                            : "ElasticCoupling(spring") +
                                        (sc.hasBacklash() ? "+backlash)" : ")"));
  }
  if (sc.hasGravity()) {
    gravity_ = SimTK::Force::Gravity(forces_, matter_, -SimTK::YAxis, sc.loads.gravity);
    applied_order_.push_back(nullptr);
    inventory_.force_elements.push_back("Gravity");
  }
  if (sc.hasRollerLoads()) {
    std::vector<Loads> per_cart;
    for (int j = 0; j < sc.carts.count; ++j) per_cart.push_back(sc.cartLoads(j));
    auto* f = new RollerLoadForce(carts_, per_cart, sc.carts.geometry);
    SimTK::Force::Custom(forces_, f);
    load_force_ = sources.loads = f;
    applied_order_.push_back(f);
    inventory_.force_elements.push_back("RollerLoads");
  }
  if (sc.hasGuideFriction()) {
    auto* f = new GuideFriction(forces_, matter_, carts_, sc.loads, sc.carts.geometry);
    SimTK::Force::Custom(forces_, f);
    friction_force_ = sources.friction = f;
    applied_order_.push_back(f);
    inventory_.force_elements.push_back("GuideFriction");
  }
  sources.torsion = torsion_force_;
  auto* meter = new EnergyMeter(forces_, sources);
  SimTK::Force::Custom(forces_, meter);
  energy_meter_ = meter;
  applied_order_.push_back(meter);
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

SimTK::State MultibodyModel::closedFormState(double phi, double omega, double twist) const {
  SimTK::State s = closedFormKinematics(phi, omega, twist);
  startMotor(s);
  return s;
}

void MultibodyModel::startMotor(SimTK::State& s) const {
  if (!motor_force_) return;
  const bool steady = motorSteadyAtStart(scene_, motor_force_->supply());
  motor_force_->initialize(s, steady);
  system_.realize(s, SimTK::Stage::Velocity);
  motor_force_->applyDueEvents(s, false);
  system_.realize(s, SimTK::Stage::Velocity);
}

SimTK::State MultibodyModel::closedFormKinematics(double phi, double omega, double twist) const {
  SimTK::State s = system_.getDefaultState();
  system_.realizeModel(s);
  // Carts of different masses: the lightest is the one a friction error moves most.
  if (friction_force_) friction_force_->setErrorWeights(s, scene_.lightestCartMassWithRodShare());
  if (motor_force_) motor_force_->setErrorWeights(s);
  if (elastic()) {
    // Simbody counts 1 rad (1 rad/s) as a unit change of every coordinate (speed), but the
    // coupling twist is ~torque/c: 1e-6 rad at c = 1e9, so it was held to ~100 % of itself and
    // the coupling torque carried errors of c·accuracy. One unit of twist is the twist that
    // carries the motor's breakdown torque at the crank, M_kr·u·η, so the coupling torque is
    // held to accuracy·M_kr·u·η whatever the stiffness.
    const double torque_scale =
        breakdown_torque_ * scene_.reducer.ratio * scene_.reducer.efficiency;
    s.updUWeights(matter_.getMySubsystemIndex())[motor_.getFirstUIndex(s)] =
        std::max(1.0, scene_.coupling.stiffness / torque_scale);
  }
  if (torsion_force_) {
    // The same for each segment of a torsional chain: one unit of its twist carries M_kr·u·η.
    const double torque_scale = std::max(breakdown_torque_ * scene_.reducer.ratio * scene_.reducer.efficiency, 1e-300);
    for (int k = 0; k < torsion_force_->segmentCount(); ++k)
      s.updUWeights(matter_.getMySubsystemIndex())[torsion_force_->segmentBody(k).getFirstUIndex(s)] =
          std::max(1.0, torsion_force_->stiffness(k) / torque_scale);
  }
  system_.realize(s, SimTK::Stage::Instance);
  IndependentState x;
  x.crank_angle = phi;
  x.crank_speed = omega;
  x.twist = twist;
  x.twist_rate = 0.0;  // the motor side starts at the crank's speed
  // A prescribed crank speed is the options' (MinimalCoordinates::apply writes it).
  MinimalCoordinates(*this, s).apply(0.0, x, s);
  system_.realize(s, SimTK::Stage::Velocity);
  return s;
}

SimTK::State MultibodyModel::assembledState(double phi, double omega, double twist) const {
  SimTK::State s = closedFormKinematics(phi, omega, twist);
  // The closed-form configuration already satisfies the loops; projection only removes
  // round-off and can therefore never jump to the other assembly branch.
  system_.realize(s, SimTK::Stage::Position);
  system_.projectQ(s, 1e-13);
  system_.realize(s, SimTK::Stage::Velocity);
  system_.projectU(s, 1e-13);
  startMotor(s);
  if (friction_force_ && friction_force_->lagged()) {
    // Start the friction normal forces at the reactions they produce themselves (fixed point;
    // it contracts by a factor of order f per pass).
    for (int pass = 0; pass < 8; ++pass) {
      system_.realize(s, SimTK::Stage::Acceleration);
      const SimTK::Vector n = friction_force_->currentNormals(s);
      friction_force_->setNormalsInUse(s, n);
    }
  } else if (friction_force_) {
    // Algebraic law: the friction loop solved by the minimal formulation's inverse-dynamics pass.
    MinimalCoordinates coords(*this, s);
    coords.apply(0.0, coords.extract(s), s);
    MinimalDynamics dyn(*this, s);
    if (!dyn.evaluate(s, coords))
      throw std::invalid_argument("multibody model: at the initial state the " +
                                  describeLoopFailure(dyn.loopResult()));
  }
  system_.realize(s, SimTK::Stage::Acceleration);
  return s;
}

SimTK::State MultibodyModel::initialState() const {
  return assembledState(scene_.initial.crank_angle, scene_.initial.crank_speed, scene_.initial.twist);
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
  L.reset(ts);
  L.set(ts, Column::t, s.getTime());
  L.set(ts, Column::phi_motor, phi1);
  L.set(ts, Column::phi_crank, phi2);
  L.set(ts, Column::omega_motor, w1);
  L.set(ts, Column::omega_crank, w2);
  L.set(ts, Column::eps_crank, e2);
  L.set(ts, Column::eps_motor, e1);
  L.set(ts, Column::twist, twist);
  L.set(ts, Column::twist_rate, twist_rate);
  L.set(ts, Column::twist_accel, twist_accel);
  L.set(ts, Column::coupling_torque, couplingTorque(s, udot));
  L.set(ts, Column::motor_torque, motorTorque(s));
  for (size_t j = 0; j < carts_.size(); ++j) {
    const CartRig& c = carts_[j];
    L.set(ts, Column::x_cart, int(j) + 1, c.x(s));
    L.set(ts, Column::v_cart, int(j) + 1, c.v(s));
    L.set(ts, Column::a_cart, int(j) + 1, udot[c.cart.getFirstUIndex(s)]);
  }
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

void MultibodyModel::observeReactions(const SimTK::State& s, std::vector<double>& re) const {
  const double torque_coupling = couplingTorque(s);
  SimTK::Vector_<SimTK::SpatialVec> reactions;
  matter_.calcMobilizerReactionForces(s, reactions);
  const SimTK::Vector_<SimTK::SpatialVec>& applied = system_.getRigidBodyForces(s, SimTK::Stage::Dynamics);
  const double g = scene_.loads.gravity;
  const ColumnLayout& L = reactions_layout_;
  L.reset(re);
  L.set(re, Column::t, s.getTime());
  for (size_t j = 0; j < carts_.size(); ++j) {
    const int cart = int(j) + 1;
    const CartRig& c = carts_[j];
    const SimTK::MobilizedBodyIndex ic = c.cart.getMobilizedBodyIndex();
    const GuideNormals n = solveGuideNormals(reactions[ic], c.side, scene_.carts.geometry);
    const double friction = friction_force_ ? friction_force_->frictionForce(s, int(j)) : 0.0;
    if (!c.cam.isEmptyHandle()) {
      // Cam drive: the coupler acts on the mobilities [crank, cart] (in that order); Simbody
      // returns constraint forces with the sign opposite to applied forces. The cam force on
      // the cart is horizontal; "F_rod" > 0 pulls the cart towards the shaft, like a rod in
      // tension, and the pusher puts the opposite force on the cam.
      const SimTK::Vector f = c.cam.getConstrainedMobilityForcesAsVector(s);
      const double Fx_on_cart = -f[1];
      setCartReactions(cart, {n.front, n.rear, -c.side * Fx_on_cart, friction, -Fx_on_cart, 0.0}, re);
      continue;
    }
    // Force of the rod on the cart at B from the cart's free body: m·a = applied + guide + rod.
    const double m_cart = c.cart.getBodyMass(s);
    const SimTK::Vec3 a_cart(c.cart.getOneUDot(s, 0), 0, 0);
    const SimTK::Vec3 F_rod_on_cart = m_cart * a_cart - applied[ic][1] - reactions[ic][1];
    // Pin A in ground, and the unit vector B -> A along the rod: tension pulls the cart to A.
    const SimTK::Vec3 p_A = c.crank.findStationLocationInGround(s, c.p_CrankPin);
    const SimTK::Vec3 p_B = c.cart.getBodyOriginLocation(s);
    const SimTK::UnitVec3 e_BA(p_A - p_B);
    // Force of the rod on the crank pin: rod free body m·a_S = F_A + (-F_B) + m·g.
    SimTK::Vec3 F_rod_on_crank = -F_rod_on_cart;
    if (!c.rod.isEmptyHandle()) {
      const SimTK::Vec3 a_S = c.rod.findStationAccelerationInGround(s, SimTK::Vec3(0.5 * c.rod_length, 0, 0));
      F_rod_on_crank += -c.rod_mass * a_S + c.rod_mass * SimTK::Vec3(0, -g, 0);
    }
    setCartReactions(cart, {n.front, n.rear, ~F_rod_on_cart * e_BA, friction, F_rod_on_crank[0], F_rod_on_crank[1]},
                     re);
  }
  const SimTK::Vec3 bearing = reactions[crank_.getMobilizedBodyIndex()][1];
  L.set(re, Column::bearing_x, bearing[0]);
  L.set(re, Column::bearing_y, bearing[1]);
  L.set(re, Column::coupling_torque, torque_coupling);
}

}  // namespace rollerdyn
