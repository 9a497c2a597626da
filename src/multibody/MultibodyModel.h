// The Simbody multibody model of an installation, built once from an immutable Scene
// (Simbody examples' pattern: build the system, realize stage by stage). Holds the system and
// the handles to its bodies and force elements; the evolving data lives in SimTK::State objects.
//
// Topology (x along the guides, y up, z = shaft axis; everything in the plane z = 0):
//   Ground -Pin(z)-> crankshaft  (crank-side inertia, plus J_n1 when the coupling is rigid)
//   crankshaft -Pin(z)-> motor side (J_n1, reduced to the crank axis; its q is the coupling
//                                    twist φ1 - φ2)                     [elastic coupling only]
//   crankshaft -Pin(z) at pin A_j-> rod j       [rods.model = distributed]
//   Ground -Slider(x)-> cart j, origin at the rod hinge B_j
//   loop closure at B_j: rod end on the cart's z axis through B_j (one PointOnLine, two
//   equations), or, for split and massless rods, a Constraint::Rod of length l between A_j and B_j.
//   cam drive (scene.drive = cam, Loveikin and Pochka (cam drive paper)): no rod; a Constraint::CoordinateCoupler
//   x_B - σ·x(φ2 + j·Δφ) = 0 (CamFollower.h) ties cart j to the crankshaft.
// Rods hang from the crankshaft, not from the carts, so the crankshaft never has zero
// articulated inertia even when the scene gives it none of its own.
//
// Only what the scene asks for is built: no motor element when motor.enabled is false, no
// coupling element for a rigid coupling (one body), no gravity, loads, friction or flywheel
// when the scene leaves them out.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "Simbody.h"
#include "analysis/RunResult.h"
#include "io/OutputColumns.h"
#include "motor/MotorLaw.h"
#include "multibody/CartRig.h"
#include "scene/Scene.h"

namespace rollerdyn {

class MotorForce;
class ElasticCoupling;
class CrankshaftTorsion;
class RollerLoadForce;
class GuideFriction;
struct GuideNormals;
class EnergyMeter;

struct MultibodyOptions {
  bool prescribe_crank_speed = false;  // drive the crankshaft at a constant speed (Motion::Steady)
  double crank_speed = 0.0;            // that speed [rad/s]
  bool structured_jacobian = true;     // minimal formulation: Newton Jacobian by difference quotients
                                       // of the mechanical states only (false: of every state)
  std::shared_ptr<const MotorLaw> motor_law;  // the motor's law; null: the scene's motor.model
};

// What the built system contains, for `rollerdyn check` and for tests.
struct MultibodyInventory {
  int bodies = 0;                 // mobilized bodies, ground excluded
  int mobilities = 0;             // generalized speeds u
  int constraints = 0;            // Constraint objects
  int constraint_equations = 0;   // acceleration-level constraint equations
  int degrees_of_freedom = 0;     // mobilities - constraint equations - prescribed
  std::vector<std::string> force_elements;  // names of the force elements built
  std::vector<std::string> effects;         // Scene::effects()
};

// Energy state at one instant [J].
struct EnergySnapshot {
  double kinetic = 0, potential = 0;
  double motor_work = 0, damping_dissipation = 0, friction_dissipation = 0, load_work = 0;
  double brake_dissipation = 0;
  double reducer_losses = 0;  // the reducer's losses on the motor's torque (ReducerLosses.h)
};

// The energy audit of a run from the snapshots at its first and last recorded rows (the work
// integrals are cumulative states, so the run's share is their difference).
EnergyAudit energyAuditBetween(const EnergySnapshot& first, const EnergySnapshot& last);

class MultibodyModel {
 public:
  explicit MultibodyModel(const Scene& scene, const MultibodyOptions& options = {});
  ~MultibodyModel();
  MultibodyModel(const MultibodyModel&) = delete;
  MultibodyModel& operator=(const MultibodyModel&) = delete;

  const Scene& scene() const { return scene_; }
  const SimTK::MultibodySystem& system() const { return system_; }
  const SimTK::SimbodyMatterSubsystem& matter() const { return matter_; }
  const MultibodyInventory& inventory() const { return inventory_; }
  const std::vector<CartRig>& carts() const { return carts_; }
  const MultibodyOptions& options() const { return options_; }
  const SimTK::GeneralForceSubsystem& forces() const { return forces_; }
  // The crankshaft: the whole rigid shaft, or the throw at the drive end of a torsional chain.
  const SimTK::MobilizedBody& crank() const { return crank_; }
  // The springs between a torsional chain's throws; nullptr for a rigid crankshaft.
  const CrankshaftTorsion* crankshaftTorsion() const { return torsion_force_; }
  // Motor-side body: mobilized on the crankshaft (its q is the twist) when the coupling is
  // elastic, the crankshaft itself when it is rigid.
  const SimTK::MobilizedBody& motorSide() const { return motor_; }
  bool elastic() const { return motor_.getMobilizedBodyIndex() != crank_.getMobilizedBodyIndex(); }
  bool hasGuideFriction() const { return friction_force_ != nullptr; }
  // The motor force element (null without a motor): its law, supply, phase and z states.
  const MotorForce* motorForce() const { return motor_force_; }
  // M_kr of the motor law the model runs [N·m at the rotor] (motor/BreakdownTorque.h).
  double motorBreakdownTorque() const { return breakdown_torque_; }
  // z entries of the motor element (law states, brake work): the first entries of the force
  // subsystem's z, before the guide-friction normal forces and the energy integrals.
  int motorStateCount() const;
  // z entries of the energy audit (EnergyMeter.h): 4, 5 when the reducer's losses are integrated.
  int energyStateCount() const;
  // reducer.losses = power_flow: the timeseries carries reducer_loss_torque (RunResult.h).
  bool recordsReducerLosses() const;
  // The guide-friction element (precondition: hasGuideFriction()).
  const GuideFriction& frictionElement() const { return *friction_force_; }
  // True when the guide friction carries normal-force lag states (loads.guide_friction.normal_force
  // = lagged); false without friction or with the algebraic law.
  bool hasFrictionLagStates() const;
  // The normal force of the guide friction in words, for every multibody result
  // (RunResult::guide_normals); empty without guide friction.
  std::string guideNormalsDescription() const;
  // Time derivatives of the force subsystem's auxiliary states z (energy audit, guide-friction
  // normal-force lags; indexed like forces().getZ(s)) for the guide normal forces
  // `guide_normals_now` (N_front, N_rear per cart; ignored without friction). State realized to
  // Velocity. The constrained formulation computes the same rates in realizeAcceleration from
  // Simbody's joint reactions.
  void auxiliaryRates(const SimTK::State& s, const SimTK::Vector& guide_normals_now,
                      SimTK::Vector& zdot) const;
  // ∂(friction-dissipation rate)/∂N̂ [W/N] per guide normal-force state (GuideFriction.h); empty
  // without guide friction. State realized to Velocity.
  SimTK::Vector frictionPowerGradient(const SimTK::State& s) const;
  // Adds every force element's applied forces to the arrays (sized for the matter subsystem),
  // element by element in the force subsystem's order: the sums Simbody forms at Dynamics stage,
  // without realizing the system to Dynamics. State realized to Velocity. include_friction =
  // false leaves the guide friction out (the minimal formulation adds it once its loop is solved).
  void addAppliedForces(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& body_forces,
                        SimTK::Vector_<SimTK::Vec3>& particle_forces, SimTK::Vector& mobility_forces,
                        bool include_friction = true) const;

  // A state assembled exactly at crank angle φ2, crank speed φ̇2 and coupling twist φ1 - φ2
  // (closed-form slider-crank positions and velocities, then a projection that only removes
  // round-off), with consistent guide-friction normal forces. Realized to Acceleration (Simbody's
  // constrained solve: dense in the constraints; the minimal formulation uses closedFormState).
  SimTK::State assembledState(double crank_angle, double crank_speed, double twist) const;
  // The scene's initial state (assembledState).
  SimTK::State initialState() const;
  // The same configuration from the closed forms alone (MinimalCoordinates.h: exact to round-off,
  // no projection), realized to Velocity; O(n). The motor's states are set as in assembledState
  // (startMotor); the guide-friction normal forces (lag states or algebraic) are left at zero:
  // the minimal formulation sets them from its friction loop.
  SimTK::State closedFormState(double crank_angle, double crank_speed, double twist) const;

  // Output columns (io/OutputColumns.h: units, meanings) and where each value of a row goes.
  std::vector<std::string> timeseriesColumns() const { return timeseries_layout_.names(); }
  std::vector<std::string> reactionColumns() const { return reactions_layout_.names(); }
  const ColumnLayout& timeseriesLayout() const { return timeseries_layout_; }
  const ColumnLayout& reactionsLayout() const { return reactions_layout_; }
  // One cart's columns of a reactions row (cart j, 0-based) from the force on the cart at its
  // hinge B, whichever formulation found it [N]; both formulations write them here.
  // Cam: Fx_on_cart, the cam's horizontal force on the cart.
  void setCamReactions(int j, const GuideNormals& n, double friction, double Fx_on_cart,
                       std::vector<double>& reactions_row) const;
  // Rod: F_rod_on_cart, the rod's force on the cart; a_S, the rod's centre-of-mass acceleration
  // (read only when the rod is a body). State realized to Position.
  void setRodReactions(const SimTK::State& s, int j, const GuideNormals& n, double friction,
                       const SimTK::Vec3& F_rod_on_cart, const SimTK::Vec3& a_S,
                       std::vector<double>& reactions_row) const;
  // The guide friction's force on cart j as the model applies it; 0 without guide friction [N].
  double guideFrictionForce(const SimTK::State& s, int j) const;
  // One output row of each table from a state realized to Acceleration.
  void observe(const SimTK::State& s, std::vector<double>& timeseries_row,
               std::vector<double>& reactions_row) const;
  // The timeseries row alone, from a state realized to Dynamics and its accelerations u̇
  // (Simbody's, or the minimal formulation's projected ones): no constrained solve needed.
  void observeMotion(const SimTK::State& s, const SimTK::Vector& udot,
                     std::vector<double>& timeseries_row) const;
  // The reactions row alone, from a state realized to Acceleration.
  void observeReactions(const SimTK::State& s, std::vector<double>& reactions_row) const;

  double crankAngle(const SimTK::State& s) const { return crank_.getOneQ(s, 0); }
  double crankSpeed(const SimTK::State& s) const { return crank_.getOneU(s, 0); }
  // dω/dt of the crank [rad/s²]; s realized to Acceleration.
  double crankAcceleration(const SimTK::State& s) const { return crank_.getOneUDot(s, 0); }
  double motorSpeed(const SimTK::State& s) const;   // reduced to the crank axis
  double motorTorque(const SimTK::State& s) const;  // reduced to the crank axis, 0 without motor
  double couplingTorque(const SimTK::State& s) const;  // rigid coupling: Acceleration stage
  // The same from given accelerations u̇ (a rigid coupling's torque needs φ̈2) [N·m].
  double couplingTorque(const SimTK::State& s, const SimTK::Vector& udot) const;
  // Largest absolute position-constraint error [m] (state realized to Position).
  double constraintError(const SimTK::State& s) const;
  EnergySnapshot energy(const SimTK::State& s) const;  // realized to Dynamics

 private:
  // One cart's columns of a reactions row (cart = j + 1) [N].
  struct CartReactions {
    double N_front, N_rear, F_rod, friction, crankpin_x, crankpin_y;
  };
  void setCartReactions(int cart, const CartReactions& r, std::vector<double>& reactions_row) const;
  // Cart j's columns of a reactions row from Simbody's constrained solve: its mobilizer's
  // `reactions` and the `applied` body forces at a state realized to Acceleration.
  void observeCartReactions(const SimTK::State& s, int j, const SimTK::Vector_<SimTK::SpatialVec>& reactions,
                            const SimTK::Vector_<SimTK::SpatialVec>& applied, std::vector<double>& reactions_row) const;
  // closedFormState without the motor's states.
  SimTK::State closedFormKinematics(double crank_angle, double crank_speed, double twist) const;
  // The motor's own states at t = 0 (steady when the motor ran before, MotorLaw::initialState),
  // then the supply's events due at t = 0 (a speed trigger the initial speed has passed already).
  // State realized to Velocity on return; nothing without a motor.
  void startMotor(SimTK::State& s) const;
  // Error weights of the coupling twist and of each shaft segment's twist: one unit carries the
  // breakdown torque at the crank, M_kr·u·η (s realized to Model).
  void weightTwists(SimTK::State& s) const;
  // The guide-friction normal forces at t = 0: the lag states at the reactions they produce, or
  // the algebraic law's loop solved (std::invalid_argument when it has no solution).
  void startFrictionNormals(SimTK::State& s) const;
  void buildDrive();
  // The crankshaft body (or one throw) of inertia J [kg·m²] about its axis, carrying the split
  // rods' pin masses of `carts`.
  SimTK::Body::Rigid crankBody(double J, const std::vector<int>& carts) const;
  // One body per throw and the springs between them (physics/TorsionalChain.h); J_motor_side
  // joins the drive-end throw (rigid coupling).
  void buildTorsionalChain(double J_motor_side);
  // Per cart: its slider and what links it to the crankshaft (rod constraint, rod body, or cam).
  void buildCarts();
  void driveCartByCam(CartRig& rig, int cart);
  // A distributed rod: its own body on the crank pin, its end held on the cart's axis through B.
  void linkCartByRodBody(CartRig& rig);
  // Motor, coupling, gravity, roller loads, guide friction, then the energy meter, in that order
  // (addAppliedForces sums them in it).
  void buildForces();
  void addMotorForce();
  // The elastic coupling's spring (and damper, backlash) between motor side and crankshaft.
  void addElasticCoupling();
  // The roller loads of every cart.
  void addRollerLoads();
  // The motor side's and the crank's angles, speeds and accelerations into a timeseries row.
  void setShaftMotion(const SimTK::State& s, const SimTK::Vector& udot, std::vector<double>& timeseries_row) const;
  // Each cart's position, speed and acceleration (ground x) into a timeseries row.
  void setCartMotion(const SimTK::State& s, const SimTK::Vector& udot, std::vector<double>& timeseries_row) const;
  // The drive's columns of a timeseries row: motor, reducer losses, tooth contact, shaft torques.
  void setDriveColumns(const SimTK::State& s, std::vector<double>& timeseries_row) const;
  // Hands f to the force subsystem, in applied_order_ and the inventory under inventory_name.
  void addForceElement(SimTK::Force::Custom::Implementation* f, const std::string& inventory_name);
  void fillInventory();
  // The columns this model writes, from the force elements it built.
  void layOutColumns();

  Scene scene_;
  MultibodyOptions options_;
  SimTK::MultibodySystem system_;
  SimTK::SimbodyMatterSubsystem matter_;
  SimTK::GeneralForceSubsystem forces_;
  SimTK::MobilizedBody motor_;   // motor-side body; same as crank_ for a rigid coupling
  SimTK::MobilizedBody crank_;
  std::vector<SimTK::MobilizedBody> throw_of_cart_;  // per cart: the body its crank pin is on
  std::vector<CartRig> carts_;
  int constraint_count_ = 0;
  // Owned by the force subsystem once wrapped in SimTK::Force::Custom.
  const MotorForce* motor_force_ = nullptr;
  double breakdown_torque_ = 0;  // M_kr of the law the model runs; the key without a motor [N·m]
  const ElasticCoupling* coupling_force_ = nullptr;
  const CrankshaftTorsion* torsion_force_ = nullptr;
  const RollerLoadForce* load_force_ = nullptr;
  const GuideFriction* friction_force_ = nullptr;
  const EnergyMeter* energy_meter_ = nullptr;
  // Force elements in the force subsystem's order (addAppliedForces); nullptr stands for gravity_.
  std::vector<const SimTK::Force::Custom::Implementation*> applied_order_;
  SimTK::Force::Gravity gravity_;  // empty handle without gravity
  MultibodyInventory inventory_;
  ColumnLayout timeseries_layout_, reactions_layout_;
};

}  // namespace rollerdyn
