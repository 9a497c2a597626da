#include "scene/SceneParser.h"

#include "scene/DidYouMean.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "scene/MotorSwitchingParser.h"
#include "scene/SceneDocument.h"
#include "scene/SceneReader.h"
#include "scene/SceneSchema.h"

namespace rollerdyn {

using scene_detail::blameSecond;
using scene_detail::Reader;

namespace {

constexpr double kDegToRad = M_PI / 180.0;

// A Simbody integrator only applies to the constrained formulation: never ignore it silently.
void requireConstrainedForIntegrator(const Reader& in, const SimulationSettings& s) {
  if (!(s.formulation == Formulation::Minimal && in.has("simulation.integrator"))) return;
  const std::string why = "no simulation.integrator: the minimal formulation (simulation.formulation) "
                          "always integrates with CVODE Adams; set simulation.formulation: constrained "
                          "to use a Simbody integrator";
  if (blameSecond(in.doc(), "simulation.integrator", "simulation.formulation"))
    in.doc().fail("simulation.formulation", "constrained (simulation.integrator = " + s.integrator + " is set)",
                  "minimal");
  in.doc().fail("simulation.integrator", why, s.integrator);
}

// One output row at least: output_step within the run.
void requireOutputStepWithinRun(const Reader& in, const SimulationSettings& s) {
  if (!(s.output_step > s.t_end)) return;
  const std::string t = formatNumber(s.t_end), dt = formatNumber(s.output_step);
  if (blameSecond(in.doc(), "simulation.output_step", "simulation.t_end"))
    in.doc().fail("simulation.t_end", "t_end >= output_step = " + dt + " s (simulation.output_step)", t);
  in.doc().fail("simulation.output_step", "a number in (0, t_end = " + t + "] [s] (simulation.t_end)", dt);
}

SimulationSettings readSimulation(const Reader& in) {
  SimulationSettings s;
  s.t_end = in.number("simulation.t_end");
  s.accuracy = in.number("simulation.accuracy");
  s.integrator = in.choice("simulation.integrator");
  s.formulation = in.choiceOf<Formulation>("simulation.formulation");
  requireConstrainedForIntegrator(in, s);
  s.output_step = in.number("simulation.output_step");
  s.reactions = in.flag("simulation.reactions");
  s.self_check_interval = in.has("simulation.self_check_interval") ? in.integer("simulation.self_check_interval") : 0;
  requireOutputStepWithinRun(in, s);
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

// Whether crank.angles_deg gives the cranks' angles instead of crank.offset_deg: when it alone is
// given, or when a later --set gave it than the offset (so `--set crank.angles_deg=[...]` works on a
// scene file with an offset, and a --set of the offset on a file with angles). Both in the same
// place (the file, or one --set) could disagree: an error.
bool anglesReplaceOffset(const Reader& in) {
  const bool has_angles = in.has("crank.angles_deg"), has_offset = in.has("crank.offset_deg");
  if (!has_angles || !has_offset) return has_angles;
  const SceneDocument& doc = in.doc();
  const int set_angles = doc.overrideFor("crank.angles_deg"), set_offset = doc.overrideFor("crank.offset_deg");
  if (set_angles == set_offset)
    doc.fail("crank.angles_deg", "at most one of crank.offset_deg and crank.angles_deg (they could disagree)",
             describeNode(doc.find("crank.angles_deg")));
  return set_angles > set_offset;
}

CrankShaft readCrank(const Reader& in) {
  CrankShaft c;
  c.radius = in.number("crank.radius");
  // crank.angles_deg may replace crank.offset_deg (readCrankAngles()); one of them is required.
  c.offset = anglesReplaceOffset(in)
                 ? std::nan("")
                 : in.requiredNumber("crank.offset_deg", "required unless crank.angles_deg is given") * kDegToRad;
  c.inertia_per_crank = in.number("crank.inertia_per_crank");
  c.shaft_inertia = in.number("crank.shaft_inertia");
  return c;
}

// The rods' mass: >= 0 for massless rods (kept for reference; the models ignore it), > 0
// otherwise. The range is checked here, not in the schema, so that one rule gives one message.
double readRodMass(const Reader& in, RodModel model) {
  if (model == RodModel::Massless) {
    const double m = in.numberOr("rods.mass", 0.0);
    if (m < 0.0) in.doc().fail("rods.mass", "a number >= 0 [kg]", formatNumber(m));
    return m;
  }
  const double m = in.requiredNumber("rods.mass", "required unless rods.model is massless");
  if (m <= 0.0) in.doc().fail("rods.mass", "a number > 0 [kg] (0 only with rods.model massless)", formatNumber(m));
  return m;
}

ConnectingRods readRods(const Reader& in, double r) {
  ConnectingRods rods;
  rods.model = in.choiceOf<RodModel>("rods.model");
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
  rods.mass = readRodMass(in, rods.model);
  // Uniform slender rod about its centre: m·l²/12 (Loveikin and Pochka (2007): I_s = q·l³/12 with m = q·l).
  rods.inertia_com =
      in.numberOr("rods.inertia_com", rods.mass * rods.length * rods.length / 12.0);
  return rods;
}

// drive.type and cam.*: the cam drive with optimal reversal of Loveikin and Pochka (Scene.h). Under a cam no rod is built, so the
// Scene gets massless rods; the rod keys stay validated so `--set drive.type=crank` works.
void readDrive(const Reader& in, Scene& s) {
  s.drive = in.choiceOf<DriveType>("drive.type");
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

// The sides one word gives every cart: same, opposite or alternate (+1, -1, ...); none for any
// other word.
std::optional<std::vector<int>> sidesOfWord(const std::string& w, int count) {
  std::vector<int> sides(static_cast<size_t>(count), +1);
  if (w == "same") return sides;
  if (w == "opposite") return std::vector<int>(static_cast<size_t>(count), -1);
  if (w == "alternate") {
    for (size_t j = 0; j < sides.size(); ++j) sides[j] = (j % 2 == 0) ? +1 : -1;
    return sides;
  }
  return std::nullopt;
}

// One entry same/opposite per cart; a list of another length blames carts.count when a --set
// changed it last.
std::vector<int> sidesOfList(const Reader& in, const YAML::Node& node, int count) {
  const std::string path = "carts.sides";
  const SceneDocument& doc = in.doc();
  if (node.size() != static_cast<size_t>(count)) {
    const std::string want = "a list of " + std::to_string(count) +
                             " entries same/opposite, one per cart (carts.count = " + std::to_string(count) + ")";
    if (blameSecond(doc, path, "carts.count"))
      doc.fail("carts.count", "an integer equal to the length of carts.sides (" + std::to_string(node.size()) + ")",
               std::to_string(count));
    doc.fail(path, want, describeNode(node));
  }
  std::vector<int> sides(static_cast<size_t>(count), +1);
  for (size_t j = 0; j < node.size(); ++j) {
    const YAML::Node e = node[j];
    const std::string w = e.IsScalar() ? e.Scalar() : "";
    if (w == "same" || w == "opposite") sides[j] = w == "same" ? +1 : -1;
    else doc.fail(path + "[" + std::to_string(j) + "]", "same or opposite", describeNode(e));
  }
  return sides;
}

// carts.sides: +1 for a cart on the same side as cart 1 (x > 0, Loveikin, Pochka, Romasevych (2018)), -1 for the opposite
// side (Loveikin and Pochka's (2007) second cart).
std::vector<int> readSides(const Reader& in, int count) {
  const std::string path = "carts.sides";
  if (!in.has(path)) return std::vector<int>(static_cast<size_t>(count), +1);
  const YAML::Node node = in.doc().find(path);
  if (node.IsScalar())
    if (std::optional<std::vector<int>> sides = sidesOfWord(node.Scalar(), count)) return *sides;
  if (!node.IsSequence())
    in.fail(*findSceneKey(path), describeNode(node) + (node.IsScalar() ? didYouMean(node.Scalar(), {"same", "opposite", "alternate"})
                                                                       : std::string()));
  return sidesOfList(in, node, count);
}

// crank.angles_deg (each crank's nominal angle, instead of j·Δφ) and crank.angle_error_deg (each
// crank's deviation from it), docs/per-cart.md. Empty lists keep the uniform j·Δφ.
void readCrankAngles(const Reader& in, CrankShaft& c, int count) {
  const SceneDocument& doc = in.doc();
  if (anglesReplaceOffset(in)) {
    double uniform = 0.0;
    const std::vector<double> deg = in.perCartNumbers("crank.angles_deg", count, uniform);
    if (deg.empty())  // a single angle says nothing about the other cranks
      doc.fail("crank.angles_deg", describeExpectedList(*findSceneKey("crank.angles_deg"), count) +
                                       ", the first 0 (cart 1's crank)", formatNumber(uniform));
    if (deg[0] != 0.0)
      doc.fail("crank.angles_deg[0]",
               "0 for cart 1: the angles are measured from cart 1's crank (turn the whole shaft with "
               "initial.crank_angle_deg)",
               formatNumber(deg[0]));
    for (double a : deg) c.angles.push_back(a * kDegToRad);
  }
  double uniform_error = 0.0;
  const std::vector<double> errors = in.perCartNumbers("crank.angle_error_deg", count, uniform_error);
  for (double e : errors) c.angle_errors.push_back(e * kDegToRad);
  // One error common to every crank turns the whole shaft: allowed, kept as a list so that a
  // scene without the key keeps the uniform expression of Scene::crankPhase.
  if (errors.empty() && uniform_error != 0.0)
    c.angle_errors.assign(static_cast<size_t>(count), uniform_error * kDegToRad);
}

Carts readCarts(const Reader& in) {
  Carts c;
  c.count = in.integer("carts.count");
  c.side = readSides(in, c.count);
  c.masses = in.perCartNumbers("carts.mass", c.count, c.mass);
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

Reducer readReducer(const Reader& in) {
  Reducer r;
  r.ratio = in.number("reducer.ratio");
  r.efficiency = in.number("reducer.efficiency");
  r.losses = in.choiceOf<ReducerLossModel>("reducer.losses");
  // Absent: the same efficiency both ways (under papers the key has no effect: KeyEffects.cpp).
  r.efficiency_reverse = in.numberOr("reducer.efficiency_reverse", r.efficiency);
  r.inertia = in.number("reducer.inertia");
  r.delta = in.number("reducer.delta");
  r.backlash = in.number("reducer.backlash");
  return r;
}

Coupling readCoupling(const Reader& in) {
  Coupling c;
  c.type = in.choiceOf<CouplingType>("coupling.type");
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
  f.location = in.choiceOf<FlywheelLocation>("flywheel.location");
  return f;
}

// The loads; per_cart gets one entry per cart when any per-cart load key is a list (the others
// repeat their scalar there), and stays empty otherwise. formulation: the multibody formulation,
// which decides the default normal-force law of the guide friction: algebraic where the minimal
// formulation's O(n) inverse-dynamics pass solves the loop (docs/friction-and-reactions.md,
// "Which normal force"), lagged in the constrained formulation, where the guide reaction is only
// known after Simbody's constrained solve.
// The roller loads, per cart where a key gives a list (per_cart then holds every cart's loads;
// empty when every key gives one number).
void readRollerLoads(const Reader& in, int count, Loads& l, std::vector<CartLoads>& per_cart) {
  const std::vector<double> F1 = in.perCartNumbers("loads.roller_force_front", count, l.roller_force_front);
  const std::vector<double> F2 = in.perCartNumbers("loads.roller_force_rear", count, l.roller_force_rear);
  const std::vector<double> R1 = in.perCartNumbers("loads.roller_normal_front", count, l.roller_normal_front);
  const std::vector<double> R2 = in.perCartNumbers("loads.roller_normal_rear", count, l.roller_normal_rear);
  const std::vector<double> mu = in.perCartNumbers("loads.rolling_resistance", count, l.rolling_resistance);
  per_cart.clear();
  if (!F1.empty() || !F2.empty() || !R1.empty() || !R2.empty() || !mu.empty()) {
    auto at = [](const std::vector<double>& list, double uniform, int j) { return list.empty() ? uniform : list[j]; };
    for (int j = 0; j < count; ++j)
      per_cart.push_back({at(F1, l.roller_force_front, j), at(F2, l.roller_force_rear, j),
                          at(R1, l.roller_normal_front, j), at(R2, l.roller_normal_rear, j),
                          at(mu, l.rolling_resistance, j)});
  }
}

// The guide normal force the friction reads: algebraic needs the minimal formulation, whose
// default it is; lagged is the constrained formulation's.
GuideNormalForce readGuideNormalForce(const Reader& in, Formulation formulation) {
  const std::string normal_key = "loads.guide_friction.normal_force";
  const GuideNormalForce g = in.has(normal_key)                     ? in.choiceOf<GuideNormalForce>(normal_key)
                             : formulation == Formulation::Minimal ? GuideNormalForce::Algebraic
                                                                   : GuideNormalForce::Lagged;
  if (g == GuideNormalForce::Algebraic && formulation == Formulation::Constrained) {
    if (blameSecond(in.doc(), normal_key, "simulation.formulation"))
      in.doc().fail("simulation.formulation",
                    "minimal (loads.guide_friction.normal_force = algebraic needs the minimal formulation)",
                    "constrained");
    in.doc().fail(normal_key,
                  "lagged with simulation.formulation: constrained (the constrained formulation knows the "
                  "guide reaction only after Simbody's constrained solve, so it cannot solve the friction "
                  "loop algebraically; use simulation.formulation: minimal)",
                  toString(g));
  }
  return g;
}

Loads readLoads(const Reader& in, int count, Formulation formulation, std::vector<CartLoads>& per_cart) {
  Loads l;
  readRollerLoads(in, count, l, per_cart);
  l.roller_force_direction = in.choiceOf<RollerForceDirection>("loads.roller_force_direction");
  l.guide_friction = in.number("loads.guide_friction.coefficient");
  l.gravity = in.number("loads.gravity");
  l.velocity_smoothing = in.number("loads.velocity_smoothing");
  l.guide_friction_lag = in.number("loads.guide_friction.normal_force_lag");
  l.guide_normal_force = readGuideNormalForce(in, formulation);
  return l;
}

ReducedSettings readReduced(const Reader& in) {
  ReducedSettings r;
  r.kinematics = in.choiceOf<KinematicsForm>("reduced.kinematics");
  r.integrator = in.choiceOf<ReducedIntegrator>("reduced.integrator");
  r.baranov_step = in.number("reduced.baranov_step_deg") * kDegToRad;
  r.guide_normals = in.choiceOf<ReducedGuideNormals>("reduced.guide_normals");
  return r;
}

// Backlash: the teeth's contact stiffness and damping are the coupling's c, k, which a rigid
// coupling does not have (physics/CouplingLaw.h).
void requireElasticCouplingForBacklash(const Reader& in, const Scene& s) {
  if (s.reducer.backlash > 0.0 && s.coupling.type == CouplingType::Rigid)
    in.doc().fail("reducer.backlash",
                  "0 with coupling.type: rigid (the teeth in contact act through the coupling's stiffness and "
                  "damping: set coupling.type: elastic with coupling.stiffness, or reducer.backlash: 0)",
                  formatNumber(s.reducer.backlash));
}

// Guide reactions (Loveikin, Pochka, Romasevych (2018) eq. (18)-(25)) divide by 2b; with friction
// they drive the load.
void requireGuideBaseForFriction(const Reader& in, const Scene& s) {
  if (!(s.loads.guide_friction > 0.0)) return;
  const std::string want = "a number > 0 [m] (required when loads.guide_friction.coefficient > 0)";
  if (!in.has("carts.geometry.b")) in.doc().failMissing("carts.geometry.b", want);
  if (s.carts.geometry.b <= 0.0) in.doc().fail("carts.geometry.b", want, formatNumber(s.carts.geometry.b));
}

// Fewer than 10 output rows per crank revolution leave no metric worth printing: δ, the peaks,
// the steady state and the run-up are read from the rows (the second trial's 0.5 s step, 1.2
// rows per revolution, printed a run-up "to 95 % of 11.19 rad/s", above the synchronous crank
// speed of 10.69). Between 10 and 50 rows a warning says what it costs (Plausibility.h).
void requireRowsPerRevolution(const Reader& in, const Scene& s) {
  if (!(s.motor.enabled && s.motor.omega_sync > 0 && s.reducer.ratio > 0)) return;
  const double t_rev = 2.0 * M_PI * s.reducer.ratio / s.motor.omega_sync;
  auto g3 = [](double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.3g", v);
    return std::string(b);
  };
  if (s.simulation.output_step > t_rev / 10.0)
    in.doc().fail("simulation.output_step",
                  "at most " + g3(t_rev / 10.0) + " s: 10 output rows per crank revolution (" + g3(t_rev) +
                      " s at the synchronous crank speed ω0/u), better 50 or more (" + g3(t_rev / 50.0) +
                      " s), since δ, the peaks and the steady state are read from the rows",
                  formatNumber(s.simulation.output_step));
}

// The rules that tie keys of different sections together, checked once every section is read.
void checkAcrossSections(const Reader& in, const Scene& s) {
  requireElasticCouplingForBacklash(in, s);
  requireGuideBaseForFriction(in, s);
  requireRowsPerRevolution(in, s);
}

// The paper the scene cites: optional (a scene of one's own need not cite one), but not empty.
std::string readSourceCitation(const Reader& in) {
  const std::string source = in.text("source");
  if (in.has("source") && source.find_first_not_of(" \t\n") == std::string::npos) {
    in.doc().fail("source", "a citation of the source paper (non-empty text)", "empty text");
  }
  return source;
}

// The mechanism: crank, rods, carts, the cranks' angles and the crankshaft's layout.
void readMechanism(const Reader& in, Scene& s) {
  s.crank = readCrank(in);
  s.rods = readRods(in, s.crank.radius);
  s.carts = readCarts(in);
  readCrankAngles(in, s.crank, s.carts.count);
  s.crankshaft = scene_detail::readCrankshaft(in, s.carts.count);
}

Scene readScene(const SceneDocument& doc) {
  const Reader in(doc);
  Scene s;
  s.source_path = doc.file();
  s.name = std::filesystem::path(doc.file()).stem().string();
  s.source = readSourceCitation(in);
  s.simulation = readSimulation(in);
  s.initial = readInitial(in);
  readMechanism(in, s);
  scene_detail::readMotor(in, s.motor, s.induction);
  s.reducer = readReducer(in);
  s.coupling = readCoupling(in);
  s.flywheel = readFlywheel(in);
  s.loads = readLoads(in, s.carts.count, s.simulation.formulation, s.cart_loads);
  s.reduced = readReduced(in);
  readDrive(in, s);
  s.sizing = scene_detail::readSizing(in);
  readMotorSwitching(in, s);
  scene_detail::checkTorsionalChain(in, s);
  checkAcrossSections(in, s);
  return s;
}

}  // namespace

Scene parseSceneInput(const SceneInput& input, const std::vector<std::string>& overrides) {
  SceneDocument doc(input.text, input.label, !input.from_data);
  for (size_t i = 0; i < overrides.size(); ++i) doc.applyOverride(static_cast<int>(i + 1), overrides[i]);
  doc.checkStructure();
  Scene scene = readScene(doc);
  for (const KeySpec& k : sceneSchema())
    if (doc.find(k.path).IsDefined()) scene.given_keys.push_back(k.path);
  if (input.from_data) scene.name = input.label;  // a name, not a file whose stem names the scene
  return scene;
}

Scene parseSceneText(const std::string& yaml_text, const std::string& file_label,
                     const std::vector<std::string>& overrides) {
  return parseSceneInput(SceneInput{file_label, yaml_text, false}, overrides);
}

SceneInput readSceneInput(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) {
    throw SceneError::inFile(path, 0, "", "a readable scene file", std::strerror(errno));
  }
  std::ostringstream text;
  text << f.rdbuf();
  return SceneInput{path, text.str(), false};
}

Scene parseSceneFile(const std::string& path, const std::vector<std::string>& overrides) {
  return parseSceneInput(readSceneInput(path), overrides);
}

}  // namespace rollerdyn
