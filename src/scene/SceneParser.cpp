#include "scene/SceneParser.h"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "scene/SceneDocument.h"
#include "scene/SceneSchema.h"

namespace rollerdyn {

namespace {

constexpr double kDegToRad = M_PI / 180.0;

// Typed, range-checked access to single keys of a SceneDocument, driven by the schema table:
// each read checks the YAML type, finiteness and the key's range and either returns the value,
// the key's default, or throws a located SceneError.
class Reader {
 public:
  explicit Reader(const SceneDocument& doc) : doc_(doc) {}

  bool has(const std::string& path) const { return doc_.find(path).IsDefined(); }

  // A Number key: its value, or its default when Optional and absent.
  double number(const std::string& path) const {
    const KeySpec& s = spec(path);
    if (!has(path)) return absent(s);
    return checkedNumber(s, doc_.find(path));
  }
  // A Number key that must be present here for a reason the schema cannot express.
  double requiredNumber(const std::string& path, const std::string& why) const {
    const KeySpec& s = spec(path);
    if (!has(path)) doc_.failMissing(path, describeExpected(s) + " (" + why + ")");
    return checkedNumber(s, doc_.find(path));
  }
  // A Conditional Number key with a fallback decided by the caller.
  double numberOr(const std::string& path, double fallback) const {
    return has(path) ? checkedNumber(spec(path), doc_.find(path)) : fallback;
  }

  int integer(const std::string& path) const {
    const KeySpec& s = spec(path);
    if (!has(path)) return static_cast<int>(absent(s));
    const YAML::Node n = scalar(s, doc_.find(path));
    long long v = 0;
    if (n.Tag() == "!" || !YAML::convert<long long>::decode(n, v)) fail(s, describeNode(n));
    if (!inRange(s.range, static_cast<double>(v))) fail(s, describeNode(n));
    return static_cast<int>(v);
  }

  std::string text(const std::string& path) const {
    const KeySpec& s = spec(path);
    if (!has(path)) {
      if (s.presence == Presence::Required) doc_.failMissing(path, describeExpected(s));
      return s.default_text;
    }
    return scalar(s, doc_.find(path)).Scalar();
  }

  // A Choice key: one of its words (case-sensitive, so a misspelling is never guessed at).
  std::string choice(const std::string& path) const {
    const std::string word = text(path);
    const KeySpec& s = spec(path);
    for (const std::string& c : s.choices)
      if (c == word) return word;
    fail(s, describeNode(doc_.find(path)));
  }

  bool flag(const std::string& path) const {
    const KeySpec& s = spec(path);
    if (!has(path)) return absent(s) != 0.0;
    const std::string v = scalar(s, doc_.find(path)).Scalar();
    // YAML 1.2 core booleans only; yaml-cpp would also take yes/no/on/off/y/n.
    if (v == "true" || v == "True" || v == "TRUE") return true;
    if (v == "false" || v == "False" || v == "FALSE") return false;
    fail(s, describeNode(doc_.find(path)));
  }

  [[noreturn]] void fail(const KeySpec& s, const std::string& got) const {
    doc_.fail(s.path, describeExpected(s), got);
  }

  const SceneDocument& doc() const { return doc_; }

 private:
  static const KeySpec& spec(const std::string& path) {
    const KeySpec* s = findSceneKey(path);
    if (!s) throw std::logic_error("SceneParser reads key '" + path + "' missing from the schema");
    return *s;
  }

  static bool inRange(const Range& r, double v) {
    if (r.lo_inclusive ? v < r.lo : v <= r.lo) return false;
    if (r.hi_inclusive ? v > r.hi : v >= r.hi) return false;
    return true;
  }

  double absent(const KeySpec& s) const {
    if (s.presence != Presence::Optional) doc_.failMissing(s.path, describeExpected(s));
    return s.default_number;
  }

  // The node itself if it is a scalar; otherwise a "got a map / a list / null" error.
  YAML::Node scalar(const KeySpec& s, const YAML::Node& n) const {
    if (!n.IsScalar()) fail(s, describeNode(n));
    return n;
  }

  double checkedNumber(const KeySpec& s, const YAML::Node& node) const {
    const YAML::Node n = scalar(s, node);
    double v = 0.0;
    // A quoted "10" is a string in YAML; a number must be written as a number.
    if (n.Tag() == "!" || !YAML::convert<double>::decode(n, v)) fail(s, describeNode(n));
    if (!std::isfinite(v)) doc_.fail(s.path, finite(describeExpected(s)), n.Scalar());
    if (!inRange(s.range, v)) fail(s, describeNode(n));
    return v;
  }

  // "a number > 0 [m]" -> "a finite number > 0 [m]": .nan and .inf parse as doubles in YAML.
  static std::string finite(const std::string& expected) {
    const std::string a_number = "a number";
    if (expected.compare(0, a_number.size(), a_number) == 0)
      return "a finite number" + expected.substr(a_number.size());
    return expected;
  }

  const SceneDocument& doc_;
};

// Whichever of two coupled keys came from a --set is the one to blame, so that an override that
// breaks a cross-key rule is reported as that override's fault.
bool blameSecond(const SceneDocument& doc, const std::string& first, const std::string& second) {
  return doc.overrideFor(second) > doc.overrideFor(first);
}

SimulationSettings readSimulation(const Reader& in) {
  SimulationSettings s;
  s.t_end = in.number("simulation.t_end");
  s.accuracy = in.number("simulation.accuracy");
  s.integrator = in.choice("simulation.integrator");
  s.formulation = in.choice("simulation.formulation") == "minimal" ? Formulation::Minimal
                                                                   : Formulation::Constrained;
  // A Simbody integrator only applies to the constrained formulation: never ignore it silently.
  if (s.formulation == Formulation::Minimal && in.has("simulation.integrator")) {
    const std::string why = "no simulation.integrator: the minimal formulation (simulation.formulation) "
                            "always integrates with CVODE Adams; set simulation.formulation: constrained "
                            "to use a Simbody integrator";
    if (blameSecond(in.doc(), "simulation.integrator", "simulation.formulation"))
      in.doc().fail("simulation.formulation", "constrained (simulation.integrator = " + s.integrator + " is set)",
                    "minimal");
    in.doc().fail("simulation.integrator", why, s.integrator);
  }
  s.output_step = in.number("simulation.output_step");
  s.reactions = in.flag("simulation.reactions");
  s.self_check_interval = in.has("simulation.self_check_interval") ? in.integer("simulation.self_check_interval") : 0;
  if (s.output_step > s.t_end) {
    const std::string t = formatNumber(s.t_end), dt = formatNumber(s.output_step);
    if (blameSecond(in.doc(), "simulation.output_step", "simulation.t_end")) {
      in.doc().fail("simulation.t_end",
                    "t_end >= output_step = " + dt + " s (simulation.output_step)", t);
    }
    in.doc().fail("simulation.output_step",
                  "a number in (0, t_end = " + t + "] [s] (simulation.t_end)", dt);
  }
  // The constraint projection cannot usefully be looser or tighter than the integration itself
  // unless asked for.
  s.constraint_tolerance = in.numberOr("simulation.constraint_tolerance", s.accuracy);
  s.steady_window_revolutions = in.number("simulation.steady_window_revolutions");
  return s;
}

InitialState readInitial(const Reader& in) {
  InitialState s;
  s.crank_angle = in.number("initial.crank_angle_deg") * kDegToRad;
  s.crank_speed = in.number("initial.crank_speed");
  s.twist = in.number("initial.twist");
  return s;
}

CrankShaft readCrank(const Reader& in) {
  CrankShaft c;
  c.radius = in.number("crank.radius");
  c.offset = in.number("crank.offset_deg") * kDegToRad;
  c.inertia_per_crank = in.number("crank.inertia_per_crank");
  c.shaft_inertia = in.number("crank.shaft_inertia");
  return c;
}

RodModel rodModelOf(const std::string& w) {
  if (w == "split") return RodModel::Split;
  if (w == "massless") return RodModel::Massless;
  return RodModel::Distributed;
}

ConnectingRods readRods(const Reader& in, double r) {
  ConnectingRods rods;
  rods.model = rodModelOf(in.choice("rods.model"));
  rods.length = in.number("rods.length");
  if (rods.length <= r) {
    // The crank-slider locks up (β reaches 90°) unless the rod is longer than the crank.
    const std::string l_txt = formatNumber(rods.length), r_txt = formatNumber(r);
    if (blameSecond(in.doc(), "rods.length", "crank.radius")) {
      in.doc().fail("crank.radius",
                    "r < l = " + l_txt + " m (rods.length), i.e. l > r", r_txt);
    }
    in.doc().fail("rods.length", "l > r = " + r_txt + " m (crank.radius)", l_txt);
  }
  if (rods.model == RodModel::Massless) {
    rods.mass = in.numberOr("rods.mass", 0.0);  // kept for reference; the models ignore it
  } else {
    rods.mass = in.requiredNumber("rods.mass", "required unless rods.model is massless");
    if (rods.mass <= 0.0) {
      in.doc().fail("rods.mass",
                    "a number > 0 [kg] (0 only with rods.model massless)",
                    formatNumber(rods.mass));
    }
  }
  // Uniform slender rod about its centre: m·l²/12 (Loveikin and Pochka (2007): I_s = q·l³/12 with m = q·l).
  rods.inertia_com =
      in.numberOr("rods.inertia_com", rods.mass * rods.length * rods.length / 12.0);
  return rods;
}

// drive.type and cam.*: the cam drive with optimal reversal of Loveikin and Pochka (Scene.h). Under a cam no rod is built, so the
// Scene gets massless rods; the rod keys stay validated so `--set drive.type=crank` works.
void readDrive(const Reader& in, Scene& s) {
  s.drive = in.choice("drive.type") == "cam" ? DriveType::Cam : DriveType::Crank;
  s.cam.stroke = s.drive == DriveType::Cam
                     ? in.requiredNumber("cam.stroke", "required when drive.type is cam")
                     : in.numberOr("cam.stroke", 0.0);
  // ρ = b/2 + x(θ) >= b/2 - Δx/2 must stay positive (Loveikin and Pochka (cam drive paper) eq. (38)-(43)).
  s.cam.pusher_distance = in.numberOr("cam.pusher_distance", 2.0 * s.cam.stroke);
  if (in.has("cam.pusher_distance") && s.cam.pusher_distance <= s.cam.stroke) {
    in.doc().fail("cam.pusher_distance",
                  "a number > cam.stroke = " + formatNumber(s.cam.stroke) + " [m]",
                  formatNumber(s.cam.pusher_distance));
  }
  if (s.drive == DriveType::Cam) s.rods = {RodModel::Massless, s.rods.length, 0.0, 0.0};
}

// carts.sides: +1 for a cart on the same side as cart 1 (x > 0, Loveikin, Pochka, Romasevych (2018)), -1 for the opposite
// side (Loveikin and Pochka's (2007) second cart).
std::vector<int> readSides(const Reader& in, int count) {
  const std::string path = "carts.sides";
  const KeySpec& spec = *findSceneKey(path);
  const SceneDocument& doc = in.doc();
  std::vector<int> sides(static_cast<size_t>(count), +1);
  if (!in.has(path)) return sides;
  const YAML::Node node = doc.find(path);
  if (node.IsScalar()) {
    const std::string w = node.Scalar();
    if (w == "same") return sides;
    if (w == "opposite") return std::vector<int>(static_cast<size_t>(count), -1);
    if (w == "alternate") {
      for (size_t j = 0; j < sides.size(); ++j) sides[j] = (j % 2 == 0) ? +1 : -1;
      return sides;
    }
  }
  if (!node.IsSequence()) in.fail(spec, describeNode(node));
  if (node.size() != static_cast<size_t>(count)) {
    const std::string want = "a list of " + std::to_string(count) +
                             " entries same/opposite, one per cart (carts.count = " +
                             std::to_string(count) + ")";
    if (blameSecond(doc, path, "carts.count")) {
      doc.fail("carts.count",
               "an integer equal to the length of carts.sides (" + std::to_string(node.size()) +
                   ")",
               std::to_string(count));
    }
    doc.fail(path, want, describeNode(node));
  }
  for (size_t j = 0; j < node.size(); ++j) {
    const YAML::Node e = node[j];
    const std::string w = e.IsScalar() ? e.Scalar() : "";
    if (w == "same") {
      sides[j] = +1;
    } else if (w == "opposite") {
      sides[j] = -1;
    } else {
      doc.fail(path + "[" + std::to_string(j) + "]", "same or opposite", describeNode(e));
    }
  }
  return sides;
}

Carts readCarts(const Reader& in) {
  Carts c;
  c.count = in.integer("carts.count");
  c.side = readSides(in, c.count);
  c.mass = in.number("carts.mass");
  CartGeometry& g = c.geometry;
  g.a = in.number("carts.geometry.a");
  g.b = in.numberOr("carts.geometry.b", 0.0);  // required with guide friction: see readScene()
  g.p = in.number("carts.geometry.p");
  g.e = in.number("carts.geometry.e");
  g.D = in.number("carts.geometry.D");
  g.d = in.number("carts.geometry.d");
  g.com_height = in.number("carts.geometry.com_height");
  return c;
}

// Kloss critical slip from exactly one of three equivalent descriptions.
double readCriticalSlip(const Reader& in, double omega0) {
  const SceneDocument& doc = in.doc();
  const std::string ways_txt =
      "exactly one of motor.critical_slip, motor.omega_critical, or "
      "motor.omega_nominal + motor.overload_ratio";
  std::vector<std::string> given;  // first key of each way present, in schema order
  if (in.has("motor.critical_slip")) given.push_back("motor.critical_slip");
  if (in.has("motor.omega_critical")) given.push_back("motor.omega_critical");
  if (in.has("motor.omega_nominal")) given.push_back("motor.omega_nominal");
  else if (in.has("motor.overload_ratio")) given.push_back("motor.overload_ratio");
  if (given.empty()) doc.failMissing("motor.critical_slip", ways_txt);
  if (given.size() > 1) {
    // Two descriptions could disagree; refuse rather than pick one silently. Blame the one a
    // --set added, if any (the latest), else the second in schema order.
    size_t blamed = 1;
    for (size_t i = 0; i < given.size(); ++i)
      if (doc.overrideFor(given[i]) > doc.overrideFor(given[blamed])) blamed = i;
    const std::string& other = given[blamed == 0 ? 1 : 0];
    doc.fail(given[blamed], ways_txt + " (" + other + " is given too)",
             describeNode(doc.find(given[blamed])));
  }
  const std::string& way = given[0];
  if (way == "motor.critical_slip") return in.number(way);  // range (0, 1) from the schema

  const std::string w0_txt = formatNumber(omega0);
  if (way == "motor.omega_critical") {
    const double w_kr = in.number(way);
    if (w_kr >= omega0) {
      doc.fail(way, "a number in (0, omega_sync = " + w0_txt + ") [rad/s]", formatNumber(w_kr));
    }
    return 1.0 - w_kr / omega0;  // Loveikin and Pochka (2007) eq. (7)
  }
  const double w_n =
      in.requiredNumber("motor.omega_nominal", "required with motor.overload_ratio");
  const double lambda =
      in.requiredNumber("motor.overload_ratio", "required with motor.omega_nominal");
  if (w_n >= omega0) {
    doc.fail("motor.omega_nominal", "a number in (0, omega_sync = " + w0_txt + ") [rad/s]",
             formatNumber(w_n));
  }
  const double s_n = 1.0 - w_n / omega0;
  const double s_kr = s_n * (lambda + std::sqrt(lambda * lambda - 1.0));  // Loveikin, Pochka, Romasevych (2018) eq. (37)
  if (s_kr >= 1.0) {
    doc.fail("motor.overload_ratio",
             "a value giving critical slip s_kr = s_n(lambda + sqrt(lambda^2 - 1)) < 1 with s_n = " +
                 formatNumber(s_n),
             formatNumber(lambda) + " (s_kr = " + formatNumber(s_kr) + ")");
  }
  return s_kr;
}

KlossMotor readMotor(const Reader& in) {
  KlossMotor m;
  m.enabled = in.flag("motor.enabled");
  m.omega_sync = in.number("motor.omega_sync");
  m.breakdown_torque = in.number("motor.breakdown_torque");
  m.critical_slip = readCriticalSlip(in, m.omega_sync);
  m.rotor_inertia = in.number("motor.rotor_inertia");
  return m;
}

Reducer readReducer(const Reader& in) {
  Reducer r;
  r.ratio = in.number("reducer.ratio");
  r.efficiency = in.number("reducer.efficiency");
  r.inertia = in.number("reducer.inertia");
  r.delta = in.number("reducer.delta");
  return r;
}

Coupling readCoupling(const Reader& in) {
  Coupling c;
  c.type = in.choice("coupling.type") == "rigid" ? CouplingType::Rigid : CouplingType::Elastic;
  // A rigid coupling ignores stiffness; it may stay in the file so that
  // `--set coupling.type=rigid` works on an elastic scene.
  c.stiffness = c.type == CouplingType::Elastic
                    ? in.requiredNumber("coupling.stiffness", "required when coupling.type is elastic")
                    : in.numberOr("coupling.stiffness", 0.0);
  c.damping = in.number("coupling.damping");
  c.inertia = in.number("coupling.inertia");
  return c;
}

Flywheel readFlywheel(const Reader& in) {
  Flywheel f;
  f.inertia = in.number("flywheel.inertia");
  f.location = in.choice("flywheel.location") == "motor_shaft" ? FlywheelLocation::MotorShaft
                                                               : FlywheelLocation::Crankshaft;
  return f;
}

// formulation: the multibody formulation, which decides the default normal-force law of the
// guide friction: algebraic where the minimal formulation's O(n) inverse-dynamics pass solves
// the loop (docs/friction-and-reactions.md, "Which normal force"), lagged in the constrained
// formulation, where the guide reaction is only known after Simbody's constrained solve.
Loads readLoads(const Reader& in, Formulation formulation) {
  Loads l;
  l.roller_force_front = in.number("loads.roller_force_front");
  l.roller_force_rear = in.number("loads.roller_force_rear");
  l.roller_normal_front = in.number("loads.roller_normal_front");
  l.roller_normal_rear = in.number("loads.roller_normal_rear");
  l.roller_force_direction = in.choice("loads.roller_force_direction") == "as_printed"
                                 ? RollerForceDirection::AsPrinted
                                 : RollerForceDirection::OpposesVelocity;
  l.guide_friction = in.number("loads.guide_friction.coefficient");
  l.gravity = in.number("loads.gravity");
  l.velocity_smoothing = in.number("loads.velocity_smoothing");
  l.guide_friction_lag = in.number("loads.guide_friction.normal_force_lag");
  const std::string normal_key = "loads.guide_friction.normal_force";
  const std::string normal = in.has(normal_key) ? in.choice(normal_key)
                             : formulation == Formulation::Minimal ? "algebraic"
                                                                   : "lagged";
  l.guide_normal_force = normal == "algebraic" ? GuideNormalForce::Algebraic : GuideNormalForce::Lagged;
  if (l.guide_normal_force == GuideNormalForce::Algebraic && formulation == Formulation::Constrained) {
    if (blameSecond(in.doc(), normal_key, "simulation.formulation"))
      in.doc().fail("simulation.formulation",
                    "minimal (loads.guide_friction.normal_force = algebraic needs the minimal formulation)",
                    "constrained");
    in.doc().fail(normal_key,
                  "lagged with simulation.formulation: constrained (the constrained formulation knows the "
                  "guide reaction only after Simbody's constrained solve, so it cannot solve the friction "
                  "loop algebraically; use simulation.formulation: minimal)",
                  normal);
  }
  return l;
}

ReducedSettings readReduced(const Reader& in) {
  ReducedSettings r;
  r.kinematics = in.choice("reduced.kinematics") == "truncated" ? KinematicsForm::Truncated
                                                                : KinematicsForm::Exact;
  r.integrator = in.choice("reduced.integrator") == "baranov" ? ReducedIntegrator::Baranov
                                                              : ReducedIntegrator::Cvode;
  r.baranov_step = in.number("reduced.baranov_step_deg") * kDegToRad;
  r.guide_normals = in.choice("reduced.guide_normals") == "quasi_static" ? ReducedGuideNormals::QuasiStatic
                                                                        : ReducedGuideNormals::Kinetostatic;
  return r;
}

// Ratings and targets of the sizing answers (SizingInputs.h); absent keys stay 0 = not given.
SizingInputs readSizing(const Reader& in) {
  SizingInputs z;
  z.motor_nominal_torque = in.number("sizing.motor_nominal_torque");
  z.motor_nominal_power = in.number("sizing.motor_nominal_power");
  z.motor_efficiency = in.number("sizing.motor_efficiency");
  z.target_delta = in.number("sizing.target_delta");
  z.coupling_rated_torque = in.number("sizing.coupling_rated_torque");
  z.rating_guide_roller = in.number("sizing.bearing_rating.guide_roller");
  z.rating_rod_end = in.number("sizing.bearing_rating.rod_end");
  z.rating_crank_pin = in.number("sizing.bearing_rating.crank_pin");
  z.rating_main_bearing = in.number("sizing.bearing_rating.main_bearing");
  if (in.has("motor.omega_nominal")) z.motor_omega_nominal = in.number("motor.omega_nominal");
  if (in.has("motor.overload_ratio")) z.motor_overload_ratio = in.number("motor.overload_ratio");
  if (z.motor_nominal_torque > 0 && z.motor_nominal_power > 0)
    in.doc().fail("sizing.motor_nominal_power",
                  "at most one of sizing.motor_nominal_torque and sizing.motor_nominal_power "
                  "(they could disagree)",
                  formatNumber(z.motor_nominal_power));
  if (z.motor_nominal_power > 0 && !(z.motor_omega_nominal > 0))
    in.doc().fail("sizing.motor_nominal_power",
                  "a nominal power together with motor.omega_nominal (M_n = P_n/omega_n)",
                  formatNumber(z.motor_nominal_power) + " without motor.omega_nominal");
  return z;
}

Scene readScene(const SceneDocument& doc) {
  const Reader in(doc);
  Scene s;
  s.source_path = doc.file();
  s.name = std::filesystem::path(doc.file()).stem().string();
  s.source = in.text("source");
  if (s.source.find_first_not_of(" \t\n") == std::string::npos) {
    doc.fail("source", "a citation of the source paper (non-empty text)", "empty text");
  }
  s.simulation = readSimulation(in);
  s.initial = readInitial(in);
  s.crank = readCrank(in);
  s.rods = readRods(in, s.crank.radius);
  s.carts = readCarts(in);
  s.motor = readMotor(in);
  s.reducer = readReducer(in);
  s.coupling = readCoupling(in);
  s.flywheel = readFlywheel(in);
  s.loads = readLoads(in, s.simulation.formulation);
  s.reduced = readReduced(in);
  readDrive(in, s);
  s.sizing = readSizing(in);

  // Guide reactions (Loveikin, Pochka, Romasevych (2018) eq. (18)-(25)) divide by 2b; with friction they drive the load.
  if (s.loads.guide_friction > 0.0) {
    const std::string want =
        "a number > 0 [m] (required when loads.guide_friction.coefficient > 0)";
    if (!in.has("carts.geometry.b")) doc.failMissing("carts.geometry.b", want);
    if (s.carts.geometry.b <= 0.0) doc.fail("carts.geometry.b", want, formatNumber(s.carts.geometry.b));
  }
  return s;
}

}  // namespace

Scene parseSceneText(const std::string& yaml_text, const std::string& file_label,
                     const std::vector<std::string>& overrides) {
  SceneDocument doc(yaml_text, file_label);
  for (size_t i = 0; i < overrides.size(); ++i) doc.applyOverride(static_cast<int>(i + 1), overrides[i]);
  doc.checkStructure();
  return readScene(doc);
}

Scene parseSceneFile(const std::string& path, const std::vector<std::string>& overrides) {
  std::ifstream f(path, std::ios::binary);
  if (!f) {
    throw SceneError::inFile(path, 0, "", "a readable scene file", std::strerror(errno));
  }
  std::ostringstream text;
  text << f.rdbuf();
  return parseSceneText(text.str(), path, overrides);
}

}  // namespace rollerdyn
