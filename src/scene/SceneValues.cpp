#include "scene/SceneValues.h"

#include <cstdio>
#include <functional>
#include <map>
#include <stdexcept>

#include "scene/MotorModels.h"
#include "scene/SceneChoices.h"
#include "scene/SceneSchema.h"

namespace rollerdyn {

namespace {

using Field = std::function<std::string(const Scene&)>;
using Fields = std::map<std::string, Field>;

std::string text(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}
std::string text(int v) { return std::to_string(v); }
std::string text(bool v) { return v ? "true" : "false"; }
std::string text(const std::string& v) { return v; }
std::string text(const char* v) { return v; }
template <class T>
std::string text(const std::vector<T>& list) {
  std::string s = "[";
  for (size_t i = 0; i < list.size(); ++i) s += (i ? ", " : "") + text(list[i]);
  return s + "]";
}

// The entry of a key whose field the getter returns.
template <class Get>
void add(Fields& f, const std::string& key, Get get) {
  f[key] = [get](const Scene& s) { return text(get(s)); };
}

void simulationFields(Fields& f) {
  add(f, "source", [](const Scene& s) { return s.source; });
  add(f, "simulation.t_end", [](const Scene& s) { return s.simulation.t_end; });
  add(f, "simulation.accuracy", [](const Scene& s) { return s.simulation.accuracy; });
  add(f, "simulation.integrator", [](const Scene& s) { return s.simulation.integrator; });
  add(f, "simulation.formulation", [](const Scene& s) { return toString(s.simulation.formulation); });
  add(f, "simulation.output_step", [](const Scene& s) { return s.simulation.output_step; });
  add(f, "simulation.reactions", [](const Scene& s) { return s.simulation.reactions; });
  add(f, "simulation.self_check_interval", [](const Scene& s) { return s.simulation.self_check_interval; });
  add(f, "simulation.constraint_tolerance", [](const Scene& s) { return s.simulation.constraint_tolerance; });
  add(f, "simulation.steady_window_revolutions", [](const Scene& s) { return s.simulation.steady_window_revolutions; });
  add(f, "initial.crank_angle_deg", [](const Scene& s) { return s.initial.crank_angle; });
  add(f, "initial.crank_speed", [](const Scene& s) { return s.initial.crank_speed; });
  add(f, "initial.twist", [](const Scene& s) { return s.initial.twist; });
}

void mechanismFields(Fields& f) {
  add(f, "crank.radius", [](const Scene& s) { return s.crank.radius; });
  add(f, "crank.offset_deg", [](const Scene& s) { return s.crank.offset; });
  add(f, "crank.angles_deg", [](const Scene& s) { return s.crank.angles; });
  add(f, "crank.angle_error_deg", [](const Scene& s) { return s.crank.angle_errors; });
  add(f, "crank.inertia_per_crank", [](const Scene& s) { return s.crank.inertia_per_crank; });
  add(f, "crank.shaft_inertia", [](const Scene& s) { return s.crank.shaft_inertia; });
  add(f, "crankshaft.throw_positions", [](const Scene& s) { return s.crankshaft.throw_positions; });
  add(f, "crankshaft.bearing_positions", [](const Scene& s) { return s.crankshaft.bearing_positions; });
  add(f, "crankshaft.bending_stiffness", [](const Scene& s) { return s.crankshaft.bending_stiffness; });
  add(f, "crankshaft.torsional_stiffness", [](const Scene& s) { return s.crankshaft.torsional_stiffness; });
  add(f, "crankshaft.torsional_damping", [](const Scene& s) { return s.crankshaft.torsional_damping; });
  add(f, "rods.model", [](const Scene& s) { return toString(s.rods.model); });
  add(f, "rods.length", [](const Scene& s) { return s.rods.length; });
  add(f, "rods.mass", [](const Scene& s) { return s.rods.mass; });
  add(f, "rods.inertia_com", [](const Scene& s) { return s.rods.inertia_com; });
  add(f, "drive.type", [](const Scene& s) { return toString(s.drive); });
  add(f, "cam.stroke", [](const Scene& s) { return s.cam.stroke; });
  add(f, "cam.pusher_distance", [](const Scene& s) { return s.cam.pusher_distance; });
}

void cartFields(Fields& f) {
  add(f, "carts.count", [](const Scene& s) { return s.carts.count; });
  add(f, "carts.sides", [](const Scene& s) { return s.carts.side; });
  add(f, "carts.mass", [](const Scene& s) { return s.carts.masses.empty() ? text(s.carts.mass) : text(s.carts.masses); });
  add(f, "carts.geometry.a", [](const Scene& s) { return s.carts.geometry.a; });
  add(f, "carts.geometry.b", [](const Scene& s) { return s.carts.geometry.b; });
  add(f, "carts.geometry.p", [](const Scene& s) { return s.carts.geometry.p; });
  add(f, "carts.geometry.e", [](const Scene& s) { return s.carts.geometry.e; });
  add(f, "carts.geometry.D", [](const Scene& s) { return s.carts.geometry.D; });
  add(f, "carts.geometry.d", [](const Scene& s) { return s.carts.geometry.d; });
  add(f, "carts.geometry.com_height", [](const Scene& s) { return s.carts.geometry.com_height; });
}

void motorFields(Fields& f) {
  add(f, "motor.enabled", [](const Scene& s) { return s.motor.enabled; });
  add(f, "motor.omega_sync", [](const Scene& s) { return s.motor.omega_sync; });
  add(f, "motor.breakdown_torque", [](const Scene& s) { return s.motor.breakdown_torque; });
  add(f, "motor.critical_slip", [](const Scene& s) { return s.motor.critical_slip; });
  add(f, "motor.omega_critical", [](const Scene&) { return "in motor.critical_slip"; });
  add(f, "motor.omega_nominal", [](const Scene& s) { return s.sizing.motor_omega_nominal; });
  add(f, "motor.overload_ratio", [](const Scene& s) { return s.sizing.motor_overload_ratio; });
  add(f, "motor.rotor_inertia", [](const Scene& s) { return s.motor.rotor_inertia; });
  add(f, "motor.model", [](const Scene& s) { return toString(s.induction.model); });
  for (const MotorModelInfo& law : motorModelTable())
    for (const MotorLawKey& own : law.own_keys)
      add(f, own.spec().path, [field = own.field](const Scene& s) { return s.induction.*field; });
  add(f, "motor.voltage", [](const Scene& s) { return s.induction.voltage; });
  add(f, "motor.frequency", [](const Scene& s) { return s.induction.frequency; });
  add(f, "motor.connection", [](const Scene& s) { return toString(s.induction.connection); });
  add(f, "motor.pole_pairs", [](const Scene& s) { return s.induction.pole_pairs; });
}

void machineFields(Fields& f) {
  add(f, "motor.circuit.R_s", [](const Scene& s) { return s.induction.circuit.R_s; });
  add(f, "motor.circuit.L_sigma_s", [](const Scene& s) { return s.induction.circuit.L_sigma_s; });
  add(f, "motor.circuit.L_m", [](const Scene& s) { return s.induction.circuit.L_m; });
  add(f, "motor.circuit.R_r", [](const Scene& s) { return s.induction.circuit.R_r; });
  add(f, "motor.circuit.L_sigma_r", [](const Scene& s) { return s.induction.circuit.L_sigma_r; });
  add(f, "motor.circuit.R_r2", [](const Scene& s) { return s.induction.circuit.R_r2; });
  add(f, "motor.circuit.L_sigma_r2", [](const Scene& s) { return s.induction.circuit.L_sigma_r2; });
  add(f, "motor.catalogue.power", [](const Scene& s) { return s.induction.catalogue.power; });
  add(f, "motor.catalogue.omega_nominal", [](const Scene& s) { return s.induction.catalogue.omega_nominal; });
  add(f, "motor.catalogue.current", [](const Scene& s) { return s.induction.catalogue.current; });
  add(f, "motor.catalogue.power_factor", [](const Scene& s) { return s.induction.catalogue.power_factor; });
  add(f, "motor.catalogue.efficiency", [](const Scene& s) { return s.induction.catalogue.efficiency; });
  add(f, "motor.catalogue.starting_torque_ratio",
      [](const Scene& s) { return s.induction.catalogue.starting_torque_ratio; });
  add(f, "motor.catalogue.breakdown_torque_ratio",
      [](const Scene& s) { return s.induction.catalogue.breakdown_torque_ratio; });
  add(f, "motor.catalogue.starting_current_ratio",
      [](const Scene& s) { return s.induction.catalogue.starting_current_ratio; });
  add(f, "motor.catalogue.cages", [](const Scene& s) { return s.induction.catalogue.cages; });
}

void switchingFields(Fields& f) {
  add(f, "motor.start.method", [](const Scene& s) { return toString(s.motor_start.method); });
  add(f, "motor.start.t_on", [](const Scene& s) { return s.motor_start.t_on; });
  add(f, "motor.start.phase_deg", [](const Scene& s) { return s.motor_start.phase; });
  add(f, "motor.start.changeover_time", [](const Scene& s) { return s.motor_start.changeover_time; });
  add(f, "motor.start.changeover_speed", [](const Scene& s) { return s.motor_start.changeover_speed; });
  add(f, "motor.start.changeover_gap", [](const Scene& s) { return s.motor_start.changeover_gap; });
  add(f, "motor.start.ramp_time", [](const Scene& s) { return s.motor_start.ramp_time; });
  add(f, "motor.start.initial_voltage", [](const Scene& s) { return s.motor_start.initial_voltage; });
  add(f, "motor.start.current_limit", [](const Scene& s) { return s.motor_start.current_limit; });
  add(f, "motor.start.max_start_time", [](const Scene& s) { return s.motor_start.max_start_time; });
  add(f, "motor.start.initial_frequency", [](const Scene& s) { return s.motor_start.initial_frequency; });
  add(f, "motor.start.boost", [](const Scene& s) { return s.motor_start.boost; });
  add(f, "motor.stop.t_off", [](const Scene& s) { return s.motor_stop.t_off; });
  add(f, "motor.stop.brake_torque", [](const Scene& s) { return s.motor_stop.brake_torque; });
  add(f, "motor.stop.brake_delay", [](const Scene& s) { return s.motor_stop.brake_delay; });
  add(f, "motor.stop.t_restart", [](const Scene& s) { return s.motor_stop.t_restart; });
}

void driveTrainFields(Fields& f) {
  add(f, "reducer.ratio", [](const Scene& s) { return s.reducer.ratio; });
  add(f, "reducer.efficiency", [](const Scene& s) { return s.reducer.efficiency; });
  add(f, "reducer.losses", [](const Scene& s) { return toString(s.reducer.losses); });
  add(f, "reducer.efficiency_reverse", [](const Scene& s) { return s.reducer.reverseEfficiency(); });
  add(f, "reducer.inertia", [](const Scene& s) { return s.reducer.inertia; });
  add(f, "reducer.delta", [](const Scene& s) { return s.reducer.delta; });
  add(f, "reducer.backlash", [](const Scene& s) { return s.reducer.backlash; });
  add(f, "coupling.type", [](const Scene& s) { return toString(s.coupling.type); });
  add(f, "coupling.stiffness", [](const Scene& s) { return s.coupling.stiffness; });
  add(f, "coupling.damping", [](const Scene& s) { return s.coupling.damping; });
  add(f, "coupling.inertia", [](const Scene& s) { return s.coupling.inertia; });
  add(f, "flywheel.inertia", [](const Scene& s) { return s.flywheel.inertia; });
  add(f, "flywheel.location", [](const Scene& s) { return toString(s.flywheel.location); });
}

// A per-cart load key: the uniform value, or the carts' values when the scene gives a list.
template <class Get>
void addPerCart(Fields& f, const std::string& key, Get get) {
  f[key] = [get](const Scene& s) {
    if (s.cart_loads.empty()) return text(get(s.loads));
    std::vector<double> v;
    for (int j = 0; j < s.carts.count; ++j) v.push_back(get(s.cartLoads(j)));
    return text(v);
  };
}

void loadFields(Fields& f) {
  addPerCart(f, "loads.roller_force_front", [](const Loads& l) { return l.roller_force_front; });
  addPerCart(f, "loads.roller_force_rear", [](const Loads& l) { return l.roller_force_rear; });
  addPerCart(f, "loads.roller_normal_front", [](const Loads& l) { return l.roller_normal_front; });
  addPerCart(f, "loads.roller_normal_rear", [](const Loads& l) { return l.roller_normal_rear; });
  addPerCart(f, "loads.rolling_resistance", [](const Loads& l) { return l.rolling_resistance; });
  add(f, "loads.roller_force_direction", [](const Scene& s) { return toString(s.loads.roller_force_direction); });
  add(f, "loads.guide_friction.coefficient", [](const Scene& s) { return s.loads.guide_friction; });
  add(f, "loads.guide_friction.normal_force", [](const Scene& s) { return toString(s.loads.guide_normal_force); });
  add(f, "loads.guide_friction.normal_force_lag", [](const Scene& s) { return s.loads.guide_friction_lag; });
  add(f, "loads.gravity", [](const Scene& s) { return s.loads.gravity; });
  add(f, "loads.velocity_smoothing", [](const Scene& s) { return s.loads.velocity_smoothing; });
  add(f, "reduced.kinematics", [](const Scene& s) { return toString(s.reduced.kinematics); });
  add(f, "reduced.integrator", [](const Scene& s) { return toString(s.reduced.integrator); });
  add(f, "reduced.baranov_step_deg", [](const Scene& s) { return s.reduced.baranov_step; });
  add(f, "reduced.guide_normals", [](const Scene& s) { return toString(s.reduced.guide_normals); });
}

void sizingFields(Fields& f) {
  add(f, "sizing.motor_nominal_torque", [](const Scene& s) { return s.sizing.motor_nominal_torque; });
  add(f, "sizing.motor_nominal_power", [](const Scene& s) { return s.sizing.motor_nominal_power; });
  add(f, "sizing.motor_efficiency", [](const Scene& s) { return s.sizing.motor_efficiency; });
  add(f, "sizing.starts_per_hour", [](const Scene& s) { return s.sizing.starts_per_hour; });
  add(f, "sizing.target_delta", [](const Scene& s) { return s.sizing.target_delta; });
  add(f, "sizing.coupling_rated_torque", [](const Scene& s) { return s.sizing.coupling_rated_torque; });
  add(f, "sizing.bearing_rating.guide_roller", [](const Scene& s) { return s.sizing.rating_guide_roller; });
  add(f, "sizing.bearing_rating.rod_end", [](const Scene& s) { return s.sizing.rating_rod_end; });
  add(f, "sizing.bearing_rating.crank_pin", [](const Scene& s) { return s.sizing.rating_crank_pin; });
  add(f, "sizing.bearing_rating.main_bearing", [](const Scene& s) { return s.sizing.rating_main_bearing; });
  add(f, "sizing.reducer.application_factor", [](const Scene& s) { return s.sizing.reducer.application_factor; });
  add(f, "sizing.reducer.rated_torque", [](const Scene& s) { return s.sizing.reducer.rated_torque; });
  add(f, "sizing.reducer.max_torque", [](const Scene& s) { return s.sizing.reducer.max_torque; });
  add(f, "sizing.reducer.sn_exponent", [](const Scene& s) { return s.sizing.reducer.sn_exponent; });
  add(f, "sizing.motor.locked_rotor_time", [](const Scene& s) { return s.sizing.motor.locked_rotor_time; });
  add(f, "sizing.motor.no_load_starts", [](const Scene& s) { return s.sizing.motor.no_load_starts; });
}

void snCurveFields(Fields& f, const std::string& prefix, SnCurve FatigueInputs::*curve) {
  add(f, prefix + ".endurance_amplitude", [curve](const Scene& s) { return (s.sizing.fatigue.*curve).endurance_amplitude; });
  add(f, prefix + ".knee_cycles", [curve](const Scene& s) { return (s.sizing.fatigue.*curve).knee_cycles; });
  add(f, prefix + ".slope", [curve](const Scene& s) { return (s.sizing.fatigue.*curve).slope; });
  add(f, prefix + ".ultimate", [curve](const Scene& s) { return (s.sizing.fatigue.*curve).ultimate; });
}

void signOffFields(Fields& f) {
  snCurveFields(f, "sizing.fatigue.coupling_torque", &FatigueInputs::coupling_torque);
  snCurveFields(f, "sizing.fatigue.rod_force", &FatigueInputs::rod_force);
  // The schema's first word is Haibach's extension, the second the plain cut-off.
  add(f, "sizing.fatigue.below_knee", [](const Scene& s) {
    return choiceWord(choiceKey("sizing.fatigue.below_knee"), s.sizing.fatigue.haibach ? 0 : 1);
  });
  add(f, "sizing.fatigue.required_starts", [](const Scene& s) { return s.sizing.fatigue.required_starts; });
  add(f, "sizing.fatigue.required_hours", [](const Scene& s) { return s.sizing.fatigue.required_hours; });
  add(f, "sizing.coupling.rated_torque", [](const Scene& s) { return s.sizing.coupling.rated_torque; });
  add(f, "sizing.coupling.max_torque", [](const Scene& s) { return s.sizing.coupling.max_torque; });
  add(f, "sizing.coupling.vibratory_torque", [](const Scene& s) { return s.sizing.coupling.vibratory_torque; });
  add(f, "sizing.coupling.damping_power", [](const Scene& s) { return s.sizing.coupling.damping_power; });
  add(f, "sizing.coupling.temperature_factor", [](const Scene& s) { return s.sizing.coupling.temperature_factor; });
  add(f, "sizing.coupling.start_factor", [](const Scene& s) { return s.sizing.coupling.start_factor; });
  add(f, "sizing.coupling.shock_factor", [](const Scene& s) { return s.sizing.coupling.shock_factor; });
}

const Fields& fields() {
  static const Fields table = [] {
    Fields f;
    for (auto section : {simulationFields, mechanismFields, cartFields, motorFields, machineFields, switchingFields,
                         driveTrainFields, loadFields, sizingFields, signOffFields})
      section(f);
    for (const auto& [key, field] : f)
      if (!findSceneKey(key)) throw std::logic_error("sceneValues(): '" + key + "' is no key of the scene schema");
    return f;
  }();
  return table;
}

}  // namespace

std::vector<std::pair<std::string, std::string>> sceneValues(const Scene& scene) {
  const Fields& table = fields();
  std::vector<std::pair<std::string, std::string>> values;
  for (const KeySpec& k : sceneSchema()) {
    const auto it = table.find(k.path);
    if (it == table.end()) throw std::logic_error("sceneValues(): the schema key '" + k.path + "' has no entry");
    values.emplace_back(k.path, it->second(scene));
  }
  return values;
}

}  // namespace rollerdyn
