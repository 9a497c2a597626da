#include "reduced/ReducedModel.h"

#include "physics/CartReducedInertia.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "analysis/FrictionChecks.h"
#include "physics/CamMotionLaw.h"
#include "motor/BreakdownTorque.h"
#include "motor/MotorColumns.h"
#include "physics/CouplingLaw.h"
#include "motor/SharedMotorLaw.h"
#include "physics/RollerLoads.h"

namespace rollerdyn {

ReducedModel::ReducedModel(const Scene& scene) : ReducedModel(scene, nullptr) {}

namespace {
// The given law, else the scene's motor.model; none without a motor.
std::shared_ptr<const MotorLaw> lawOf(const Scene& scene, std::shared_ptr<const MotorLaw> given) {
  if (!scene.motor.enabled) return nullptr;
  return given ? given : sharedMotorLaw(scene);
}
}  // namespace

ReducedModel::ReducedModel(const Scene& scene, std::shared_ptr<const MotorLaw> law)
    : scene_(scene),
      rigid_(scene.coupling.type == CouplingType::Rigid),
      kinetostatic_(scene.reduced.guide_normals == ReducedGuideNormals::Kinetostatic),
      law_(lawOf(scene, std::move(law))) {
  checkCarts();
  const int n = scene_.carts.count;
  breakdown_torque_ = rollerdyn::motorBreakdownTorque(scene_, law_.get());
  reducer_ = reducerLaw(scene_, breakdown_torque_);
  coupling_ = couplingLaw(scene_);
  reduceInertias();
  if (!rigid_ && !(J_n1_ > 0.0))
    throw std::invalid_argument("reduced model: elastic coupling needs a motor-side inertia J_n1 > 0");
  if (motorStateCount() > ModelEvaluation::kMaxMotorStates)
    throw std::invalid_argument("reduced model: the motor law has more states than the model carries");
  supply_ = scene_.motor.enabled ? makeSupply(scene_, law_.get()) : Supply();
  initial_phase_ = supply_.initialPhase();
  loop_carts_.resize(n);
  loop_friction_.resize(n);
  loop_normals_.resize(2 * n);
  layOutColumns();
}

void ReducedModel::checkCarts() const {
  const int n = scene_.carts.count;
  if (n < 1) throw std::invalid_argument("reduced model: carts.count must be >= 1");
  if (static_cast<int>(scene_.carts.side.size()) != n)
    throw std::invalid_argument("reduced model: carts.sides must list one side per cart (" +
                                std::to_string(n) + ")");
  // Checks r > 0, l > r and σ = ±1 once, so the right-hand side never throws.
  for (int j = 0; j < n; ++j) cartPose(j, 0.0);
}

void ReducedModel::reduceInertias() {
  const int n = scene_.carts.count;
  J_n1_ = scene_.motorSideInertia();  // Loveikin, Pochka, Romasevych (2018) eq. (1)
  J_crank_ = scene_.crankSideInertia();
  if (scene_.rods.model == RodModel::Split) {
    // Loveikin, Pochka, Romasevych (2018) eq. (2): J_K = n·J'_K + n·(m_rod/2)·r²
    const double r = scene_.crank.radius;
    J_crank_ += n * 0.5 * scene_.rods.mass * r * r;
  }
  for (int j = 0; j < n; ++j) {
    m_B_.push_back(scene_.cartMassWithRodShare(j));  // Loveikin, Pochka, Romasevych (2018) eq. (3)
    loads_.push_back(scene_.cartLoads(j));
  }
}

void ReducedModel::layOutColumns() {
  WrittenColumns written;
  written.multibody = false;
  written.carts = scene_.carts.count;
  addMotorColumns(law_.get(), supply_, written);
  written.reducer_losses = integratesReducerLosses();
  written.backlash = coupling_.hasBacklash();
  timeseries_layout_ = ColumnLayout(OutputFile::Timeseries, written);
  reactions_layout_ = ColumnLayout(OutputFile::Reactions, written);
}

double ReducedModel::rotorSpeed(const double* y) const {
  return (y[iOmega()] + (rigid_ ? 0.0 : y[iTwistRate()])) * scene_.reducer.ratio;
}

std::string ReducedModel::guideNormalsDescription() const { return rollerdyn::guideNormalsDescription(scene_, true); }

void ReducedModel::rodLoadAtHinge(int j, const SliderCrankPose& p, double w, double& V0, double& V1) const {
  V0 = V1 = 0.0;
  if (scene_.rods.model != RodModel::Distributed) return;  // split: in m_B; massless: none
  // Rod moment balance about the crank pin A (a moving point): with F_c = F·(B->A)/l + (0, -V)
  // the rod's force on the cart, (r_AB × F_c)_z = -Δx·V and
  //   (r_AB × F_c)_z = (r_AS × m·(g - a_S))_z - I_S·ψ̈,   r_AS = r_AB/2 = (Δx, Δy)/2,
  // a_S = (x_S''·ω² + x_S'·ε, y_S''·ω² + y_S'·ε), ψ̈ = -σ·(β''·ω² + β'·ε) (SliderCrank.h).
  // Quasi-statically V = m·g/2, the half weight of CartStatics.h.
  const double m = scene_.rods.mass, I = scene_.rods.inertia_com, g = scene_.loads.gravity;
  const double sigma = scene_.carts.side[j];
  const double l = scene_.rods.length;
  const double dx = sigma * l * std::cos(p.beta), dy = -l * std::sin(p.beta);
  const double w2 = w * w;
  // RHS(ε) = m·[-(Δx/2)·(g + a_Sy) + (Δy/2)·a_Sx] - I·ψ̈, affine in ε.
  const double rhs0 = m * (-(0.5 * dx) * (g + p.d2y_S * w2) + 0.5 * dy * p.d2x_S * w2) + I * sigma * p.d2beta * w2;
  const double rhs1 = m * (-(0.5 * dx) * p.dy_S + 0.5 * dy * p.dx_S) + I * sigma * p.dbeta;
  V0 = -rhs0 / dx;
  V1 = -rhs1 / dx;
}

CartStaticsResult ReducedModel::kinetostaticStatics(int j, const CartEvaluation& c, double w, double eps,
                                                    double friction_world) const {
  const double sigma = scene_.carts.side[j];
  double V0 = 0, V1 = 0;
  rodLoadAtHinge(j, c.pose, w, V0, V1);
  // d'Alembert force of the cart along local x': -m_B·σ·(x_B''·ω² + x_B'·ε).
  const double Fin = -m_B_[j] * sigma * (c.pose.d2x_B * w * w + c.pose.dx_B * eps);
  const double V = V0 + V1 * eps;
  CartStaticsResult r = cartStaticsWithFriction(scene_, j, c.pose.beta, c.roller_force, sigma * friction_world, Fin, V);
  // F_rod as reactions.csv defines it for both models: the rod's force on the cart along B -> A,
  // (-cos β, sin β) locally; of the rod's vertical load -V that is -V·sin β.
  r.F_rod -= V * std::sin(c.pose.beta);
  return r;
}

void ReducedModel::loopTerms(int j, const CartEvaluation& c, double w, GuideLoopCart& t) const {
  // cartStaticsWithFriction is affine in (friction, ε): its value and two unit differences.
  const CartStaticsResult base = kinetostaticStatics(j, c, w, 0.0, 0.0);
  const CartStaticsResult at_eps = kinetostaticStatics(j, c, w, 1.0, 0.0);
  const CartStaticsResult at_friction = kinetostaticStatics(j, c, w, 0.0, 1.0);
  t.n0[0] = base.N_front;
  t.n0[1] = base.N_rear;
  t.n_eps[0] = at_eps.N_front - base.N_front;
  t.n_eps[1] = at_eps.N_rear - base.N_rear;
  t.n_F[0] = at_friction.N_front - base.N_front;
  t.n_F[1] = at_friction.N_rear - base.N_rear;
  const double sigma = scene_.carts.side[j];
  t.c = sigma * frictionDirection(loads_[j], c.v_local) * loads_[j].guide_friction;  // world x
  t.w = c.pose.dx_B;  // divided by the crank equation's inertia by the caller
}

SliderCrankPose ReducedModel::cartPose(int j, double phi) const {
  const double theta = phi + scene_.crankPhase(j);
  if (scene_.hasCamDrive())  // Loveikin and Pochka (cam drive paper) eq. (32)-(34): x(θ) replaces the slider-crank
    return camDrivePose(theta, scene_.cam.stroke, scene_.carts.side[j]);
  const double r = scene_.crank.radius, l = scene_.rods.length;
  const int side = scene_.carts.side[j];
  return scene_.reduced.kinematics == KinematicsForm::Truncated
             ? sliderCrankTruncated(theta, r, l, side)   // Loveikin, Pochka, Romasevych (2018) eq. (52)-(57)
             : sliderCrankExact(theta, r, l, side);      // Loveikin, Pochka, Romasevych (2018) eq. (40)-(47)
}

// One cart's share of J_n2(φ) and of dJ_n2/dφ: Loveikin, Pochka, Romasevych (2018) eq. (9) (cart, x_B'²) + the rod terms of
// Loveikin and Pochka (2007) eq. (9) (distributed rod: centre-of-mass speed and rotation), and their φ-derivatives
// (Loveikin, Pochka, Romasevych (2018) eq. (38), analytic).
double ReducedModel::cartInertia(int j, const SliderCrankPose& p) const {
  return cartReducedInertia(m_B_[j], scene_.rods, p);
}

double ReducedModel::cartInertiaDerivative(int j, const SliderCrankPose& p) const {
  double dJ = 2.0 * m_B_[j] * p.dx_B * p.d2x_B;
  if (scene_.rods.model == RodModel::Distributed)
    dJ += 2.0 * scene_.rods.mass * (p.dx_S * p.d2x_S + p.dy_S * p.d2y_S) +
          2.0 * scene_.rods.inertia_com * p.dbeta * p.d2beta;
  return dJ;
}

// Torque of the rod's weight about the crank axis for one cart [N·m].
double ReducedModel::rodGravityTorque(const SliderCrankPose& p, double theta) const {
  const double g = scene_.loads.gravity, m = scene_.rods.mass;
  if (!(g > 0.0)) return 0.0;
  if (scene_.rods.model == RodModel::Distributed) return m * g * p.dy_S;  // Loveikin and Pochka (2007) eq. (5)
  if (scene_.rods.model == RodModel::Split)
    return 0.5 * m * g * scene_.crank.radius * std::cos(theta);  // pin half-mass
  return 0.0;
}

double ReducedModel::crankSideInertia(double phi) const {
  double J = J_crank_;
  for (int j = 0; j < cartCount(); ++j) J += cartInertia(j, cartPose(j, phi));
  return J;
}

double ReducedModel::crankSideInertiaDerivative(double phi) const {
  double dJ = 0.0;
  for (int j = 0; j < cartCount(); ++j) dJ += cartInertiaDerivative(j, cartPose(j, phi));
  return dJ;
}

double ReducedModel::reducedInertia(double phi) const {
  return (rigid_ ? J_n1_ : 0.0) + crankSideInertia(phi);
}

double ReducedModel::reducedInertiaDerivative(double phi) const {
  return crankSideInertiaDerivative(phi);
}

double ReducedModel::motorTorque(double omega_motor) const {
  if (!scene_.motor.enabled) return 0.0;
  const double u = scene_.reducer.ratio;
  // Loveikin, Pochka, Romasevych (2018) eq. (37) / Loveikin and Pochka (2007) eq. (7)-(8), in the singularity-free form of KlossMotor.h
  return reducerCrankTorque(reducer_, law_->steadyTorque(SupplyState{}, omega_motor * u), omega_motor);
}

CartEvaluation ReducedModel::cartKinematics(int j, double phi, double omega) const {
  CartEvaluation c;
  const int sigma = scene_.carts.side[j];
  c.theta = phi + scene_.crankPhase(j);
  c.pose = cartPose(j, phi);
  c.v_local = sigma * c.pose.dx_B * omega;                        // v' = σ·ẋ_B
  c.roller_force = rollerHorizontalForce(loads_[j], c.v_local);  // H along local +x'
  return c;
}

CartEvaluation ReducedModel::evaluateCart(int j, double phi, double omega, double Fin) const {
  CartEvaluation c = cartKinematics(j, phi, omega);
  const int sigma = scene_.carts.side[j];
  const double phi_f = frictionDirection(loads_[j], c.v_local);
  c.statics = solveCartStatics(scene_, j, c.pose.beta, c.roller_force, phi_f, Fin);
  // Virtual work in world x: the local force (H + friction) is σ·(H + friction) in world x.
  c.generalized_force = sigma * (c.roller_force + c.statics.friction) * c.pose.dx_B;
  return c;
}

double ReducedModel::loadTorque(double phi, double omega, std::vector<CartEvaluation>* carts) const {
  double M = 0.0;
  if (carts) carts->clear();
  for (int j = 0; j < cartCount(); ++j) {
    CartEvaluation c = evaluateCart(j, phi, omega, 0.0);  // quasi-static friction
    M += rodGravityTorque(c.pose, c.theta) - c.generalized_force;
    if (carts) carts->push_back(c);
  }
  return M;
}

double ReducedModel::gravityPotential(double phi) const {
  const double g = scene_.loads.gravity;
  if (!(g > 0.0)) return 0.0;
  double V = 0.0;
  for (int j = 0; j < cartCount(); ++j) {
    const double theta = phi + scene_.crankPhase(j);
    if (scene_.rods.model == RodModel::Distributed)
      V += scene_.rods.mass * g * cartPose(j, phi).y_S;
    else if (scene_.rods.model == RodModel::Split)
      V += 0.5 * scene_.rods.mass * g * scene_.crank.radius * std::sin(theta);
  }
  return V;
}

Eigen::VectorXd ReducedModel::initialState() const {
  Eigen::VectorXd y = Eigen::VectorXd::Zero(stateSize());
  y(iPhi()) = scene_.initial.crank_angle;
  y(iOmega()) = scene_.initial.crank_speed;
  if (!rigid_) {
    y(iTwist()) = scene_.initial.twist;
    y(iTwistRate()) = 0.0;  // motor starts at the same reduced speed (Scene.h)
  }
  if (motorStateCount() > 0) {
    const double w_r = rotorSpeed(y.data());
    law_->initialState(supply_.state(initial_phase_, 0.0, w_r), w_r, motorSteadyAtStart(scene_, supply_),
                       y.data() + iMotorStates());
  }
  return y;
}

ModelEvaluation ReducedModel::evaluate(const Eigen::VectorXd& y) const {
  ModelEvaluation e;
  evaluate(y.data(), e, true);
  return e;
}

Eigen::VectorXd ReducedModel::derivatives(double /*t*/, const Eigen::VectorXd& y) const {
  Eigen::VectorXd d(stateSize());
  if (!derivatives(y.data(), d.data())) d.setConstant(std::nan(""));  // void: a cart locks
  return d;
}

void ReducedModel::evaluate(const double* y, ModelEvaluation& e, bool keep_carts) const {
  evaluate(0.0, initial_phase_, y, e, keep_carts);
}

bool ReducedModel::derivatives(const double* y, double* d) const { return derivatives(0.0, initial_phase_, y, d); }

namespace {

// The state's crank angle and speed, the coupling's twist and its rate (none in a rigid drive),
// the motor's speed; the evaluation's friction results reset.
void readState(const ReducedModel& m, const double* y, ModelEvaluation& e) {
  e.phi_crank = y[m.iPhi()];
  e.omega_crank = y[m.iOmega()];
  e.twist = m.rigid() ? 0.0 : y[m.iTwist()];
  e.twist_rate = m.rigid() ? 0.0 : y[m.iTwistRate()];
  e.omega_motor = e.omega_crank + e.twist_rate;
  e.friction_loop = GuideLoopResult{};
  e.friction_power_kinetostatic = 0.0;
}

// The powers of the motor, the brake (both at the motor's speed), the guide friction and the load.
void recordPowers(double P_friction, double P_load, ModelEvaluation& e) {
  e.motor_power = e.motor_torque * e.omega_motor;
  e.brake_power = -e.brake_torque * e.omega_motor;
  e.friction_power = P_friction;
  e.load_power = P_load;
}

}  // namespace

void ReducedModel::evaluate(double t, const SupplyPhase& phase, const double* y, ModelEvaluation& e,
                            bool keep_carts) const {
  readState(*this, y, e);
  // One pass over the carts, each cart's pose computed once (crankSideInertia(),
  // crankSideInertiaDerivative() and loadTorque() would compute it three times), from the same
  // per-cart terms those functions sum. Quasi-static normals: the friction is known per cart
  // (CartStatics.h); kinetostatic: solveCrankEquation() finds it with the crank acceleration.
  const CartPass& pass = cartPass(e.phi_crank, e.omega_crank);
  recordCartPass(pass, keep_carts, e);
  evaluateMotor(t, phase, y, e);
  solveCrankEquation(pass, e);
  if (kinetostatic_ && keep_carts) kinetostaticCarts(pass, e);
  if (checksFrictionWork()) e.friction_power_kinetostatic = kinetostaticFrictionPower(pass, e);
}

void ReducedModel::recordCartPass(const CartPass& pass, bool keep_carts, ModelEvaluation& e) const {
  e.friction_loop = pass.locked;
  e.carts.clear();  // keeps its capacity
  if (keep_carts && !kinetostatic_) e.carts.insert(e.carts.end(), pass.carts.begin(), pass.carts.end());
  e.J_n2 = pass.J;
  e.dJ_n2 = pass.dJ;
}

void ReducedModel::solveCrankEquation(const CartPass& pass, ModelEvaluation& e) const {
  const double M_drive = e.motor_torque + e.brake_torque;  // on the motor side, at the crank axis
  // The crank equation's inertia and its right-hand side without the load torque.
  const double J_eq = rigid_ ? J_n1_ + pass.J : pass.J;
  const CouplingTorque coupling = rigid_ ? CouplingTorque{} : couplingTorque(coupling_, e.twist, e.twist_rate);
  const double drive = rigid_ ? M_drive : coupling.torque;
  double M = pass.M, P_friction = pass.P_friction;
  if (kinetostatic_ && scene_.hasGuideFriction()) solveFrictionLoop(pass, J_eq, drive, e, M, P_friction);
  e.load_torque = M;
  drivetrainAccelerations(M_drive, drive, coupling, e);
  recordPowers(P_friction, pass.P_load, e);
}

void ReducedModel::solveFrictionLoop(const CartPass& pass, double J_eq, double drive, ModelEvaluation& e, double& M,
                                     double& P_friction) const {
  // The friction loop (physics/GuideFrictionLoop.h): ε = ε0 + Σ_j (x_B'_j/J)·F_j, F_j the
  // friction along world x, whose generalized force on φ2 is F_j·x_B'_j.
  const int n = cartCount();
  const double w2 = e.omega_crank;
  for (int j = 0; j < n; ++j) {
    loop_carts_[j] = pass.loop[j];
    loop_carts_[j].w /= J_eq;
  }
  const double eps0 = (drive - M - 0.5 * pass.dJ * w2 * w2) / J_eq;
  e.friction_loop = solveGuideFrictionLoop(loop_carts_.data(), n, eps0, loop_friction_.data(), loop_normals_.data());
  if (e.friction_loop.status != LoopStatus::Solved) std::fill(loop_friction_.begin(), loop_friction_.end(), 0.0);
  for (int j = 0; j < n; ++j) {
    const double dx = pass.carts[j].pose.dx_B;
    M -= loop_friction_[j] * dx;
    P_friction -= loop_friction_[j] * dx * w2;
  }
}

void ReducedModel::drivetrainAccelerations(double M_drive, double drive, const CouplingTorque& coupling,
                                           ModelEvaluation& e) const {
  const double w2 = e.omega_crank;
  if (rigid_) {
    // Loveikin and Pochka (2007) eq. (1) in time form: J·φ̈ = M_p - M_o - ½·J'·φ̇²
    e.eps_crank = (M_drive - e.load_torque - 0.5 * e.dJ_n2 * w2 * w2) / (J_n1_ + e.J_n2);
    e.eps_motor = e.eps_crank;
    e.twist_accel = 0.0;
    // Torque the rigid coupling passes to the crank side: what the motor gives minus what the
    // motor-side inertia takes.
    e.coupling_torque = M_drive - J_n1_ * e.eps_crank;
    e.damping_power = 0.0;
  } else {
    // Loveikin, Pochka, Romasevych (2018) eq. (58), the coupling's law physics/CouplingLaw.h
    e.coupling_torque = drive;
    e.eps_motor = (M_drive - e.coupling_torque) / J_n1_;
    e.eps_crank = (e.coupling_torque - e.load_torque - 0.5 * e.dJ_n2 * w2 * w2) / e.J_n2;
    e.twist_accel = e.eps_motor - e.eps_crank;
    e.damping_power = coupling.damping_power;
  }
}

void ReducedModel::kinetostaticCarts(const CartPass& pass, ModelEvaluation& e) const {
  // The reactions of this instant: the cart statics at the crank acceleration just found.
  const bool friction = scene_.hasGuideFriction();
  for (int j = 0; j < cartCount(); ++j) {
    CartEvaluation c = pass.carts[j];
    const double F_world = friction ? loop_friction_[j] : 0.0;
    c.statics = kinetostaticStatics(j, c, e.omega_crank, e.eps_crank, F_world);
    c.generalized_force = scene_.carts.side[j] * (c.roller_force + c.statics.friction) * c.pose.dx_B;
    e.carts.push_back(c);
  }
}

double ReducedModel::kinetostaticFrictionPower(const CartPass& pass, const ModelEvaluation& e) const {
  // Each cart's loop at fixed ε (w = 0): the friction power behind the run's friction-work check.
  const int n = cartCount();
  for (int j = 0; j < n; ++j) {
    loop_carts_[j] = pass.loop[j];
    loop_carts_[j].w = 0.0;
  }
  const GuideLoopResult r =
      solveGuideFrictionLoop(loop_carts_.data(), n, e.eps_crank, loop_friction_.data(), loop_normals_.data());
  double P = 0.0;
  for (int j = 0; j < n; ++j) P -= loop_friction_[j] * pass.carts[j].pose.dx_B * e.omega_crank;
  return r.status == LoopStatus::Solved ? P : std::nan("");
}

void ReducedModel::evaluateMotor(double t, const SupplyPhase& phase, const double* y, ModelEvaluation& e) const {
  e.brake_torque = 0.0;
  e.stator_current = MotorEvaluation::kNotModelled;
  if (!scene_.motor.enabled) {
    e.motor_torque = 0.0;
    return;
  }
  const double u = scene_.reducer.ratio;
  const double w_r = e.omega_motor * u;
  e.supply = supply_.state(phase, t, w_r);
  e.brake_torque = reducerCrankTorque(reducer_, supply_.brakeTorque(phase, w_r), e.omega_motor);
  MotorEvaluation out;
  law_->evaluate(e.supply, w_r, y + iMotorStates(), out, motorStateCount() > 0 ? e.motor_state_rates.data() : nullptr);
  e.motor_torque = reducerCrankTorque(reducer_, out.torque, e.omega_motor);
  e.reducer_loss_torque = reducerLossTorque(reducer_, out.torque, e.omega_motor);
  e.reducer_loss_power = e.reducer_loss_torque * e.omega_motor;
  e.stator_current = out.stator_current;
}

bool ReducedModel::derivatives(double t, const SupplyPhase& phase, const double* y, double* d) const {
  ModelEvaluation e;  // carts stays empty: no allocation
  evaluate(t, phase, y, e, false);
  d[iPhi()] = e.omega_crank;
  d[iOmega()] = e.eps_crank;
  if (!rigid_) {
    d[iTwist()] = e.twist_rate;
    d[iTwistRate()] = e.twist_accel;
    d[iDampingWork()] = e.damping_power;
  }
  d[iMotorWork()] = e.motor_power;
  d[iFrictionWork()] = e.friction_power;
  d[iLoadWork()] = e.load_power;
  if (checksFrictionWork()) d[iFrictionWorkKinetostatic()] = e.friction_power_kinetostatic;
  if (iBrakeWork() >= 0) d[iBrakeWork()] = e.brake_power;
  if (iReducerLosses() >= 0) d[iReducerLosses()] = e.reducer_loss_power;
  for (int i = 0; i < motorStateCount(); ++i) d[iMotorStates() + i] = e.motor_state_rates[i];
  return e.friction_loop.status == LoopStatus::Solved;
}

double ReducedModel::kineticEnergy(const Eigen::VectorXd& y) const {
  const double phi = y(iPhi()), w2 = y(iOmega());
  if (rigid_) return 0.5 * (J_n1_ + crankSideInertia(phi)) * w2 * w2;
  const double w1 = w2 + y(iTwistRate());
  return 0.5 * J_n1_ * w1 * w1 + 0.5 * crankSideInertia(phi) * w2 * w2;
}

double ReducedModel::potentialEnergy(const Eigen::VectorXd& y) const {
  double V = gravityPotential(y(iPhi()));
  if (!rigid_) V += couplingPotential(coupling_, y(iTwist()));  // Loveikin, Pochka, Romasevych (2018) eq. (34)
  return V;
}

std::vector<CartEvaluation> ReducedModel::cartReactions(double phi, double omega, double eps,
                                                        bool include_inertia) const {
  std::vector<CartEvaluation> out;
  for (int j = 0; j < cartCount(); ++j) {
    double Fin = 0.0;
    if (include_inertia) {
      const SliderCrankPose p = cartPose(j, phi);
      const double a_world = p.d2x_B * omega * omega + p.dx_B * eps;
      Fin = -m_B_[j] * scene_.carts.side[j] * a_world;  // d'Alembert, local x'
    }
    out.push_back(evaluateCart(j, phi, omega, Fin));
  }
  return out;
}

}  // namespace rollerdyn
