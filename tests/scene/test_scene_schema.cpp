// The schema table, the parser and the scene file reference agree: the reference generated from
// the schema documents every key and is the committed docs/scene-reference.md, and every key's
// value actually reaches the Scene.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "scene/SceneParser.h"
#include "scene/SceneReference.h"
#include "scene/SceneSchema.h"

namespace rollerdyn {
namespace {

std::string committedReference() {
  std::ifstream in(std::string(ROLLERDYN_SOURCE_DIR) + "/docs/scene-reference.md");
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Key paths in the first column of the reference's tables: rows starting "| `key` |".
std::set<std::string> documentedKeys(const std::string& markdown) {
  std::set<std::string> keys;
  const std::regex row(R"(^\| `([a-z_.A-Z0-9]+)` \|)");  // digits: motor.circuit.R_r2
  std::istringstream in(markdown);
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (std::regex_search(line, m, row)) keys.insert(m[1]);
  }
  return keys;
}

TEST(SceneReference, DocumentsEveryKeyAndNoOther) {
  const std::set<std::string> documented = documentedKeys(sceneReferenceMarkdown());
  std::set<std::string> schema;
  for (const KeySpec& k : sceneSchema()) schema.insert(k.path);
  EXPECT_EQ(documented, schema);
  EXPECT_GE(schema.size(), 50u);
}

TEST(SceneReference, CommittedPageIsTheGeneratedOne) {
  // docs/scene-reference.md is generated from the schema: regenerate it after changing the
  // schema with ./build/rollerdyn schema --markdown > docs/scene-reference.md
  const std::string committed = committedReference();
  ASSERT_FALSE(committed.empty()) << "docs/scene-reference.md is missing";
  EXPECT_TRUE(committed == sceneReferenceMarkdown())
      << "docs/scene-reference.md differs from the schema's reference: run\n"
         "  ./build/rollerdyn schema --markdown > docs/scene-reference.md";
}

TEST(SceneReference, EveryKeyHasMeaningAndEveryConditionalKeySaysWhen) {
  for (const SceneKeyDoc& k : sceneKeyDocs()) {
    EXPECT_FALSE(k.meaning.empty()) << k.key;
    EXPECT_FALSE(k.allowed.empty()) << k.key;
    if (k.presence == "conditional") {
      EXPECT_FALSE(k.condition.empty()) << k.key << ": say when it is required";
    }
    // An optional key has a default, except free text, which may be left out (source).
    if (k.presence == "optional" && findSceneKey(k.key)->kind != KeyKind::Text) {
      EXPECT_FALSE(k.default_value.empty()) << k.key;
    }
  }
  // Physical quantities of the papers carry their source.
  for (const char* key : {"crank.radius", "rods.length", "motor.breakdown_torque", "coupling.stiffness",
                          "loads.roller_force_front", "reduced.kinematics"})
    EXPECT_NE(findSceneKey(key)->source.find("("), std::string::npos) << key;
}

// A default the reference shows is a value the key accepts: typed back with --set it is taken
// (the reference showed sizing.motor_nominal_torque with default 0, which "> 0" refuses); keys
// whose absence means "not given" say so instead.
TEST(SceneReference, EveryDefaultShownIsAcceptedByItsKey) {
  const std::string scene = std::string(ROLLERDYN_SOURCE_DIR) + "/model/balanced-4cart.yaml";
  int not_given = 0, typed_back = 0;
  for (const KeySpec& k : sceneSchema()) {
    if (k.presence != Presence::Optional || (k.kind != KeyKind::Number && k.kind != KeyKind::Integer)) continue;
    const std::string shown = defaultText(k);
    if (shown == "not given") {
      ++not_given;
      continue;
    }
    ASSERT_FALSE(shown.empty()) << k.path;
    try {
      (void)parseSceneFile(scene, {k.path + "=" + shown});
      ++typed_back;
    } catch (const std::exception& e) {
      // Rules that couple keys may refuse a default beside the scene's other values; the key's
      // own range must not be what refuses it.
      const std::string what = e.what();
      EXPECT_EQ(what.find("expected " + describeExpected(k)), std::string::npos) << k.path << " = " << shown << ": " << what;
    }
  }
  EXPECT_GE(not_given, 5);
  EXPECT_GE(typed_back, 30);  // the rest are refused by rules coupling keys (a starting method's keys without it)
  EXPECT_EQ(defaultText(*findSceneKey("sizing.motor_nominal_torque")), "not given");
}

TEST(SceneReference, TableCellsEscapeTheBar) {
  const std::string md = sceneReferenceMarkdown();
  std::istringstream in(md);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("| `", 0) != 0) continue;
    std::size_t bars = 0;
    for (std::size_t i = 0; i < line.size(); ++i)
      if (line[i] == '|' && (i == 0 || line[i - 1] != '\\')) ++bars;
    EXPECT_EQ(bars, 7u) << line;  // six columns
  }
}

TEST(SceneSchema, FixedKeyPathsExist) {
  // Other commands and scripts rely on these exact paths.
  for (const char* k :
       {"simulation.t_end", "simulation.accuracy", "simulation.integrator", "crank.offset_deg",
        "carts.count", "rods.model", "coupling.type", "coupling.stiffness", "coupling.damping",
        "flywheel.inertia", "loads.roller_force_direction", "loads.guide_friction.coefficient",
        "reduced.kinematics", "reduced.baranov_step_deg", "initial.crank_angle_deg",
        "carts.geometry.a", "motor.critical_slip", "carts.sides"})
    EXPECT_NE(findSceneKey(k), nullptr) << k;
  EXPECT_TRUE(isSceneMap("loads.guide_friction"));
  EXPECT_FALSE(isSceneMap("loads.gravity"));
  EXPECT_EQ(sceneChildKeys("carts"),
            (std::vector<std::string>{"count", "sides", "mass", "geometry"}));
}

TEST(SceneSchema, ExpectedClauses) {
  EXPECT_EQ(describeExpected(*findSceneKey("crank.radius")), "a number > 0 [m]");
  EXPECT_EQ(describeExpected(*findSceneKey("reducer.efficiency")), "a number in (0, 1]");
  EXPECT_EQ(describeExpected(*findSceneKey("loads.guide_friction.coefficient")),
            "a number in [0, 1)");
  EXPECT_EQ(describeExpected(*findSceneKey("carts.count")), "an integer in [1, 1000]");
  EXPECT_EQ(describeExpected(*findSceneKey("coupling.type")), "one of: elastic, rigid");
  EXPECT_EQ(describeExpected(*findSceneKey("initial.twist")), "a finite number [rad]");
}

// Every key set to a value different from its default; each must land in the Scene.
const char* kFullScene = R"(source: every key
simulation:
  t_end: 3.0
  accuracy: 1.0e-5
  integrator: CPodes
  formulation: constrained
  output_step: 0.01
  reactions: false
  self_check_interval: 7
  constraint_tolerance: 1.0e-7
  steady_window_revolutions: 3
initial:
  crank_angle_deg: 45
  crank_speed: 2.0
  twist: 0.001
crank:
  radius: 0.25
  offset_deg: 60
  angle_error_deg: [0, 2, -1]
  inertia_per_crank: 0.5
  shaft_inertia: 0.7
crankshaft:
  throw_positions: [0.2, 0.5, 0.8]
  bearing_positions: [0, 0.35, 0.65, 1.0]
  bending_stiffness: 2.0e5
  torsional_stiffness: 7.85e5
  torsional_damping: 30
rods:
  model: split
  length: 0.9
  mass: 50
  inertia_com: 4.0
carts:
  count: 3
  sides: [opposite, same, opposite]
  mass: 900
  geometry:
    a: 0.1
    b: 0.2
    p: 0.3
    e: 0.4
    D: 0.5
    d: 0.06
    com_height: 0.7
motor:
  enabled: false
  omega_sync: 125.664
  breakdown_torque: 300
  critical_slip: 0.2
  rotor_inertia: 0.25
  model: park
  torque_time_constant: 0.05
  voltage: 400
  frequency: 60
  connection: delta
  pole_pairs: 3
  circuit:
    R_s: 0.1
    L_sigma_s: 0.002
    L_m: 0.05
    R_r: 0.3
    L_sigma_r: 0.001
    R_r2: 0.05
    L_sigma_r2: 0.004
  catalogue:
    power: 15000
    omega_nominal: 122
    current: 30
    power_factor: 0.87
    efficiency: 0.88
    starting_torque_ratio: 1.2
    breakdown_torque_ratio: 2.0
    starting_current_ratio: 6.0
    cages: 1
  start:
    method: soft_starter
    t_on: 0.5
    phase_deg: 30
    changeover_time: 1.5
    changeover_gap: 0.04
    ramp_time: 2.5
    initial_voltage: 0.4
    current_limit: 80
    max_start_time: 6
    initial_frequency: 5
    boost: 0.05
  stop:
    t_off: 2.0
    brake_torque: 150
    brake_delay: 0.1
    t_restart: 2.8
reducer:
  losses: power_flow
  efficiency_reverse: 0.75
  ratio: 12
  efficiency: 0.8
  inertia: 0.05
  delta: 1.1
  backlash: 0.003
coupling:
  type: elastic
  stiffness: 150000
  damping: 3000
  inertia: 0.4
flywheel:
  inertia: 20
  location: motor_shaft
loads:
  roller_force_front: 100
  roller_force_rear: 200
  roller_normal_front: 300
  roller_normal_rear: 400
  roller_force_direction: as_printed
  guide_friction:
    coefficient: 0.02
    normal_force: lagged
    normal_force_lag: 0.004
  gravity: 9.8
  velocity_smoothing: 0.01
  rolling_resistance: 0.05
reduced:
  kinematics: truncated
  integrator: baranov
  baranov_step_deg: 2
  guide_normals: quasi_static
drive:
  type: crank
cam:
  stroke: 0.45
  pusher_distance: 1.2
sizing:
  motor_nominal_torque: 120
  motor_efficiency: 0.9
  target_delta: 0.05
  starts_per_hour: 6
  coupling_rated_torque: 9000
  bearing_rating:
    guide_roller: 1000
    rod_end: 2000
    crank_pin: 3000
    main_bearing: 4000
  fatigue:
    coupling_torque: {endurance_amplitude: 900, knee_cycles: 2.0e+6, slope: 6, ultimate: 20000}
    rod_force: {endurance_amplitude: 30000, knee_cycles: 2.0e+6, slope: 5, ultimate: 600000}
    below_knee: cutoff
    required_starts: 100000
    required_hours: 20000
  coupling:
    vibratory_torque: 980
    damping_power: 100
    temperature_factor: 1.4
    start_factor: 1.2
    shock_factor: 1.5
  reducer:
    application_factor: 1.5
    rated_torque: 8000
    max_torque: 16000
    sn_exponent: 8.74
  motor:
    locked_rotor_time: 11
    no_load_starts: 700
)";

TEST(SceneSchema, FullSceneCoversTheSchema) {
  // If a key is added to the schema, this scene (and the checks below) must grow with it.
  for (const KeySpec& k : sceneSchema()) {
    // The critical slip has three alternative ways; the full scene uses way 1.
    if (k.path == "motor.omega_critical" || k.path == "motor.omega_nominal" ||
        k.path == "motor.overload_ratio" ||
        k.path == "sizing.motor_nominal_power" ||  // excludes motor_nominal_torque: test_scene_sizing
        k.path == "crank.angles_deg" ||  // the alternative of crank.offset_deg: test_scene_per_cart
        k.path == "motor.start.changeover_speed" ||  // the changeover's other way (changeover_time)
        // the makers' T_KN and T_Kmax exclude the single coupling_rated_torque: test_scene_sizing
        k.path == "sizing.coupling.rated_torque" || k.path == "sizing.coupling.max_torque")
      continue;
    const std::string leaf = k.path.substr(k.path.rfind('.') + 1);
    EXPECT_NE(std::string(kFullScene).find(leaf + ":"), std::string::npos) << k.path;
  }
}

TEST(SceneSchema, EveryKeyReachesTheScene) {
  // The file gives every starting method's keys; the method given again on the command line makes
  // those of the other methods warnings rather than errors (docs/startup.md), so all reach the Scene.
  const Scene s = parseSceneText(kFullScene, "full.yaml", {"motor.start.method=soft_starter"});
  const double deg = M_PI / 180.0;
  EXPECT_EQ(s.source, "every key");
  EXPECT_EQ(s.crankshaft.throw_positions, (std::vector<double>{0.2, 0.5, 0.8}));
  EXPECT_EQ(s.crankshaft.bearing_positions, (std::vector<double>{0, 0.35, 0.65, 1.0}));
  EXPECT_DOUBLE_EQ(s.crankshaft.bending_stiffness, 2.0e5);
  EXPECT_DOUBLE_EQ(s.crankshaft.torsional_stiffness, 7.85e5);
  EXPECT_DOUBLE_EQ(s.crankshaft.torsional_damping, 30);
  EXPECT_DOUBLE_EQ(s.simulation.t_end, 3.0);
  EXPECT_DOUBLE_EQ(s.simulation.accuracy, 1e-5);
  EXPECT_EQ(s.simulation.integrator, "CPodes");
  EXPECT_DOUBLE_EQ(s.simulation.output_step, 0.01);
  EXPECT_FALSE(s.simulation.reactions);
  EXPECT_EQ(s.simulation.self_check_interval, 7);
  EXPECT_EQ(s.loads.guide_normal_force, GuideNormalForce::Lagged);
  EXPECT_EQ(s.reduced.guide_normals, ReducedGuideNormals::QuasiStatic);
  EXPECT_DOUBLE_EQ(s.simulation.constraint_tolerance, 1e-7);
  EXPECT_DOUBLE_EQ(s.simulation.steady_window_revolutions, 3.0);
  EXPECT_DOUBLE_EQ(s.initial.crank_angle, 45 * deg);
  EXPECT_DOUBLE_EQ(s.initial.crank_speed, 2.0);
  EXPECT_DOUBLE_EQ(s.initial.twist, 0.001);
  EXPECT_DOUBLE_EQ(s.crank.radius, 0.25);
  EXPECT_DOUBLE_EQ(s.crank.offset, 60 * deg);
  EXPECT_EQ(s.crank.angle_errors, (std::vector<double>{0.0, 2 * deg, -1 * deg}));
  EXPECT_DOUBLE_EQ(s.crankPhase(1), 60 * deg + 2 * deg);
  EXPECT_DOUBLE_EQ(s.crank.inertia_per_crank, 0.5);
  EXPECT_DOUBLE_EQ(s.crank.shaft_inertia, 0.7);
  EXPECT_EQ(s.rods.model, RodModel::Split);
  EXPECT_DOUBLE_EQ(s.rods.length, 0.9);
  EXPECT_DOUBLE_EQ(s.rods.mass, 50.0);
  EXPECT_DOUBLE_EQ(s.rods.inertia_com, 4.0);
  EXPECT_EQ(s.carts.count, 3);
  EXPECT_EQ(s.carts.side, (std::vector<int>{-1, 1, -1}));
  EXPECT_DOUBLE_EQ(s.carts.mass, 900.0);
  EXPECT_DOUBLE_EQ(s.carts.geometry.a, 0.1);
  EXPECT_DOUBLE_EQ(s.carts.geometry.b, 0.2);
  EXPECT_DOUBLE_EQ(s.carts.geometry.p, 0.3);
  EXPECT_DOUBLE_EQ(s.carts.geometry.e, 0.4);
  EXPECT_DOUBLE_EQ(s.carts.geometry.D, 0.5);
  EXPECT_DOUBLE_EQ(s.carts.geometry.d, 0.06);
  EXPECT_DOUBLE_EQ(s.carts.geometry.com_height, 0.7);
  EXPECT_FALSE(s.motor.enabled);
  EXPECT_DOUBLE_EQ(s.motor.omega_sync, 125.664);
  EXPECT_DOUBLE_EQ(s.motor.breakdown_torque, 300.0);
  EXPECT_DOUBLE_EQ(s.motor.critical_slip, 0.2);
  EXPECT_DOUBLE_EQ(s.motor.rotor_inertia, 0.25);
  const InductionMotor& im = s.induction;
  EXPECT_EQ(im.model, MotorModel::Park);
  EXPECT_DOUBLE_EQ(im.torque_time_constant, 0.05);
  EXPECT_DOUBLE_EQ(im.voltage, 400.0);
  EXPECT_DOUBLE_EQ(im.frequency, 60.0);
  EXPECT_EQ(im.connection, WindingConnection::Delta);
  EXPECT_EQ(im.pole_pairs, 3);
  EXPECT_DOUBLE_EQ(im.circuit.R_s, 0.1);
  EXPECT_DOUBLE_EQ(im.circuit.L_sigma_s, 0.002);
  EXPECT_DOUBLE_EQ(im.circuit.L_m, 0.05);
  EXPECT_DOUBLE_EQ(im.circuit.R_r, 0.3);
  EXPECT_DOUBLE_EQ(im.circuit.L_sigma_r, 0.001);
  EXPECT_DOUBLE_EQ(im.circuit.R_r2, 0.05);
  EXPECT_DOUBLE_EQ(im.circuit.L_sigma_r2, 0.004);
  EXPECT_DOUBLE_EQ(im.catalogue.power, 15000.0);
  EXPECT_DOUBLE_EQ(im.catalogue.omega_nominal, 122.0);
  EXPECT_DOUBLE_EQ(im.catalogue.current, 30.0);
  EXPECT_DOUBLE_EQ(im.catalogue.power_factor, 0.87);
  EXPECT_DOUBLE_EQ(im.catalogue.efficiency, 0.88);
  EXPECT_DOUBLE_EQ(im.catalogue.starting_torque_ratio, 1.2);
  EXPECT_DOUBLE_EQ(im.catalogue.breakdown_torque_ratio, 2.0);
  EXPECT_DOUBLE_EQ(im.catalogue.starting_current_ratio, 6.0);
  EXPECT_EQ(im.catalogue.cages, 1);
  EXPECT_EQ(s.motor_start.method, StartMethod::SoftStarter);
  EXPECT_DOUBLE_EQ(s.motor_start.t_on, 0.5);
  EXPECT_DOUBLE_EQ(s.motor_start.phase, 30 * deg);
  EXPECT_DOUBLE_EQ(s.motor_start.changeover_time, 1.5);
  EXPECT_DOUBLE_EQ(s.motor_start.changeover_gap, 0.04);
  EXPECT_DOUBLE_EQ(s.motor_start.ramp_time, 2.5);
  EXPECT_DOUBLE_EQ(s.motor_start.initial_voltage, 0.4);
  EXPECT_DOUBLE_EQ(s.motor_start.current_limit, 80.0);
  EXPECT_DOUBLE_EQ(s.motor_start.max_start_time, 6.0);
  EXPECT_DOUBLE_EQ(s.motor_start.initial_frequency, 5.0);
  EXPECT_DOUBLE_EQ(s.motor_start.boost, 0.05);
  EXPECT_DOUBLE_EQ(s.motor_stop.t_off, 2.0);
  EXPECT_DOUBLE_EQ(s.motor_stop.brake_torque, 150.0);
  EXPECT_DOUBLE_EQ(s.motor_stop.brake_delay, 0.1);
  EXPECT_DOUBLE_EQ(s.motor_stop.t_restart, 2.8);
  EXPECT_DOUBLE_EQ(s.reducer.ratio, 12.0);
  EXPECT_DOUBLE_EQ(s.reducer.efficiency, 0.8);
  EXPECT_DOUBLE_EQ(s.reducer.inertia, 0.05);
  EXPECT_DOUBLE_EQ(s.reducer.delta, 1.1);
  EXPECT_EQ(s.reducer.losses, ReducerLossModel::PowerFlow);
  EXPECT_DOUBLE_EQ(s.reducer.efficiency_reverse, 0.75);
  EXPECT_DOUBLE_EQ(s.reducer.backlash, 0.003);
  EXPECT_EQ(s.coupling.type, CouplingType::Elastic);
  EXPECT_DOUBLE_EQ(s.coupling.stiffness, 150000.0);
  EXPECT_DOUBLE_EQ(s.coupling.damping, 3000.0);
  EXPECT_DOUBLE_EQ(s.coupling.inertia, 0.4);
  EXPECT_DOUBLE_EQ(s.flywheel.inertia, 20.0);
  EXPECT_EQ(s.flywheel.location, FlywheelLocation::MotorShaft);
  EXPECT_DOUBLE_EQ(s.loads.roller_force_front, 100.0);
  EXPECT_DOUBLE_EQ(s.loads.roller_force_rear, 200.0);
  EXPECT_DOUBLE_EQ(s.loads.roller_normal_front, 300.0);
  EXPECT_DOUBLE_EQ(s.loads.roller_normal_rear, 400.0);
  EXPECT_EQ(s.loads.roller_force_direction, RollerForceDirection::AsPrinted);
  EXPECT_DOUBLE_EQ(s.loads.guide_friction, 0.02);
  EXPECT_DOUBLE_EQ(s.loads.gravity, 9.8);
  EXPECT_DOUBLE_EQ(s.loads.velocity_smoothing, 0.01);
  EXPECT_DOUBLE_EQ(s.loads.rolling_resistance, 0.05);
  EXPECT_DOUBLE_EQ(s.loads.guide_friction_lag, 0.004);
  EXPECT_EQ(s.reduced.kinematics, KinematicsForm::Truncated);
  EXPECT_EQ(s.reduced.integrator, ReducedIntegrator::Baranov);
  EXPECT_DOUBLE_EQ(s.reduced.baranov_step, 2 * deg);
  EXPECT_EQ(s.drive, DriveType::Crank);
  EXPECT_DOUBLE_EQ(s.cam.stroke, 0.45);
  EXPECT_DOUBLE_EQ(s.cam.pusher_distance, 1.2);
  EXPECT_DOUBLE_EQ(s.sizing.motor_nominal_torque, 120.0);
  EXPECT_DOUBLE_EQ(s.sizing.motor_efficiency, 0.9);
  EXPECT_DOUBLE_EQ(s.sizing.target_delta, 0.05);
  EXPECT_DOUBLE_EQ(s.sizing.starts_per_hour, 6.0);
  EXPECT_DOUBLE_EQ(s.sizing.coupling_rated_torque, 9000.0);
  EXPECT_DOUBLE_EQ(s.sizing.rating_guide_roller, 1000.0);
  EXPECT_DOUBLE_EQ(s.sizing.rating_rod_end, 2000.0);
  EXPECT_DOUBLE_EQ(s.sizing.rating_crank_pin, 3000.0);
  EXPECT_DOUBLE_EQ(s.sizing.rating_main_bearing, 4000.0);
  EXPECT_DOUBLE_EQ(s.sizing.reducer.application_factor, 1.5);
  EXPECT_DOUBLE_EQ(s.sizing.reducer.rated_torque, 8000.0);
  EXPECT_DOUBLE_EQ(s.sizing.reducer.max_torque, 16000.0);
  EXPECT_DOUBLE_EQ(s.sizing.reducer.sn_exponent, 8.74);
  EXPECT_DOUBLE_EQ(s.sizing.motor.locked_rotor_time, 11.0);
  EXPECT_DOUBLE_EQ(s.sizing.motor.no_load_starts, 700.0);
}

}  // namespace
}  // namespace rollerdyn
