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
// H_j (local +x') from rollerHorizontalForce(v'_j), friction_j (local) from the quasi-static cart
// statics (CartStatics.h, without the cart's inertial force, as in the papers) at the local
// velocity v'_j = σ_j·x_Bj'·φ̇. With the quasi-static rod force F_j this equals
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
#pragma once

#include <vector>

#include <Eigen/Core>

#include "analysis/RunResult.h"
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
  double motor_torque = 0;        // M_n1 at the crank axis [N·m]
  double load_torque = 0;         // M_load [N·m] (rollers + friction + gravity)
  double coupling_torque = 0;     // elastic: c·ψ + k·ψ̇; rigid: M_motor - J_n1·φ̈
  double eps_crank = 0, eps_motor = 0, twist_accel = 0;
  double motor_power = 0;         // M_n1·φ̇1
  double damping_power = 0;       // k·ψ̇² ≥ 0
  double friction_power = 0;      // -Σ friction·v (≥ 0 when friction opposes v)
  double load_power = 0;          // -Σ H·v, power given to the concrete
  std::vector<CartEvaluation> carts;
};

class ReducedModel {
 public:
  // Validates the kinematic preconditions (std::invalid_argument on a bad scene).
  explicit ReducedModel(const Scene& scene);

  const Scene& scene() const { return scene_; }
  bool rigid() const { return rigid_; }
  int cartCount() const { return scene_.carts.count; }
  int stateSize() const { return rigid_ ? 5 : 8; }

  // State indices (-1 where the model has no such state).
  int iPhi() const { return 0; }
  int iOmega() const { return 1; }
  int iTwist() const { return rigid_ ? -1 : 2; }
  int iTwistRate() const { return rigid_ ? -1 : 3; }
  int iMotorWork() const { return rigid_ ? 2 : 4; }
  int iDampingWork() const { return rigid_ ? -1 : 5; }
  int iFrictionWork() const { return rigid_ ? 3 : 6; }
  int iLoadWork() const { return rigid_ ? 4 : 7; }

  // Kinematics of cart j (0-based) at crank angle φ2 of cart 1.
  SliderCrankPose cartPose(int j, double phi_crank) const;

  // J_n1 [kg·m²] (Loveikin, Pochka, Romasevych (2018) eq. (1)).
  double motorSideInertia() const { return J_n1_; }
  // J_n2(φ) and dJ_n2/dφ (analytic, from the slider-crank second derivatives).
  double crankSideInertia(double phi) const;
  double crankSideInertiaDerivative(double phi) const;
  // The inertia multiplying φ̈ of the crank equation: rigid J_n1 + J_n2(φ); elastic J_n2(φ).
  double reducedInertia(double phi) const;
  double reducedInertiaDerivative(double phi) const;

  // Kloss torque at the crank axis, 0 when the motor is disabled.
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
  void derivatives(const double* y, double* dydt) const;
  // Kinetic ½J_n1φ̇1² + ½J_n2φ̇2² (rigid: ½Jφ̇²) and potential ½cψ² + rod gravity [J].
  double kineticEnergy(const Eigen::VectorXd& y) const;
  double potentialEnergy(const Eigen::VectorXd& y) const;

  // Cart reactions at crank angle φ, speed φ̇ and acceleration φ̈. include_inertia = false: the
  // quasi-static reactions of Loveikin, Pochka, Romasevych (2018) eq. (14)-(25) (what the equations of motion use);
  // true: kinetostatic, with the d'Alembert force -m_B·a' of each cart (closer to what a
  // multibody model's constraint forces show).
  std::vector<CartEvaluation> cartReactions(double phi, double omega, double eps,
                                            bool include_inertia) const;

 private:
  CartEvaluation evaluateCart(int j, double phi, double omega, double inertial_force) const;
  double cartInertia(int j, const SliderCrankPose& p) const;            // cart j's share of J_n2 [kg·m²]
  double cartInertiaDerivative(int j, const SliderCrankPose& p) const;  // its dJ/dφ [kg·m²/rad]
  double rodGravityTorque(const SliderCrankPose& p, double theta) const;  // [N·m]

  Scene scene_;
  bool rigid_;
  double J_n1_;       // motor side, Loveikin, Pochka, Romasevych (2018) eq. (1)
  double J_crank_;    // crankshaft without rods + split pin half-masses (Loveikin, Pochka, Romasevych (2018) eq. (2))
  std::vector<double> m_B_;   // per cart: mass used with x_B', Loveikin, Pochka, Romasevych (2018) eq. (3)
  std::vector<Loads> loads_;  // per cart: the loads acting on it (Scene::cartLoads)
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
// never with an exception.
RunResult runReducedModel(const Scene& scene);

}  // namespace rollerdyn
