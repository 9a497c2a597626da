// The papers' reduced-mass ("one-mass" / "two-mass") model of the installation, built from a
// Scene. All torques and angles are reduced to the crank axis.
//
// Rigid coupling, 1 DOF φ (Loveikin and Pochka (2007) eq. (1) in time form):
//   J(φ)·φ̈ + ½·J'(φ)·φ̇² = M_motor(φ̇) - M_load(φ, φ̇),   J = J_n1 + J_n2(φ)
// Elastic coupling, 2 DOF (Loveikin, Pochka, Romasevych (2018) eq. (58), with φ̇2² in the second term: eq. (38) shows the
// printed φ̈2² is a typo):
//   J_n1·φ̈1 = M_n1(φ̇1) - c·(φ1 - φ2) - k·(φ̇1 - φ̇2)
//   J_n2(φ2)·φ̈2 + ½·J_n2'(φ2)·φ̇2² = c·(φ1 - φ2) + k·(φ̇1 - φ̇2) - M_n2(φ2, φ̇2)
// (½·J_n2' = Σ m_Bj·x'_Bj·x''_Bj + rod terms, Loveikin, Pochka, Romasevych (2018) eq. (38).)
//
// J_n1 = Scene::motorSideInertia() (Loveikin, Pochka, Romasevych (2018) eq. (1)); J_n2(φ) = Scene::crankSideInertia() +
// Σ_j [m_B·x_Bj'² + rod terms] (Loveikin, Pochka, Romasevych (2018) eq. (9), Loveikin and Pochka (2007) eq. (9)):
//   distributed rods: m_rod·(x_S'² + y_S'²) + I_com·β'²   (Loveikin and Pochka (2007) eq. (9)), m_B = carts.mass
// (each cart with its own m_B and loads when the scene gives them per cart, docs/per-cart.md)
//   split rods:       m_rod/2·r² at the crank pin (Loveikin, Pochka, Romasevych (2018) eq. (2)), m_B = m'_B + m_rod/2 (eq. (3))
//   massless rods:    nothing
// M_load (resisting torque, Loveikin, Pochka, Romasevych (2018) eq. (30), Loveikin and Pochka (2007) eq. (5)) by virtual work in world x:
//   M_load = -Σ_j σ_j·(H_j + friction_j)·x_Bj' + dV_gravity/dφ
// H_j (local +x') from rollerHorizontalForce(v'_j), friction_j (local) at the local velocity
// v'_j = σ_j·x_Bj'·φ̇ from the guide normal forces of reduced.guide_normals:
//   quasi_static  the papers' cart statics (CartStatics.h, without inertial forces): a function
//                 of φ and φ̇ alone;
//   kinetostatic  the cart statics with the cart's d'Alembert force -m_B·a' and the rod's
//                 inertial load at its hinge (distributed rods: the rod's moment balance about the
//                 crank pin, I_S·ψ̈ + r_AS × m·a_S), at the crank acceleration ε the friction itself
//                 helps determine: the loop of physics/GuideFrictionLoop.h, the law the multibody
//                 model's algebraic normal force uses, solved directly at every evaluation.
// With the quasi-static rod force F_j this equals
// Σ F_j·r·(σ_j·sin θ_j·cos β_j + cos θ_j·sin β_j), i.e. Σ F_j·r·sin(θ_j + β_j) of eq. (26)-(30)
// for σ = +1. Gravity: distributed rods add
// m_rod·g·y_S' (Loveikin and Pochka (2007) eq. (5)), split rods m_rod/2·g·r·cos θ (pin half-mass); carts move
// horizontally and do no gravity work.
//
// Cam drive (scene.drive = cam, Loveikin and Pochka (cam drive paper)): cartPose() returns the cam law x_B = σ·x(θ) and its
// θ-derivatives (physics/CamMotionLaw.h) in place of the slider-crank transfer functions; the
// scene's rods are massless then and β = 0, so every formula above holds unchanged.
//
// State vector (Eigen::VectorXd). The elastic model integrates the twist ψ = φ1 - φ2 instead of
// φ1: φ1 and φ2 grow to hundreds of radians while ψ swings by < 1e-3 rad, so integrating φ1 and
// subtracting would leave ψ with the error of a 300-rad quantity. Same equations, exact change
// of variables. Work integrals ride along as extra states (energy audit, RunResult.h).
//   rigid:   [φ, φ̇, W_motor, W_friction, W_load]
//   elastic: [φ2, φ̇2, ψ, ψ̇, W_motor, W_damping, W_friction, W_load]
// then, only when the scene asks for them: with quasi-static normals and guide friction, the
// friction work the kinetostatic normals would give at the run's own accelerations W_friction_kin
// (the run's friction-work check); the brake's dissipation W_brake (motor.stop.brake_torque); and
// the motor law's own states (MotorLaw.h: none for the static laws).
//
// Motor: the scene's motor law (motor.model) at the rotor, M(supply, ω_r = u·φ̇1, x), fed by the
// starting method's supply (motor/Supply.h) in the run's SupplyPhase; at the crank through the
// reducer's law (reducer.losses, physics/ReducerLosses.h: the papers' M·u·η, Loveikin, Pochka,
// Romasevych (2018) eq. (37), or by the direction of the power flow); a brake torque M_b on the
// motor shaft likewise.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "analysis/RunControl.h"
#include "analysis/RunResult.h"
#include "io/OutputColumns.h"
#include "motor/MotorLaw.h"
#include "motor/Supply.h"
#include "physics/CouplingLaw.h"
#include "physics/GuideFrictionLoop.h"
#include "physics/ReducerLosses.h"
#include "physics/SliderCrank.h"
#include "reduced/CartStatics.h"
#include "scene/Scene.h"

namespace rollerdyn {

// Everything about one cart at one instant of the reduced model.
struct CartEvaluation {
  double theta = 0;          // crank angle of this cart, φ2 + j·Δφ [rad]
  SliderCrankPose pose;      // kinematics (exact or truncated per scene.reduced.kinematics)
  double v_local = 0;        // v' = σ·ẋ_B [m/s]
  double roller_force = 0;   // H, local +x' [N]
  CartStaticsResult statics; // quasi-static rod force, guide reactions, local friction
  double generalized_force = 0;  // σ·(H + friction)·x_B' [N·m]: the loads' torque on φ
};

// The whole right-hand side at one state, with its intermediate quantities.
struct ModelEvaluation {
  double phi_crank = 0, omega_crank = 0, twist = 0, twist_rate = 0, omega_motor = 0;
  double J_n2 = 0, dJ_n2 = 0;     // crank-side reduced inertia and its φ-derivative
  double motor_torque = 0;        // M_n1 at the crank axis, passed on by the reducer [N·m]
  double reducer_loss_torque = 0; // the reducer's loss torque on the motor's torque, at the crank
                                  // axis [N·m] (physics/ReducerLosses.h)
  double reducer_loss_power = 0;  // its power L·φ̇1 [W]
  double brake_torque = 0;        // mechanical brake on the motor shaft, at the crank axis [N·m]
  double stator_current = 0;      // RMS stator phase current [A]; NaN when the law has none
  SupplyState supply;             // what the starting method applies (motor/Supply.h)
  double brake_power = 0;         // -M_brake·φ̇1 ≥ 0, dissipated in the brake [W]
  static constexpr int kMaxMotorStates = 8;
  std::array<double, kMaxMotorStates> motor_state_rates{};  // the motor law's dx/dt
  double load_torque = 0;         // M_load [N·m] (rollers + friction + gravity)
  double coupling_torque = 0;     // elastic: c·ψ + k·ψ̇; rigid: M_motor - J_n1·φ̈
  double eps_crank = 0, eps_motor = 0, twist_accel = 0;
  double motor_power = 0;         // M_n1·φ̇1
  double damping_power = 0;       // k·ψ̇² ≥ 0
  double friction_power = 0;      // -Σ friction·v (≥ 0 when friction opposes v)
  double load_power = 0;          // -Σ H·v, power given to the concrete
  // Quasi-static normals with friction: -Σ friction·v with the kinetostatic normals at eps_crank
  // [W]; 0 otherwise.
  double friction_power_kinetostatic = 0;
  // Solved, unless the guide friction locks a cart or its loop has no solution (the evaluation's
  // accelerations are then void): physics/GuideFrictionLoop.h.
  GuideLoopResult friction_loop;
  std::vector<CartEvaluation> carts;
};

class ReducedModel {
 public:
  // Validates the kinematic preconditions (std::invalid_argument on a bad scene).
  explicit ReducedModel(const Scene& scene);
  // With a given motor law (instead of the scene's motor.model; null: the scene's), e.g. a law
  // written in a test.
  ReducedModel(const Scene& scene, std::shared_ptr<const MotorLaw> law);

  const Scene& scene() const { return scene_; }
  bool rigid() const { return rigid_; }
  int cartCount() const { return scene_.carts.count; }
  int stateSize() const {
    return mechanicalSize() + (checksFrictionWork() ? 1 : 0) + (supply_.hasBrake() ? 1 : 0) +
           (integratesReducerLosses() ? 1 : 0) + motorStateCount();
  }
  // reducer.losses = power_flow: the reducer's losses ride along as a work state W_reducer and
  // the timeseries carries reducer_loss_torque (under the papers' η they are (1/η − 1)·W_motor).
  bool integratesReducerLosses() const { return scene_.motor.enabled && reducer_.model == ReducerLossModel::PowerFlow; }
  const ReducerLaw& reducer() const { return reducer_; }
  const CouplingLaw& coupling() const { return coupling_; }
  // reduced.guide_normals = kinetostatic (with guide friction: the loop is solved).
  bool kinetostatic() const { return kinetostatic_; }
  // Quasi-static normals with guide friction: the kinetostatic friction work is integrated too.
  bool checksFrictionWork() const { return !kinetostatic_ && scene_.hasGuideFriction(); }

  // State indices (-1 where the model has no such state).
  int iPhi() const { return 0; }
  int iOmega() const { return 1; }
  int iTwist() const { return rigid_ ? -1 : 2; }
  int iTwistRate() const { return rigid_ ? -1 : 3; }
  int iMotorWork() const { return rigid_ ? 2 : 4; }
  int iDampingWork() const { return rigid_ ? -1 : 5; }
  int iFrictionWork() const { return rigid_ ? 3 : 6; }
  int iLoadWork() const { return rigid_ ? 4 : 7; }
  int iFrictionWorkKinetostatic() const { return checksFrictionWork() ? mechanicalSize() : -1; }
  int iBrakeWork() const { return supply_.hasBrake() ? mechanicalSize() + (checksFrictionWork() ? 1 : 0) : -1; }
  int iReducerLosses() const {
    return integratesReducerLosses() ? mechanicalSize() + (checksFrictionWork() ? 1 : 0) + (supply_.hasBrake() ? 1 : 0)
                                     : -1;
  }
  int iMotorStates() const {  // first of them
    return mechanicalSize() + (checksFrictionWork() ? 1 : 0) + (supply_.hasBrake() ? 1 : 0) +
           (integratesReducerLosses() ? 1 : 0);
  }
  int motorStateCount() const { return law_ ? law_->stateCount() : 0; }

  // The motor law (null without a motor) and the supply of the scene's starting method.
  const MotorLaw* motorLaw() const { return law_.get(); }
  const Supply& supply() const { return supply_; }
  // The columns this model writes (io/OutputColumns.h: units, meanings) and where each value of
  // a row goes.
  const ColumnLayout& timeseriesLayout() const { return timeseries_layout_; }
  const ColumnLayout& reactionsLayout() const { return reactions_layout_; }
  // Rotor speed ω_r = u·φ̇1 [rad/s] of state y.
  double rotorSpeed(const double* y) const;

  // Kinematics of cart j (0-based) at crank angle φ2 of cart 1.
  SliderCrankPose cartPose(int j, double phi_crank) const;

  // J_n1 [kg·m²] (Loveikin, Pochka, Romasevych (2018) eq. (1)).
  double motorSideInertia() const { return J_n1_; }
  // M_kr of the motor law the model runs [N·m at the rotor] (motor/BreakdownTorque.h).
  double motorBreakdownTorque() const { return breakdown_torque_; }
  // J_n2(φ) and dJ_n2/dφ (analytic, from the slider-crank second derivatives).
  double crankSideInertia(double phi) const;
  double crankSideInertiaDerivative(double phi) const;
  // The inertia multiplying φ̈ of the crank equation: rigid J_n1 + J_n2(φ); elastic J_n2(φ).
  double reducedInertia(double phi) const;
  double reducedInertiaDerivative(double phi) const;

  // Motor torque at the crank axis under the rated supply (the static laws' torque-speed
  // curve; a law with states at rest), 0 when the motor is disabled.
  double motorTorque(double omega_motor) const;
  // Resisting torque M_load(φ, φ̇) [N·m]; fills per-cart details when carts != nullptr.
  double loadTorque(double phi, double omega, std::vector<CartEvaluation>* carts = nullptr) const;
  // Gravity potential of the rods relative to y = 0 [J].
  double gravityPotential(double phi) const;

  Eigen::VectorXd initialState() const;
  ModelEvaluation evaluate(const Eigen::VectorXd& y) const;
  Eigen::VectorXd derivatives(double t, const Eigen::VectorXd& y) const;
  // The same two for the integrators' inner loops (the overloads above call these): y and dydt
  // point to stateSize() doubles. Nothing is allocated: e.carts is filled only when carts is
  // true (and left empty otherwise), reusing its capacity when the same ModelEvaluation is
  // passed again.
  void evaluate(const double* y, ModelEvaluation& e, bool carts) const;
  // False when the evaluation is void (e.friction_loop not solved: a cart locks).
  bool derivatives(const double* y, double* dydt) const;
  // The same at time t in supply phase p (the overloads above: the phase at t = 0, enough for a
  // constant supply).
  void evaluate(double t, const SupplyPhase& p, const double* y, ModelEvaluation& e, bool carts) const;
  bool derivatives(double t, const SupplyPhase& p, const double* y, double* dydt) const;
  // Kinetic ½J_n1φ̇1² + ½J_n2φ̇2² (rigid: ½Jφ̇²) and potential ½cψ² + rod gravity [J].
  double kineticEnergy(const Eigen::VectorXd& y) const;
  double potentialEnergy(const Eigen::VectorXd& y) const;

  // The guide normal forces in words, for every reduced result (RunResult::guide_normals).
  std::string guideNormalsDescription() const;

  // Cart reactions at crank angle φ, speed φ̇ and acceleration φ̈. include_inertia = false: the
  // quasi-static reactions of Loveikin, Pochka, Romasevych (2018) eq. (14)-(25) (what the equations of motion use);
  // true: kinetostatic, with the d'Alembert force -m_B·a' of each cart (closer to what a
  // multibody model's constraint forces show).
  std::vector<CartEvaluation> cartReactions(double phi, double omega, double eps,
                                            bool include_inertia) const;

  // Passes over the carts computed so far by evaluate()/derivatives(): one per new (φ2, φ̇2); an
  // evaluation at one of the last three is served from it (what the cost of a Jacobian counts).
  long cartPassesComputed() const { return cart_passes_computed_; }

 private:
  // The carts' count, sides and geometry, checked once (std::invalid_argument) so that the
  // right-hand side never throws.
  void checkCarts() const;
  // J_n1, J_K and the carts' masses m_B with their loads (Loveikin, Pochka, Romasevych (2018)
  // eq. (1)-(3)).
  void reduceInertias();
  // The timeseries and reactions columns this model writes.
  void layOutColumns();
  CartEvaluation cartKinematics(int j, double phi, double omega) const;  // pose, v', H (no statics)
  CartEvaluation evaluateCart(int j, double phi, double omega, double inertial_force) const;
  double cartInertia(int j, const SliderCrankPose& p) const;            // cart j's share of J_n2 [kg·m²]
  double cartInertiaDerivative(int j, const SliderCrankPose& p) const;  // its dJ/dφ [kg·m²/rad]
  double rodGravityTorque(const SliderCrankPose& p, double theta) const;  // [N·m]
  // Vertical load of cart j's rod on the cart at B, downward, V = V0 + V1·ε (kinetostatic;
  // CartStatics.h): the rod's moment balance about the crank pin.
  void rodLoadAtHinge(int j, const SliderCrankPose& p, double omega, double& V0, double& V1) const;
  // Fills the loop terms of cart j (kinetostatic normals) for φ̇ = omega, and w_per_J = x_B'.
  void loopTerms(int j, const CartEvaluation& c, double omega, GuideLoopCart& t) const;
  // Kinetostatic statics of cart j at ε with its friction along world x.
  CartStaticsResult kinetostaticStatics(int j, const CartEvaluation& c, double omega, double eps,
                                        double friction_world) const;

  int mechanicalSize() const { return rigid_ ? 5 : 8; }
  // Motor and brake torque at the crank, stator current, supply and the law's state rates into e
  // (e.omega_motor set).
  void evaluateMotor(double t, const SupplyPhase& phase, const double* y, ModelEvaluation& e) const;

  Scene scene_;
  bool rigid_;
  bool kinetostatic_;                    // reduced.guide_normals = kinetostatic
  std::shared_ptr<const MotorLaw> law_;  // null without a motor
  Supply supply_;
  SupplyPhase initial_phase_;
  ReducerLaw reducer_;  // reducer.losses (physics/ReducerLosses.h)
  CouplingLaw coupling_;  // coupling.* and reducer.backlash (physics/CouplingLaw.h); elastic only
  double J_n1_;       // motor side, Loveikin, Pochka, Romasevych (2018) eq. (1)
  double breakdown_torque_ = 0;  // M_kr of the law the model runs [N·m at the rotor]
  double J_crank_;    // crankshaft without rods + split pin half-masses (Loveikin, Pochka, Romasevych (2018) eq. (2))
  std::vector<double> m_B_;   // per cart: mass used with x_B', Loveikin, Pochka, Romasevych (2018) eq. (3)
  std::vector<Loads> loads_;  // per cart: the loads acting on it (Scene::cartLoads)
  // Scratch of the friction loop, reused by every evaluation (the model is used by one thread).
  mutable std::vector<GuideLoopCart> loop_carts_;
  mutable std::vector<double> loop_friction_, loop_normals_;

  // The pass over the carts at one crank angle and speed (φ2, φ̇2): their kinematics, loads and
  // inertia terms depend on nothing else. Finite-difference Jacobians (the modal analysis'
  // variational equations, CVODE's Newton matrix) evaluate the model at the same (φ2, φ̇2) with
  // other twists, twist rates and motor states; the last three passes are kept (the point and its
  // two speed perturbations) and reused when both values match bit for bit (CartPass.cpp).
  struct CartPass {
    double phi = 0, omega = 0;
    bool valid = false;
    double J = 0, dJ = 0, M = 0, P_friction = 0, P_load = 0;  // sums over the carts, J from J_crank_
    GuideLoopResult locked;               // quasi-static normals: the first cart that locks
    std::vector<CartEvaluation> carts;    // every cart
    std::vector<GuideLoopCart> loop;      // loopTerms() of every cart (w = x_B', not yet /J) when used
  };
  const CartPass& cartPass(double phi, double omega) const;
  // The pass's sums over the carts at (φ2, ω2): J, dJ/dφ, the carts' torque M, the friction and
  // load powers, the carts' evaluations and the first self-locking cart.
  void sumOverCarts(CartPass& pass, double phi, double omega) const;
  // The pass's crank-side inertia, its quasi-static lock and (quasi-static normals, when asked)
  // its carts into e.
  void recordCartPass(const CartPass& pass, bool keep_carts, ModelEvaluation& e) const;
  // The crank equation at the drive torques in e: the load torque (kinetostatic normals with
  // friction: after the friction loop), the accelerations and the powers, into e.
  void solveCrankEquation(const CartPass& pass, ModelEvaluation& e) const;
  // Kinetostatic normals: the friction loop at the crank acceleration (GuideFrictionLoop.h), its
  // frictions taken off the load torque M and the friction power (loop_friction_ keeps them).
  void solveFrictionLoop(const CartPass& pass, double J_eq, double drive, ModelEvaluation& e, double& M,
                         double& P_friction) const;
  // The accelerations and the coupling torque from the drive torques and the load torque in e.
  void drivetrainAccelerations(double M_drive, double drive, const CouplingTorque& coupling, ModelEvaluation& e) const;
  // Kinetostatic normals: each cart's statics at the crank acceleration just found, into e.carts.
  void kinetostaticCarts(const CartPass& pass, ModelEvaluation& e) const;
  // The friction power the kinetostatic normals would give at e's crank acceleration (NaN where
  // the loop has no solution).
  double kinetostaticFrictionPower(const CartPass& pass, const ModelEvaluation& e) const;
  bool usesLoopTerms() const { return scene_.hasGuideFriction() && (kinetostatic_ || checksFrictionWork()); }
  mutable std::array<CartPass, 3> passes_;
  mutable int next_pass_ = 0;
  mutable long cart_passes_computed_ = 0;
  ColumnLayout timeseries_layout_, reactions_layout_;
};

// Runs the reduced model of a scene from its initial state to simulation.t_end and fills the
// RunResult contract (model = "reduced"). Integrator per scene.reduced.integrator:
//   cvode   - SUNDIALS CVODE, Adams-Moulton with a dense Newton corrector; rtol =
//             simulation.accuracy, per-state absolute tolerances and an absolute tolerance on
//             the crank angle (see ReducedIntegrators.cpp); rows every simulation.output_step.
//   baranov - the papers' fixed-step scheme in crank angle (Loveikin and Pochka (2007) eq. (4), (10), (11)),
//             rigid coupling only (std::invalid_argument otherwise); its nodes are interpolated
//             linearly in time onto the same output time grid, so both integrators fill the
//             same table.
// A stall (crank or motor below 1 % of the synchronous crank speed ω0/u, i.e. slip > 0.99 or
// reversal, for 1 s of simulated time; for Baranov: the scheme's speed reaching 0) ends the run
// early with stats.complete = false and stats.status = "motor stalled at t = X s" (X = onset),
// never with an exception. The stop rules are those of every run (analysis/RunRecorder.h);
// `control` stops the run (Ctrl-C) and follows its progress, as for the multibody model.
RunResult runReducedModel(const Scene& scene, const RunControl& control = {});
// The same with a given motor law (e.g. one written in a test).
RunResult runReducedModel(const Scene& scene, std::shared_ptr<const MotorLaw> law, const RunControl& control = {});

}  // namespace rollerdyn
