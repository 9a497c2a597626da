#include "reduced/ReducedModel.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "physics/CamMotionLaw.h"
#include "physics/KlossMotor.h"
#include "physics/RollerLoads.h"

namespace rollerdyn {

ReducedModel::ReducedModel(const Scene& scene)
    : scene_(scene), rigid_(scene.coupling.type == CouplingType::Rigid) {
  const int n = scene_.carts.count;
  if (n < 1) throw std::invalid_argument("reduced model: carts.count must be >= 1");
  if (static_cast<int>(scene_.carts.side.size()) != n)
    throw std::invalid_argument("reduced model: carts.sides must list one side per cart (" +
                                std::to_string(n) + ")");
  // Checks r > 0, l > r and σ = ±1 once, so the right-hand side never throws.
  for (int j = 0; j < n; ++j) cartPose(j, 0.0);

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
  if (!rigid_ && !(J_n1_ > 0.0))
    throw std::invalid_argument("reduced model: elastic coupling needs a motor-side inertia J_n1 > 0");
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
  double J = m_B_[j] * p.dx_B * p.dx_B;
  if (scene_.rods.model == RodModel::Distributed)
    J += scene_.rods.mass * (p.dx_S * p.dx_S + p.dy_S * p.dy_S) +
         scene_.rods.inertia_com * p.dbeta * p.dbeta;
  return J;
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
  // Loveikin, Pochka, Romasevych (2018) eq. (37) / Loveikin and Pochka (2007) eq. (7)-(8), in the singularity-free form of KlossMotor.h
  return klossCrankTorque(scene_.motor, scene_.reducer.ratio, scene_.reducer.efficiency, omega_motor);
}

CartEvaluation ReducedModel::evaluateCart(int j, double phi, double omega, double Fin) const {
  CartEvaluation c;
  const int sigma = scene_.carts.side[j];
  c.theta = phi + scene_.crankPhase(j);
  c.pose = cartPose(j, phi);
  c.v_local = sigma * c.pose.dx_B * omega;                        // v' = σ·ẋ_B
  c.roller_force = rollerHorizontalForce(loads_[j], c.v_local);  // H along local +x'
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
  return y;
}

ModelEvaluation ReducedModel::evaluate(const Eigen::VectorXd& y) const {
  ModelEvaluation e;
  evaluate(y.data(), e, true);
  return e;
}

Eigen::VectorXd ReducedModel::derivatives(double /*t*/, const Eigen::VectorXd& y) const {
  Eigen::VectorXd d(stateSize());
  derivatives(y.data(), d.data());
  return d;
}

void ReducedModel::evaluate(const double* y, ModelEvaluation& e, bool keep_carts) const {
  e.phi_crank = y[iPhi()];
  e.omega_crank = y[iOmega()];
  e.twist = rigid_ ? 0.0 : y[iTwist()];
  e.twist_rate = rigid_ ? 0.0 : y[iTwistRate()];
  e.omega_motor = e.omega_crank + e.twist_rate;
  const double phi = e.phi_crank, w2 = e.omega_crank;

  // One pass over the carts, each cart's pose computed once (crankSideInertia(),
  // crankSideInertiaDerivative() and loadTorque() would compute it three times), from the same
  // per-cart terms those functions sum.
  double J = J_crank_, dJ = 0.0, M = 0.0, P_friction = 0.0, P_load = 0.0;
  e.carts.clear();  // keeps its capacity
  for (int j = 0; j < cartCount(); ++j) {
    const CartEvaluation c = evaluateCart(j, phi, w2, 0.0);  // quasi-static friction
    const SliderCrankPose& p = c.pose;
    J += cartInertia(j, p);
    dJ += cartInertiaDerivative(j, p);
    M += rodGravityTorque(p, c.theta) - c.generalized_force;
    const double sigma = scene_.carts.side[j];
    const double v = p.dx_B * w2;  // world ẋ_B
    P_friction -= sigma * c.statics.friction * v;
    P_load -= sigma * c.roller_force * v;
    if (keep_carts) e.carts.push_back(c);
  }
  e.J_n2 = J;
  e.dJ_n2 = dJ;
  e.motor_torque = motorTorque(e.omega_motor);
  e.load_torque = M;
  if (rigid_) {
    // Loveikin and Pochka (2007) eq. (1) in time form: J·φ̈ = M_p - M_o - ½·J'·φ̇²
    e.eps_crank = (e.motor_torque - e.load_torque - 0.5 * e.dJ_n2 * w2 * w2) / (J_n1_ + e.J_n2);
    e.eps_motor = e.eps_crank;
    e.twist_accel = 0.0;
    // Torque the rigid coupling passes to the crank side: what the motor gives minus what the
    // motor-side inertia takes.
    e.coupling_torque = e.motor_torque - J_n1_ * e.eps_crank;
    e.damping_power = 0.0;
  } else {
    // Loveikin, Pochka, Romasevych (2018) eq. (58)
    const double c = scene_.coupling.stiffness, k = scene_.coupling.damping;
    e.coupling_torque = c * e.twist + k * e.twist_rate;
    e.eps_motor = (e.motor_torque - e.coupling_torque) / J_n1_;
    e.eps_crank = (e.coupling_torque - e.load_torque - 0.5 * e.dJ_n2 * w2 * w2) / e.J_n2;
    e.twist_accel = e.eps_motor - e.eps_crank;
    e.damping_power = k * e.twist_rate * e.twist_rate;
  }
  e.motor_power = e.motor_torque * e.omega_motor;
  e.friction_power = P_friction;
  e.load_power = P_load;
}

void ReducedModel::derivatives(const double* y, double* d) const {
  ModelEvaluation e;  // carts stays empty: no allocation
  evaluate(y, e, false);
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
}

double ReducedModel::kineticEnergy(const Eigen::VectorXd& y) const {
  const double phi = y(iPhi()), w2 = y(iOmega());
  if (rigid_) return 0.5 * (J_n1_ + crankSideInertia(phi)) * w2 * w2;
  const double w1 = w2 + y(iTwistRate());
  return 0.5 * J_n1_ * w1 * w1 + 0.5 * crankSideInertia(phi) * w2 * w2;
}

double ReducedModel::potentialEnergy(const Eigen::VectorXd& y) const {
  double V = gravityPotential(y(iPhi()));
  if (!rigid_) V += 0.5 * scene_.coupling.stiffness * y(iTwist()) * y(iTwist());  // Loveikin, Pochka, Romasevych (2018) eq. (34)
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
