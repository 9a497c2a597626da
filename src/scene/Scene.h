// The immutable description of one roller forming installation (MuJoCo's "model").
// A Scene is produced once by parseScene() (src/scene/SceneParser.h), validated, and then only
// read: the multibody model (src/multibody) and the reduced model (src/reduced) both build from
// the same Scene, so any difference between them is a modelling difference, never an input one.
//
// Units: SI throughout (m, kg, s, N, N·m, rad). Angles are radians here; scene files may give
// degrees only under keys ending in `_deg`. Frames: x horizontal along the guides, y vertical up,
// z along the crankshaft axis; origin on the crankshaft axis. Each field's comment gives its
// meaning, its unit, and the scene-file key it comes from.
//
// Defaults: a Scene built in code (Scene{}) holds, in every field, the value the parser gives when
// the file leaves the key out: the schema's default of an Optional key (SceneSchema.cpp), the
// rule's value of a Conditional key (SceneParser.cpp), so a scene built in code runs the same
// equations as the same scene read from a file (test SceneDefaults). Required keys hold 0 here.
// Three Conditional keys follow values a Scene built in code sets itself, and must be set with
// them: carts.sides (one entry per cart, +1 each), motor.pole_pairs (round(2π·f_n/ω0)) and
// rods.inertia_com (m·l²/12).
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "scene/MotorSwitching.h"
#include "scene/SizingInputs.h"

namespace rollerdyn {

// Each enumeration lists its words in the order of the key's words in the schema (SceneSchema.cpp):
// the parser and toString() take the words from there (SceneChoices.h).
enum class RodModel { Distributed, Split, Massless };          // rods.model
enum class CouplingType { Elastic, Rigid };                     // coupling.type
enum class RollerForceDirection { OpposesVelocity, AsPrinted }; // loads.roller_force_direction
enum class KinematicsForm { Exact, Truncated };                 // reduced.kinematics
enum class FlywheelLocation { Crankshaft, MotorShaft };         // flywheel.location
enum class ReducedIntegrator { Cvode, Baranov };                // reduced.integrator
enum class DriveType { Crank, Cam };                            // drive.type
enum class Formulation { Constrained, Minimal };                // simulation.formulation
enum class MotorModel { Kloss, KlossDynamic, Circuit, Park };   // motor.model
enum class WindingConnection { Star, Delta };                   // motor.connection
enum class GuideNormalForce { Algebraic, Lagged };             // loads.guide_friction.normal_force
enum class ReducedGuideNormals { Kinetostatic, QuasiStatic };  // reduced.guide_normals
enum class ReducerLossModel { Papers, PowerFlow };            // reducer.losses

struct SimulationSettings {
  double t_end = 0;             // simulated time span [s]                       simulation.t_end
  double accuracy = 1e-6;       // integrator relative accuracy [-]              simulation.accuracy
  std::string integrator = "RungeKuttaMerson";  // Simbody integrator name      simulation.integrator
  double output_step = 0.005;   // spacing of output rows [s]                    simulation.output_step
  double constraint_tolerance = 1e-6;  // constraint projection tolerance [-]; a file without the
                                // key gets simulation.accuracy (set both when changing the accuracy
                                // in code)                               simulation.constraint_tolerance
  double steady_window_revolutions = 5;  // crank revolutions at the end of the run used for the
                                     // steady-state metrics [-]      simulation.steady_window_revolutions
  Formulation formulation = Formulation::Minimal;  // equations the multibody model integrates:
                                // all coordinates under Simbody's constraints (constrained) or
                                // the independent ones only (minimal) [-]      simulation.formulation
  bool reactions = true;        // joint reaction forces computed at every output row; false:
                                // motion and drive torques only, no reactions table [-]
                                //                                               simulation.reactions
  int self_check_interval = 0;  // minimal formulation: every k-th output row is also solved by
                                // Simbody's constrained solve and compared (accelerations,
                                // reaction columns) [rows]; 0: automatic, selfCheckInterval()
                                //                                    simulation.self_check_interval
};

struct InitialState {
  double crank_angle = 0;   // crank angle φ2 of cart 1's crank at t = 0 [rad]   initial.crank_angle_deg
  double crank_speed = 0;   // crank speed φ̇2 at t = 0 [rad/s]; motor starts at the same
                        // reduced speed (no twist rate) [rad/s]            initial.crank_speed
  double twist = 0;         // coupling twist φ1 - φ2 at t = 0 [rad]            initial.twist
};

struct CrankShaft {
  double radius = 0;        // crank radius r [m]                                crank.radius
  double offset = 0;        // angle between consecutive cranks Δφ [rad]; NaN when crank.angles_deg
                            // gives every crank's angle instead (read Scene::crankPhase(j))
                            //                                                   crank.offset_deg
  double inertia_per_crank = 0;  // J'_K, one crank about the shaft axis [kg·m²]      crank.inertia_per_crank
  double shaft_inertia = 0;  // shaft itself (excluding cranks) about its axis [kg·m²]  crank.shaft_inertia
  std::vector<double> angles = {};   // per cart j: nominal angle of its crank from cart 1's crank
                                     // (angles[0] = 0) [rad]; empty: j·Δφ   crank.angles_deg
  std::vector<double> angle_errors = {};  // per cart j: deviation of its crank from the nominal angle,
                                     // e.g. a manufacturing tolerance [rad]; empty: none
                                     //                                      crank.angle_error_deg
};

// The crankshaft as a beam on its main bearings (crankshaft.*, src/analysis/CrankshaftBearings.h).
// Positions z are measured along the shaft axis from any origin the scene chooses. Both lists
// empty: the model knows the bearings only as their resultant (reactions bearing_x, bearing_y).
struct CrankshaftLayout {
  std::vector<double> throw_positions = {};    // per cart j: axial position z of its crank throw
                                               // (the plane of its crank pin) [m]
                                               //                      crankshaft.throw_positions
  std::vector<double> bearing_positions = {};  // axial positions z of the main bearings, two or
                                               // more, ascending [m]  crankshaft.bearing_positions
  double bending_stiffness = 0;  // E·I of the shaft, uniform along it [N·m²]; 0 = not given. With
                                 // one E·I on rigid supports the reactions do not depend on it; it
                                 // only scales the shaft's deflection   crankshaft.bending_stiffness
  double torsional_stiffness = 0;  // G·I_p of the shaft between throws, uniform along it [N·m²]; 0 = a
                                   // rigid shaft. Given: one body per throw in z order, the segment
                                   // between throws a and b a torsional spring G·I_p/|z_b - z_a|
                                   // (multibody model, constrained formulation)
                                   //                            crankshaft.torsional_stiffness
  double torsional_damping = 0;    // β·G·I_p of a Kelvin-Voigt shaft [N·m²·s]: each segment's damper
                                   // d_k = β·G·I_p/Δz [N·m·s/rad]; 0 = undamped   crankshaft.torsional_damping
  bool given() const { return !bearing_positions.empty(); }
  bool torsionalChain() const { return torsional_stiffness > 0; }
};

// Cam drive with optimal reversal of Loveikin and Pochka (drive.type = cam): each cart is pushed by a constant-diameter cam on the
// crankshaft instead of a crank and rod, and follows the optimal-reversal motion law of Loveikin and Pochka (cam drive paper)
// eq. (29)-(34) as a function of the cam angle (src/physics/CamMotionLaw.h). One cam turn is one
// full cycle, so the half-cycle (one stroke) time is t3 = π/ω at crank speed ω [s]: it follows
// from the drive's speed and is not an input. Cart j's cam sits at θ = φ2 + j·Δφ (crank.offset_deg);
// θ = 0 puts the cart at the -Δx/2 end of its stroke; its hinge B is at x_B = σ·x(θ), i.e.
// mid-stroke on the shaft axis (carts move horizontally, so that offset changes no force).
// With drive.type = cam the rod keys are validated but not used: the Scene carries massless rods
// (no rod is built), and crank.radius / rods.length only serve `--set drive.type=crank`.
struct CamDrive {
  double stroke = 0;           // Δx, full stroke of the cart [m]                    cam.stroke
  double pusher_distance = 0;  // b, distance between the two pushers = cam diameter [m];
                               // only shapes the profile ρ = b/2 + x(θ), eq. (38)-(43)
                               //                                                  cam.pusher_distance
};

struct ConnectingRods {
  RodModel model = RodModel::Distributed;  // distributed | split (Loveikin, Pochka, Romasevych (2018) eq. (2)-(3)) | massless   rods.model
  double length = 0;     // l, crank pin to cart hinge [m]                          rods.length
  double mass = 0;       // m_rod of one rod [kg] (ignored when massless)           rods.mass
  double inertia_com = 0;  // own inertia about its centre of mass [kg·m²]; a file without the
                         // key gets m·l²/12 (Loveikin and Pochka (2007): I_s = q·l³/12)               rods.inertia_com
};

// Geometry of one cart, measured from the rod hinge B (Loveikin, Pochka, Romasevych (2018) fig. 3, eq. (10)), in the
// cart's own direction: +x points away from the shaft for a cart on the "same" side.
struct CartGeometry {
  double a = 0;        // half distance between the two compacting rollers [m]        carts.geometry.a
  double b = 0;        // half distance between the two guide rollers [m]             carts.geometry.b
  double p = 0;        // horizontal distance B -> cart centre of mass / roller midpoint [m]  carts.geometry.p
  double e = 0;        // depth of the compacting-roller contact below B [m]          carts.geometry.e
  double D = 0;        // compacting roller diameter [m] (informational)              carts.geometry.D
  double d = 0;        // guide roller diameter [m]; friction moment arm d/2          carts.geometry.d
  double com_height = 0;  // height of the cart's centre of mass above B [m]             carts.geometry.com_height
};

struct Carts {
  int count = 0;             // number of carts n [-]                         carts.count
  std::vector<int> side = {};  // per cart: +1 same side as cart 1's crank (x > 0), -1 opposite [-]
                             //                                               carts.sides
  double mass = 0;           // m'_B, one cart without rod [kg]; NaN when carts.mass is a list
                             // (read Scene::cartMass(j))                     carts.mass
  std::vector<double> masses = {};  // per cart: m'_B of cart j when carts.mass is a list, else empty [kg]
                               //                                             carts.mass: [...]
  CartGeometry geometry;     // carts.geometry.*
};

struct KlossMotor {
  bool enabled = true;     // motor torque applied at all                       motor.enabled
  double omega_sync = 0;   // synchronous rotor speed ω0 [rad/s]                motor.omega_sync
  double breakdown_torque = 0;  // M_kr at the rotor [N·m]                           motor.breakdown_torque
  double critical_slip = 0;  // s_kr [-]; from motor.critical_slip, or motor.omega_critical
                           // (s_kr = 1 - ω_kr/ω0, Loveikin and Pochka (2007) eq. (7)), or motor.omega_nominal +
                           // motor.overload_ratio (s_kr = s_n(λ + √(λ²-1)), Loveikin, Pochka, Romasevych (2018) eq. (37))
  double rotor_inertia = 0;  // J_p about the rotor axis [kg·m²]                  motor.rotor_inertia
};

// The induction machine behind the motor laws other than static Kloss (src/motor/MotorLaw.h):
// which law runs, the rated supply, and the machine either as an equivalent circuit or as
// catalogue data to fit one to. Every resistance and inductance here is per phase of the
// EQUIVALENT STAR: a delta winding's per-winding values R_Δ, L_Δ enter as R_Δ/3, L_Δ/3, and
// U_ph = U_n/√3 whatever the connection (docs/motor.md). Keys not given stay 0 = not given.
struct MotorCircuit {
  double R_s = 0;          // stator resistance R_s [Ω]                               motor.circuit.R_s
  double L_sigma_s = 0;    // stator leakage inductance L_σs [H]                      motor.circuit.L_sigma_s
  double L_m = 0;          // magnetizing inductance L_m [H]                          motor.circuit.L_m
  double R_r = 0;          // rotor (first cage) resistance R_r, referred to the stator [Ω]
                           //                                                        motor.circuit.R_r
  double L_sigma_r = 0;    // rotor (first cage) leakage inductance L_σr [H]          motor.circuit.L_sigma_r
  double R_r2 = 0;         // second cage's resistance [Ω]; 0: single cage            motor.circuit.R_r2
  double L_sigma_r2 = 0;   // second cage's leakage inductance [H]                    motor.circuit.L_sigma_r2
  bool given() const { return R_r > 0; }
  bool doubleCage() const { return R_r2 > 0; }
};

// Catalogue (data-sheet) values the circuit is fitted to (src/motor/CatalogueFit.h).
struct MotorCatalogue {
  double power = 0;                  // P_n, rated shaft power [W]                  motor.catalogue.power
  double omega_nominal = 0;          // ω_n, rated rotor speed [rad/s]              motor.catalogue.omega_nominal
  double current = 0;                // I_n, rated line current [A]                 motor.catalogue.current
  double power_factor = 0;           // cos φ_n at the rated point [-]              motor.catalogue.power_factor
  double efficiency = 0;             // η_n at the rated point [-]                  motor.catalogue.efficiency
  double starting_torque_ratio = 0;  // M_s/M_n, torque at standstill [-]          motor.catalogue.starting_torque_ratio
  double breakdown_torque_ratio = 0; // M_k/M_n, largest torque [-]                 motor.catalogue.breakdown_torque_ratio
  double starting_current_ratio = 0; // I_s/I_n, current at standstill [-]         motor.catalogue.starting_current_ratio
  int cages = 2;                     // rotor cages of the fitted circuit: 1 | 2 [-] motor.catalogue.cages
  bool given() const { return power > 0; }
  double nominalTorque() const { return power / omega_nominal; }  // M_n = P_n/ω_n [N·m]
};

struct InductionMotor {
  MotorModel model = MotorModel::Kloss;  // law of the motor torque: kloss | kloss_dynamic |
                                         // circuit | park [-]                           motor.model
  double torque_time_constant = 0;  // T_e of the dynamic Kloss characteristic [s]; 0: the
                                    // default 1/(2π·f_n·s_kr)                motor.torque_time_constant
  double voltage = 0;               // U_n, rated line-to-line RMS voltage [V]       motor.voltage
  double frequency = 50;            // f_n, rated supply frequency [Hz]              motor.frequency
  WindingConnection connection = WindingConnection::Star;  // winding connection at rated
                                    // voltage: star | delta [-]                     motor.connection
  int pole_pairs = 0;               // p [-]; from motor.pole_pairs, else round(2π·f_n/ω0)
                                    //                                               motor.pole_pairs
  MotorCircuit circuit;             // motor.circuit.*
  MotorCatalogue catalogue;         // motor.catalogue.*
  // Rated phase voltage of the equivalent star U_ph = U_n/√3 [V].
  double phaseVoltage() const;
  // Rated supply angular frequency ω1 = 2π·f_n [rad/s] (electrical).
  double supplyAngularFrequency() const;
};

struct Reducer {
  double ratio = 0;    // u = ω_rotor / ω_crank [-]                                 reducer.ratio
  double efficiency = 0;  // η in (0, 1] [-]; with losses = power_flow the forward efficiency η_f,
                       // motor side driving                                    reducer.efficiency
  double inertia = 0;  // J_red referred to the motor shaft [kg·m²]                 reducer.inertia
  double delta = 1;    // δ, Loveikin, Pochka, Romasevych (2018) eq. (1) factor for reducer inertia [-]        reducer.delta
  ReducerLossModel losses = ReducerLossModel::Papers;  // papers: the torque at the crank is
                       // M·u·η in both directions of the power flow (eq. (37)); power_flow:
                       // loss (1 - η_f)·|P| when the motor side drives, (1/η_r - 1)·|P| when
                       // the crank side drives (physics/ReducerLosses.h) [-]   reducer.losses
  double efficiency_reverse = 0;  // η_r in (0, 1], crank side driving [-]; 0: = η, which a file
                       // without the key holds (read only with losses = power_flow; read it
                       // through reverseEfficiency())                 reducer.efficiency_reverse
  double backlash = 0; // total backlash (free play) of the drive train between motor side and
                       // crankshaft, reduced to the crank axis: the twist φ1 - φ2 travels
                       // backlash/2 either way without torque before the teeth meet; the contact
                       // stiffness and damping are the coupling's c, k (physics/CouplingLaw.h);
                       // 0 = teeth always in contact [rad]                  reducer.backlash
  // η_r: efficiency_reverse, or η when it is 0 [-].
  double reverseEfficiency() const { return efficiency_reverse > 0 ? efficiency_reverse : efficiency; }
};

struct Coupling {
  CouplingType type = CouplingType::Elastic;  // elastic | rigid                                          coupling.type
  double stiffness = 0;  // c, reduced to the crank axis [N·m/rad]                   coupling.stiffness
  double damping = 0;  // k, reduced to the crank axis [N·m·s/rad]                 coupling.damping
  double inertia = 0;  // J_m, coupling hub on the motor shaft [kg·m²]             coupling.inertia
};

struct Flywheel {
  double inertia = 0;         // about its own shaft [kg·m²]; 0 = no flywheel     flywheel.inertia
  FlywheelLocation location = FlywheelLocation::Crankshaft;  // crankshaft | motor_shaft                         flywheel.location
};

struct Loads {
  double roller_force_front = 0;   // F_j1, horizontal compacting-roller force [N]        loads.roller_force_front
  double roller_force_rear = 0;    // F_j2 [N]                                        loads.roller_force_rear
  double roller_normal_front = 0;  // R_j1, upward reaction of the mix on a roller [N]    loads.roller_normal_front
  double roller_normal_rear = 0;   // R_j2 [N]                                        loads.roller_normal_rear
  RollerForceDirection roller_force_direction = RollerForceDirection::OpposesVelocity;  // opposes_velocity | as_printed   loads.roller_force_direction
  double guide_friction = 0;   // f, reduced guide-roller friction coefficient [-]    loads.guide_friction.coefficient
  double gravity = 9.81;       // g [m/s²]; 0 = no gravity                            loads.gravity
  double velocity_smoothing = 1e-3;  // v_s: sign(v) is replaced by tanh(v/v_s) [m/s]       loads.velocity_smoothing
  double guide_friction_lag = 2e-3;  // τ_N: time constant with which the multibody model's
                               // lagged friction normal force follows the guide reaction [s]
                               //                     loads.guide_friction.normal_force_lag
  double rolling_resistance = 0;  // μ_r, rolling resistance of the compacting rollers in the mix:
                               // a force μ_r·(R_j1 + R_j2) against the cart's velocity, added to
                               // F_j1 + F_j2 in either reading [-]      loads.rolling_resistance
  GuideNormalForce guide_normal_force = GuideNormalForce::Algebraic;  // normal force of the
                               // multibody model's guide friction: the guide reaction of the same
                               // instant, solved with the motion (algebraic), or followed with the
                               // lag τ_N (lagged) [-]; a file without the key gets algebraic with
                               // the minimal formulation, lagged with the constrained one (set it
                               // with the formulation in code)   loads.guide_friction.normal_force
};

// One cart's values of the loads.* keys that may be given per cart (a list, one value per cart);
// Scene::cartLoads(j) merges them into the Loads every law reads.
struct CartLoads {
  double roller_force_front = 0;   // F_j1 of this cart [N]                  loads.roller_force_front[j]
  double roller_force_rear = 0;    // F_j2 [N]                               loads.roller_force_rear[j]
  double roller_normal_front = 0;  // R_j1 [N]                               loads.roller_normal_front[j]
  double roller_normal_rear = 0;   // R_j2 [N]                               loads.roller_normal_rear[j]
  double rolling_resistance = 0;   // μ_r [-]                                loads.rolling_resistance[j]
};

struct ReducedSettings {
  KinematicsForm kinematics = KinematicsForm::Exact;  // exact (eq. (40)-(47)) | truncated (eq. (52)-(57))   reduced.kinematics
  ReducedIntegrator integrator = ReducedIntegrator::Cvode;  // cvode | baranov (Loveikin and Pochka (2007) eq. (4), (10), (11))  reduced.integrator
  double baranov_step = 1.0 * (M_PI / 180.0);  // crank-angle step of the Baranov scheme [rad]        reduced.baranov_step_deg
  ReducedGuideNormals guide_normals = ReducedGuideNormals::Kinetostatic;  // guide normal forces
                               // of the reduced model's friction and reactions: the papers' cart
                               // statics without inertial forces (quasi_static) or with the cart's
                               // and rod's inertial forces, solved with the motion (kinetostatic,
                               // the multibody algebraic law) [-]               reduced.guide_normals
};

// A key the scene gives that has no effect on the run and is accepted with a warning
// (Plausibility.h): a starting method's key after a --set chose another method (docs/startup.md).
// Given together with the method it does not belong to, such a key is an error instead.
struct IgnoredKey {
  std::string key;     // dotted key path, e.g. motor.start.changeover_speed
  std::string origin;  // where it was given: "FILE:LINE" or "--set #N (ARG)"
  std::string why;     // why it has no effect, naming the key that decides
};

struct Scene {
  std::string name;         // scene name: file stem, e.g. "balanced-4cart"
  std::string source_path;  // file the scene was read from
  std::string source;       // free-text citation of the paper the scene comes from   source
  SimulationSettings simulation;
  InitialState initial;
  CrankShaft crank;
  CrankshaftLayout crankshaft;  // crankshaft.*: throws and main bearings along the shaft (optional)
  ConnectingRods rods;
  Carts carts;
  KlossMotor motor;
  InductionMotor induction;  // motor.model and the machine data of the other laws
  Reducer reducer;
  Coupling coupling;
  Flywheel flywheel;
  Loads loads;               // a per-cart key given as a list is NaN here (read Scene::cartLoads(j))
  std::vector<CartLoads> cart_loads;  // per cart when any of loads.roller_force_front/_rear,
                             // roller_normal_front/_rear, rolling_resistance is a list (the others
                             // repeat their scalar); empty when all are scalars  loads.*: [...]
  ReducedSettings reduced;
  DriveType drive = DriveType::Crank;  // crank | cam                              drive.type
  CamDrive cam;                        // cam.* (used when drive == Cam)
  SizingInputs sizing;                 // sizing.*: ratings and targets, no effect on the run
  MotorStart motor_start;              // motor.start.*: starting method (MotorSwitching.h)
  MotorStop motor_stop;                // motor.stop.*: switch-off, brake, restart
  std::vector<std::string> given_keys; // the schema keys the file or --set gave (the others took
                                       // their defaults), in schema order: KeyEffects.h
  std::vector<IgnoredKey> ignored_keys;  // keys given without effect, accepted with a warning

  // --- Derived quantities, defined once so both models use the same formula. ---

  // Motor-side inertia reduced to the crank axis, Loveikin, Pochka, Romasevych (2018) eq. (1) extended by the reducer and a
  // motor-shaft flywheel: J_n1 = (J_p + J_m + J_red + J_fw,motor)·δ·u² [kg·m²].
  double motorSideInertia() const;
  // Crankshaft inertia about its axis without rods: n·J'_K + shaft + crank-side flywheel [kg·m²].
  double crankSideInertia() const;
  // The self-check interval in output rows: simulation.self_check_interval, or max(50, 10·n)
  // when not given. Why 10·n: Simbody's constrained solve at a self-check row costs about 0.5·n
  // times an O(n) evaluation of the minimal formulation (measured: 5x at 4 carts, 26x at 64,
  // ~130x at 256), so one check every 10·n rows keeps it near 5 % of the rows' cost at any n.
  int selfCheckInterval() const;
  // --- Per-cart values (docs/per-cart.md): the uniform scalar unless the scene gives a list. ---

  // Angle of cart j's crank (0-based j) relative to the shaft's reference, which is cart 1's
  // nominal crank angle φ2: j·Δφ, or crank.angles_deg[j], plus crank.angle_error_deg[j] [rad].
  double crankPhase(int j) const;
  // m'_B of cart j (0-based), without rod [kg].
  double cartMass(int j) const { return carts.masses.empty() ? carts.mass : carts.masses[j]; }
  // Cart j's centre-of-mass mass including half a rod under the split model [kg], Loveikin, Pochka, Romasevych (2018) eq. (3).
  double cartMassWithRodShare(int j) const;
  // The same for a scene whose carts all have one mass; std::logic_error when carts.mass is a list.
  double cartMassWithRodShare() const;
  // The smallest of the carts' masses with rod share [kg] (tolerance scales: the lightest cart
  // is the one a force error moves most).
  double lightestCartMassWithRodShare() const;
  // The loads acting on cart j (0-based): Loads with that cart's F_j1, F_j2, R_j1, R_j2, μ_r.
  Loads cartLoads(int j) const;
  // Σ_j (|F_j1| + |F_j2|) over the carts [N] (a force scale for tolerances).
  double rollerForceSum() const;
  // Whether every cart has the same mass and loads (whatever their crank angles and sides): only
  // then is each cart's torque the same function of its own crank angle, which the layout's phase
  // sums (modes/ExcitationOrders.h, studies/ResonanceCheck.h) assume.
  bool cartsIdentical() const;
  // Whether each optional effect is present in this scene.
  bool hasMotor() const { return motor.enabled; }
  bool hasRollerLoads() const;
  bool hasGuideFriction() const { return loads.guide_friction > 0.0; }
  bool hasGravity() const { return loads.gravity > 0.0; }
  bool hasFlywheel() const { return flywheel.inertia > 0.0; }
  bool hasCamDrive() const { return drive == DriveType::Cam; }
  bool hasBacklash() const { return coupling.type == CouplingType::Elastic && reducer.backlash > 0.0; }
  bool hasCouplingDamping() const {
    return coupling.type == CouplingType::Elastic && coupling.damping > 0.0;
  }
  // The list of effect names built for this scene (also written to summary.json).
  std::vector<std::string> effects() const;
};

// What an effect name of Scene::effects() means, in the engineer's words with the scene key that
// sets it, for the console and the report (the names stay the identifiers in summary.json).
std::string effectWords(const std::string& effect);

const char* toString(RodModel m);
const char* toString(CouplingType t);
const char* toString(RollerForceDirection d);
const char* toString(KinematicsForm k);
const char* toString(FlywheelLocation l);
const char* toString(ReducedIntegrator i);
const char* toString(Formulation f);
const char* toString(DriveType d);
const char* toString(MotorModel m);
const char* toString(WindingConnection c);
const char* toString(GuideNormalForce g);
const char* toString(ReducedGuideNormals g);
const char* toString(ReducerLossModel m);
const char* toString(StartMethod m);       // motor.start.method

}  // namespace rollerdyn
