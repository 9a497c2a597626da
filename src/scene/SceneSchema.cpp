#include "scene/SceneSchema.h"

#include <cmath>
#include <limits>
#include <sstream>

namespace rollerdyn {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Interval helpers; names read as the condition they enforce.
Range anyFinite() { return {-kInf, false, kInf, false}; }
Range positive() { return {0.0, false, kInf, false}; }
Range nonNegative() { return {0.0, true, kInf, false}; }
Range between(double lo, bool lo_in, double hi, bool hi_in) { return {lo, lo_in, hi, hi_in}; }

KeySpec number(std::string path, std::string unit, Presence presence, Range range, double def,
               std::string meaning) {
  return {std::move(path), KeyKind::Number, std::move(unit), presence, range, def, "", {},
          std::move(meaning)};
}

KeySpec integer(std::string path, Presence presence, Range range, double def,
                std::string meaning) {
  return {std::move(path), KeyKind::Integer, "-", presence, range, def, "", {},
          std::move(meaning)};
}

KeySpec choice(std::string path, Presence presence, std::vector<std::string> choices,
               std::string def, std::string meaning) {
  return {std::move(path), KeyKind::Choice, "-", presence, anyFinite(), 0.0, std::move(def),
          std::move(choices), std::move(meaning)};
}

std::vector<KeySpec> buildSchema() {
  using P = Presence;
  return {
      {"source", KeyKind::Text, "-", P::Optional, anyFinite(), 0.0, "", {},
       "citation of the paper the scene comes from (authors, year, title); optional for a scene of your own"},

      number("simulation.t_end", "s", P::Required, positive(), 0.0, "simulated time span"),
      number("simulation.accuracy", "-", P::Optional, between(0.0, false, 1.0, false), 1e-6,
             "integrator relative accuracy"),
      choice("simulation.integrator", P::Optional,
             {"RungeKuttaMerson", "RungeKutta3", "RungeKuttaFeldberg", "RungeKutta2",
              "ExplicitEuler", "Verlet", "SemiExplicitEuler2", "CPodes"},
             "RungeKuttaMerson",
             "Simbody integrator of the multibody model's constrained formulation"),
      choice("simulation.formulation", P::Optional, {"constrained", "minimal"}, "minimal",
             "equations of the multibody model: all coordinates under Simbody's constraints "
             "(constrained) or only the independent ones, integrated by CVODE Adams (minimal)"),
      number("simulation.output_step", "s", P::Optional, positive(), 0.005,
             "spacing of output rows (<= t_end)"),
      {"simulation.reactions", KeyKind::Flag, "-", P::Optional, anyFinite(), 1.0, "", {},
       "compute the joint reaction forces at every output row (reactions.csv, joint loads); "
       "false gives the motion and drive torques only, at a fraction of the multibody cost"},
      integer("simulation.self_check_interval", P::Conditional, between(1.0, true, 1e9, true), 0.0,
              "minimal formulation: every k-th output row is also solved by Simbody's constrained "
              "solve and compared (accelerations, guide normal forces, reaction columns); default "
              "max(50, 10 x carts.count)"),
      number("simulation.constraint_tolerance", "-", P::Conditional,
             between(0.0, false, 1.0, false), 0.0,
             "constraint projection tolerance (default: simulation.accuracy)"),
      number("simulation.steady_window_revolutions", "-", P::Optional, positive(), 5.0,
             "crank revolutions at the end of the run used for steady-state metrics"),

      number("initial.crank_angle_deg", "deg", P::Optional, anyFinite(), 0.0,
             "crank angle of cart 1's crank at t = 0"),
      number("initial.crank_speed", "rad/s", P::Optional, anyFinite(), 0.0,
             "crank speed at t = 0 (motor starts at the same reduced speed)"),
      number("initial.twist", "rad", P::Optional, anyFinite(), 0.0,
             "coupling twist phi1 - phi2 at t = 0"),

      number("crank.radius", "m", P::Required, positive(), 0.0, "crank radius r"),
      number("crank.offset_deg", "deg", P::Required, between(0.0, true, 360.0, false), 0.0,
             "angle between consecutive cranks"),
      number("crank.inertia_per_crank", "kg·m²", P::Optional, nonNegative(), 0.0,
             "J'_K, one crank about the shaft axis"),
      number("crank.shaft_inertia", "kg·m²", P::Optional, nonNegative(), 0.0,
             "crankshaft without cranks about its axis"),

      choice("rods.model", P::Required, {"distributed", "split", "massless"}, "",
             "connecting-rod mass model"),
      number("rods.length", "m", P::Required, positive(), 0.0,
             "rod length l, crank pin to cart hinge (l > r)"),
      number("rods.mass", "kg", P::Conditional, anyFinite(), 0.0,
             "mass of one rod (required unless rods.model is massless)"),
      number("rods.inertia_com", "kg·m²", P::Conditional, nonNegative(), 0.0,
             "rod inertia about its centre of mass (default m·l²/12)"),

      choice("drive.type", P::Optional, {"crank", "cam"}, "crank",
             "crank-slider per cart, or the cam of Loveikin and Pochka (cam drive paper) (rods then unused)"),
      number("cam.stroke", "m", P::Conditional, positive(), 0.0,
             "cam drive: full stroke of the cart (required when drive.type is cam)"),
      number("cam.pusher_distance", "m", P::Conditional, positive(), 0.0,
             "cam drive: distance b between the pushers = cam diameter (> stroke; default 2·stroke)"),

      integer("carts.count", P::Required, between(1.0, true, 1000.0, true), 0.0,
              "number of carts n"),
      {"carts.sides", KeyKind::Sides, "-", P::Conditional, anyFinite(), 0.0, "same", {},
       "side of the shaft of each cart"},
      number("carts.mass", "kg", P::Required, positive(), 0.0, "m'_B, one cart without rod"),
      number("carts.geometry.a", "m", P::Optional, nonNegative(), 0.0,
             "half distance between the two compacting rollers"),
      number("carts.geometry.b", "m", P::Conditional, nonNegative(), 0.0,
             "half distance between the two guide rollers (> 0 with guide friction)"),
      number("carts.geometry.p", "m", P::Optional, anyFinite(), 0.0,
             "horizontal distance hinge B -> cart centre of mass / roller midpoint"),
      number("carts.geometry.e", "m", P::Optional, anyFinite(), 0.0,
             "depth of the compacting-roller contact below B"),
      number("carts.geometry.D", "m", P::Optional, nonNegative(), 0.0,
             "compacting roller diameter (informational)"),
      number("carts.geometry.d", "m", P::Optional, nonNegative(), 0.0,
             "guide roller diameter (friction moment arm d/2)"),
      number("carts.geometry.com_height", "m", P::Optional, anyFinite(), 0.0,
             "height of the cart's centre of mass above B"),

      {"motor.enabled", KeyKind::Flag, "-", P::Optional, anyFinite(), 1.0, "", {},
       "whether the motor torque is applied"},
      number("motor.omega_sync", "rad/s", P::Required, positive(), 0.0,
             "synchronous rotor speed omega0"),
      number("motor.breakdown_torque", "N·m", P::Conditional, positive(), 0.0,
             "breakdown (critical) torque M_kr at the rotor (Kloss; required unless "
             "motor.catalogue is given, then breakdown_torque_ratio·P_n/omega_n)"),
      number("motor.critical_slip", "-", P::Conditional, between(0.0, false, 1.0, false), 0.0,
             "critical slip s_kr (way 1 of 3)"),
      number("motor.omega_critical", "rad/s", P::Conditional, positive(), 0.0,
             "critical rotor speed omega_kr, s_kr = 1 - omega_kr/omega0 (way 2 of 3)"),
      number("motor.omega_nominal", "rad/s", P::Conditional, positive(), 0.0,
             "nominal rotor speed omega_n (way 3 of 3, with motor.overload_ratio)"),
      number("motor.overload_ratio", "-", P::Conditional, between(1.0, false, kInf, false), 0.0,
             "lambda = M_kr / M_n (way 3 of 3, with motor.omega_nominal)"),
      number("motor.rotor_inertia", "kg·m²", P::Required, positive(), 0.0,
             "rotor inertia J_p"),
      choice("motor.model", P::Optional, {"kloss", "kloss_dynamic", "circuit", "park"}, "kloss",
             "law of the motor torque: static Kloss formula, dynamic Kloss characteristic "
             "(torque lags by T_e), steady-state equivalent circuit, or space-phasor (Park) machine"),
      number("motor.torque_time_constant", "s", P::Optional, positive(), 0.0,
             "T_e of the dynamic Kloss characteristic T_e·dM/dt + M = M_static "
             "(default 1/(2·pi·f_n·s_kr))"),
      number("motor.voltage", "V", P::Conditional, positive(), 0.0,
             "U_n, rated line-to-line RMS voltage (required for the circuit and park models)"),
      number("motor.frequency", "Hz", P::Optional, positive(), 50.0,
             "f_n, rated supply frequency"),
      choice("motor.connection", P::Optional, {"star", "delta"}, "star",
             "stator winding connection at the rated voltage (circuit values are per phase "
             "of the equivalent star either way)"),
      integer("motor.pole_pairs", P::Conditional, between(1.0, true, 64.0, true), 0.0,
              "p, pole pairs (default round(2·pi·f_n/omega0); must give omega0 = 2·pi·f_n/p)"),
      number("motor.circuit.R_s", "Ω", P::Conditional, nonNegative(), 0.0,
             "stator resistance per phase of the equivalent star"),
      number("motor.circuit.L_sigma_s", "H", P::Conditional, positive(), 0.0,
             "stator leakage inductance per phase of the equivalent star"),
      number("motor.circuit.L_m", "H", P::Conditional, positive(), 0.0,
             "magnetizing inductance per phase of the equivalent star"),
      number("motor.circuit.R_r", "Ω", P::Conditional, positive(), 0.0,
             "rotor (first cage) resistance referred to the stator, per phase"),
      number("motor.circuit.L_sigma_r", "H", P::Conditional, positive(), 0.0,
             "rotor (first cage) leakage inductance referred to the stator, per phase"),
      number("motor.circuit.R_r2", "Ω", P::Conditional, positive(), 0.0,
             "second rotor cage's resistance (double cage; with L_sigma_r2)"),
      number("motor.circuit.L_sigma_r2", "H", P::Conditional, positive(), 0.0,
             "second rotor cage's leakage inductance (double cage; with R_r2)"),
      number("motor.catalogue.power", "W", P::Conditional, positive(), 0.0,
             "P_n, rated shaft power"),
      number("motor.catalogue.omega_nominal", "rad/s", P::Conditional, positive(), 0.0,
             "omega_n, rated rotor speed (< omega0)"),
      number("motor.catalogue.current", "A", P::Conditional, positive(), 0.0,
             "I_n, rated line current at motor.voltage"),
      number("motor.catalogue.power_factor", "-", P::Conditional, between(0.0, false, 1.0, false), 0.0,
             "cos phi_n at the rated point"),
      number("motor.catalogue.efficiency", "-", P::Conditional, between(0.0, false, 1.0, false), 0.0,
             "eta_n at the rated point"),
      number("motor.catalogue.starting_torque_ratio", "-", P::Conditional, positive(), 0.0,
             "M_s/M_n, torque at standstill over the rated torque"),
      number("motor.catalogue.breakdown_torque_ratio", "-", P::Conditional,
             between(1.0, false, kInf, false), 0.0, "M_k/M_n, largest torque over the rated torque"),
      number("motor.catalogue.starting_current_ratio", "-", P::Conditional,
             between(1.0, false, kInf, false), 0.0, "I_s/I_n, current at standstill over the rated current"),
      integer("motor.catalogue.cages", P::Optional, between(1.0, true, 2.0, true), 2.0,
              "rotor cages of the circuit fitted to the catalogue (2 honours the starting torque)"),

      // Starting method and switch-off (scene/MotorSwitching.h, motor/Supply.h).
      choice("motor.start.method", P::Optional,
             {"direct_on_line", "star_delta", "soft_starter", "frequency_converter"}, "direct_on_line",
             "how the motor is switched on and brought up to speed"),
      number("motor.start.t_on", "s", P::Optional, nonNegative(), 0.0, "switch-on time"),
      number("motor.start.phase_deg", "deg", P::Optional, anyFinite(), 0.0,
             "point on the wave at switch-on: angle of the supply voltage phasor (phase a at its peak = 0)"),
      number("motor.start.changeover_time", "s", P::Conditional, positive(), 0.0,
             "star-delta: changeover to delta at this time (or motor.start.changeover_speed)"),
      number("motor.start.changeover_speed", "rad/s", P::Conditional, positive(), 0.0,
             "star-delta: changeover to delta when the rotor reaches this speed (or motor.start.changeover_time)"),
      number("motor.start.changeover_gap", "s", P::Optional, nonNegative(), 0.0,
             "star-delta: dead time of the open transition, stator disconnected"),
      number("motor.start.ramp_time", "s", P::Conditional, positive(), 0.0,
             "soft starter, frequency converter: duration t_ramp of the voltage or frequency ramp"),
      number("motor.start.initial_voltage", "-", P::Conditional, between(0.0, false, 1.0, true), 0.0,
             "soft starter: U_0/U_n at switch-on"),
      number("motor.start.current_limit", "A", P::Optional, nonNegative(), 0.0,
             "soft starter: RMS stator phase current the start is held to; 0 = none (motor models with a current only)"),
      number("motor.start.initial_frequency", "Hz", P::Conditional, positive(), 0.0,
             "frequency converter: f_0 at switch-on (< the rated frequency)"),
      number("motor.start.boost", "-", P::Optional, between(0.0, true, 1.0, false), 0.0,
             "frequency converter: voltage boost U/U_n at zero frequency, U/U_n = boost + (1 - boost)·f/f_n"),
      number("motor.stop.t_off", "s", P::Optional, positive(), kInf,
             "switch-off time (coast-down); absent = never"),
      number("motor.stop.brake_torque", "N·m", P::Optional, nonNegative(), 0.0,
             "mechanical brake torque on the motor shaft after switch-off, at the rotor; 0 = no brake"),
      number("motor.stop.brake_delay", "s", P::Optional, nonNegative(), 0.0,
             "the brake engages this long after the switch-off"),
      number("motor.stop.t_restart", "s", P::Optional, positive(), kInf,
             "reconnection direct on line at the rated supply after a switch-off (brake released); absent = never"),

      number("reducer.ratio", "-", P::Required, positive(), 0.0, "u = omega_rotor / omega_crank"),
      number("reducer.efficiency", "-", P::Required, between(0.0, false, 1.0, true), 0.0,
             "efficiency eta"),
      number("reducer.inertia", "kg·m²", P::Optional, nonNegative(), 0.0,
             "J_red referred to the motor shaft"),
      number("reducer.delta", "-", P::Optional, positive(), 1.0,
             "delta, Loveikin, Pochka, Romasevych (2018) eq. (1) factor on the motor-side inertia"),

      choice("coupling.type", P::Required, {"elastic", "rigid"}, "", "coupling model"),
      number("coupling.stiffness", "N·m/rad", P::Conditional, positive(), 0.0,
             "c reduced to the crank axis (required when elastic)"),
      number("coupling.damping", "N·m·s/rad", P::Optional, nonNegative(), 0.0,
             "k reduced to the crank axis"),
      number("coupling.inertia", "kg·m²", P::Optional, nonNegative(), 0.0,
             "J_m, coupling hub on the motor shaft"),

      number("flywheel.inertia", "kg·m²", P::Optional, nonNegative(), 0.0,
             "flywheel about its own shaft; 0 = none"),
      choice("flywheel.location", P::Optional, {"crankshaft", "motor_shaft"}, "crankshaft",
             "shaft carrying the flywheel"),

      number("loads.roller_force_front", "N", P::Optional, nonNegative(), 0.0,
             "F_j1, horizontal force on the front compacting roller"),
      number("loads.roller_force_rear", "N", P::Optional, nonNegative(), 0.0,
             "F_j2, horizontal force on the rear compacting roller"),
      number("loads.roller_normal_front", "N", P::Optional, nonNegative(), 0.0,
             "R_j1, upward reaction of the mix on the front roller"),
      number("loads.roller_normal_rear", "N", P::Optional, nonNegative(), 0.0,
             "R_j2, upward reaction of the mix on the rear roller"),
      choice("loads.roller_force_direction", P::Optional, {"opposes_velocity", "as_printed"},
             "opposes_velocity", "direction law of the horizontal roller forces"),
      number("loads.rolling_resistance", "-", P::Optional, between(0.0, true, 1.0, false), 0.0,
             "mu_r, rolling resistance of the compacting rollers: a force mu_r*(R_j1 + R_j2) against the cart's "
             "velocity, the energy compaction dissipates (docs/loads.md)"),
      number("loads.guide_friction.coefficient", "-", P::Optional,
             between(0.0, true, 1.0, false), 0.0, "f, reduced guide-roller friction coefficient"),
      choice("loads.guide_friction.normal_force", P::Conditional, {"algebraic", "lagged"}, "",
             "normal force of the multibody model's guide friction: the guide reaction of the same "
             "instant, solved with the motion (algebraic; minimal formulation) or followed with the "
             "lag tau_N (lagged); default algebraic with the minimal formulation, lagged with the "
             "constrained one"),
      number("loads.guide_friction.normal_force_lag", "s", P::Optional, between(0.0, false, 1.0, true),
             2e-3, "tau_N, time constant of the lagged friction normal force following the guide reaction (multibody)"),
      number("loads.gravity", "m/s²", P::Optional, nonNegative(), 9.81,
             "g; 0 = no gravity"),
      number("loads.velocity_smoothing", "m/s", P::Optional, positive(), 1e-3,
             "v_s in sign(v) ~ tanh(v/v_s)"),

      number("sizing.motor_nominal_torque", "N·m", P::Optional, positive(), 0.0,
             "M_n, nominal motor torque at the rotor (else P_n/omega_n, else M_kr/lambda)"),
      number("sizing.motor_nominal_power", "W", P::Optional, positive(), 0.0,
             "P_n, nominal motor shaft power; M_n = P_n/omega_n (needs motor.omega_nominal)"),
      number("sizing.motor_efficiency", "-", P::Optional, between(0.0, false, 1.0, true), 0.0,
             "eta_m, motor shaft power / power drawn from the line"),
      number("sizing.starts_per_hour", "1/h", P::Optional, nonNegative(), 0.0,
             "duty: starts of the motor per hour; the heating check adds each start's rotor heat to the "
             "steady running (absent or 0: continuous running; the console then gives the starts per hour "
             "the motor allows)"),
      number("sizing.target_delta", "-", P::Optional, positive(), 0.0,
             "coefficient of unevenness delta the flywheel should bring the run to"),
      number("sizing.coupling_rated_torque", "N·m", P::Optional, positive(), 0.0,
             "rated coupling torque, reduced to the crank axis"),
      number("sizing.bearing_rating.guide_roller", "N", P::Optional, positive(), 0.0,
             "C, basic dynamic load rating of one guide-roller bearing"),
      number("sizing.bearing_rating.rod_end", "N", P::Optional, positive(), 0.0,
             "C, basic dynamic load rating of the rod's small-end bearing (cart hinge)"),
      number("sizing.bearing_rating.crank_pin", "N", P::Optional, positive(), 0.0,
             "C, basic dynamic load rating of the rod's big-end bearing on the crank pin"),
      number("sizing.bearing_rating.main_bearing", "N", P::Optional, positive(), 0.0,
             "C, basic dynamic load rating of the crankshaft main bearing"),

      choice("reduced.kinematics", P::Optional, {"exact", "truncated"}, "exact",
             "slider-crank kinematics of the reduced model"),
      choice("reduced.integrator", P::Optional, {"cvode", "baranov"}, "cvode",
             "integrator of the reduced model"),
      number("reduced.baranov_step_deg", "deg", P::Optional, between(0.0, false, 10.0, true),
             1.0, "crank-angle step of the Baranov scheme"),
      choice("reduced.guide_normals", P::Optional, {"kinetostatic", "quasi_static"}, "kinetostatic",
             "guide normal forces of the reduced model (friction, reactions): with the cart's and "
             "rod's inertial forces, solved with the motion (kinetostatic), or the papers' cart "
             "statics without them (quasi_static)"),
  };
}

std::string joinChoices(const std::vector<std::string>& words) {
  std::string s;
  for (size_t i = 0; i < words.size(); ++i) s += (i ? ", " : "") + words[i];
  return s;
}

std::string describeRange(const Range& r) {
  const bool has_lo = std::isfinite(r.lo);
  const bool has_hi = std::isfinite(r.hi);
  if (has_lo && has_hi) {
    return std::string("in ") + (r.lo_inclusive ? "[" : "(") + formatNumber(r.lo) + ", " +
           formatNumber(r.hi) + (r.hi_inclusive ? "]" : ")");
  }
  if (has_lo) return std::string(r.lo_inclusive ? ">= " : "> ") + formatNumber(r.lo);
  if (has_hi) return std::string(r.hi_inclusive ? "<= " : "< ") + formatNumber(r.hi);
  return "";
}

}  // namespace

const std::vector<KeySpec>& sceneSchema() {
  static const std::vector<KeySpec> schema = buildSchema();
  return schema;
}

const KeySpec* findSceneKey(const std::string& path) {
  for (const KeySpec& k : sceneSchema())
    if (k.path == path) return &k;
  return nullptr;
}

bool isSceneMap(const std::string& path) {
  if (path.empty()) return true;
  const std::string prefix = path + ".";
  for (const KeySpec& k : sceneSchema())
    if (k.path.compare(0, prefix.size(), prefix) == 0) return true;
  return false;
}

std::vector<std::string> sceneChildKeys(const std::string& map_path) {
  const std::string prefix = map_path.empty() ? "" : map_path + ".";
  std::vector<std::string> children;
  for (const KeySpec& k : sceneSchema()) {
    if (k.path.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string rest = k.path.substr(prefix.size());
    const std::string child = rest.substr(0, rest.find('.'));
    bool seen = false;
    for (const std::string& c : children) seen = seen || c == child;
    if (!seen) children.push_back(child);
  }
  return children;
}

std::string describeExpected(const KeySpec& spec) {
  const std::string unit = (spec.unit.empty() || spec.unit == "-") ? "" : " [" + spec.unit + "]";
  switch (spec.kind) {
    case KeyKind::Number: {
      const std::string range = describeRange(spec.range);
      return (range.empty() ? "a finite number" : "a number " + range) + unit;
    }
    case KeyKind::Integer: {
      const std::string range = describeRange(spec.range);
      return range.empty() ? "an integer" : "an integer " + range;
    }
    case KeyKind::Text: return "a text scalar";
    case KeyKind::Choice: return "one of: " + joinChoices(spec.choices);
    case KeyKind::Flag: return "true or false";
    case KeyKind::Sides:
      return "a list of same/opposite with one entry per cart, or one of the words "
             "same, opposite, alternate";
  }
  return "?";
}

std::string formatNumber(double v) {
  std::ostringstream os;
  os.precision(12);
  os << v;
  return os.str();
}

}  // namespace rollerdyn
