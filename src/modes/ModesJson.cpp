// modes.json: the modes report (ModalAnalysis.h) as JSON, one section per part of the analysis
// (the two-mass first estimate, the steady motions and their Floquet multipliers, the frozen-angle
// modes, the excitation orders, the Campbell diagram, the separation margins, the crankshaft chain,
// the stability charts).
#include <cmath>

#include "modes/ModalAnalysis.h"
#include "io/FieldFormat.h"

namespace rollerdyn::modes {
namespace {


nlohmann::json multipliersJson(const SteadyMotion& m) {
  nlohmann::json a = nlohmann::json::array();
  for (const ClassifiedMultiplier& c : m.multipliers)
    a.push_back({{"real", c.m.mu.real()},
                 {"imag", c.m.mu.imag()},
                 {"modulus", c.m.modulus},
                 {"mode", toString(c.kind)},
                 {"growth_rate", jsonNumber(c.m.growth_rate)},
                 {"frequency", jsonNumber(c.m.frequency)},
                 {"damping_ratio", jsonNumber(c.m.damping_ratio)}});
  return a;
}

nlohmann::json steadyJson(const SteadyMotion& m) {
  if (!m.found) return {{"found", false}, {"failure", m.failure}};
  const FloquetVerdict& v = m.verdict;
  return {{"found", true},
          {"omega_mean", m.omega_mean},
          {"period", m.period},
          {"newton_iterations", m.newton_iterations},
          {"evaluations", m.evaluations},
          {"multipliers", multipliersJson(m)},
          {"verdict", v.text},
          {"stable", v.stable},
          {"max_modulus", v.max_modulus},
          {"margin", v.margin},
          {"slowest_decay_rate", jsonNumber(v.slowest_decay_rate)},
          {"torsional_modulus", v.has_torsional ? jsonNumber(v.torsional_modulus) : nlohmann::json(nullptr)},
          {"torsional_frequency", v.has_torsional ? jsonNumber(v.torsional_frequency) : nlohmann::json(nullptr)},
          {"torsional_damping_ratio", v.has_torsional ? jsonNumber(v.torsional_damping_ratio) : nlohmann::json(nullptr)},
          {"torsional_resolved", v.has_torsional && v.torsional_resolved},
          {"resolution_note", "multipliers below 1e-6 are only known to be that small: their frequency and damping "
                              "ratio are not resolved by the integration"}};
}

nlohmann::json bandJson(const Band& b) { return {{"mean", jsonNumber(b.mean)}, {"min", jsonNumber(b.min)}, {"max", jsonNumber(b.max)}}; }

// The first estimate before any linearization: two constant inertias and the coupling between them.
nlohmann::json twoMassJson(const ModesReport& r) {
  return {
      {"method", "two constant inertias, Dyomin (two rotors) eq. (10), crank side at its mean over a revolution"},
      {"applicable", r.two_mass.applicable},
      {"J1", r.two_mass.J1},
      {"J2_mean", r.two_mass.J2_mean},
      {"stiffness", r.elastic ? jsonNumber(r.two_mass.stiffness) : nlohmann::json(nullptr)},
      {"p0", r.two_mass.applicable ? jsonNumber(r.two_mass.p0) : nlohmann::json(nullptr)}};
}

nlohmann::json frozenModesJson(const ModesReport& r) {
  nlohmann::json fz = nlohmann::json::array();
  for (const ModelFrozenModes& m : r.frozen) {
    if (!m.ok) {
      fz.push_back({{"model", m.model}, {"failure", m.failure}});
      continue;
    }
    fz.push_back({{"model", m.model},
                  {"torsional_mode", m.torsional_name.empty() ? nlohmann::json(nullptr) : nlohmann::json(m.torsional_name)},
                  {"rigid_mode", m.rigid_name},
                  {"torsional_frequency", bandJson(m.torsional)},
                  {"torsional_damping_ratio", bandJson(m.torsional_damping)},
                  {"torsional_natural_frequency", bandJson(m.torsional_natural)},
                  {"torsional_damped_frequency", m.torsional_overdamped_angles >= int(m.angles.size())
                                                     ? nlohmann::json(nullptr)
                                                     : bandJson(m.torsional_damped)},
                  {"torsional_overdamped_angles", m.torsional_overdamped_angles},
                  {"kinetic_energy_share", {{"motor_side", jsonNumber(m.energy_motor_side)},
                                            {"crankshaft_and_rods", jsonNumber(m.energy_shaft_rods)},
                                            {"carts", jsonNumber(m.energy_carts)}}},
                  {"angles", m.angles.size()}});
  }
  return fz;
}

nlohmann::json excitationOrdersJson(const ModesReport& r) {
  nlohmann::json ord = nlohmann::json::array();
  for (const OrderContent& c : r.orders.table)
    ord.push_back({{"order", c.order},
                   {"layout_factor", c.layout_factor},
                   {"inertia_amplitude", c.inertia_amplitude},
                   {"load_torque_amplitude", c.load_amplitude},
                   {"exciting_torque_amplitude", c.exciting_torque}});
  return {{"layout", r.orders.layout},
          {"forced", r.orders.forced},
          {"forced_threshold", "harmonic of the load torque plus J_n2'*omega^2/2 at least 1 % of the largest"},
          {"inertia", r.orders.inertia},
          {"load_torque", r.orders.load},
          {"all", r.orders.all},
          {"inertia_mean", r.orders.inertia_mean},
          {"inertia_relative_swing", r.orders.inertia_relative_swing},
          {"table", ord}};
}

nlohmann::json campbellJson(const ModesReport& r) {
  nlohmann::json cm;
  cm["applicable"] = r.campbell.applicable;
  if (!r.campbell.note.empty()) cm["note"] = r.campbell.note;
  cm["orders"] = r.campbell.orders;
  nlohmann::json cr = nlohmann::json::array();
  for (const CampbellCrossing& c : r.campbell.crossings)
    cr.push_back({{"order", c.order},
                  {"kind", c.parametric ? "parametric: 2p = k*omega" : "forced: p = k*omega"},
                  {"omega", c.omega},
                  {"frequency", c.frequency},
                  {"omega_band_low", jsonNumber(c.omega_band_low)},
                  {"omega_band_high", jsonNumber(c.omega_band_high)}});
  cm["crossings"] = cr;
  cm["overdamped_speeds"] = r.campbell.overdamped_speeds;
  return cm;
}

nlohmann::json stabilityChartsJson(const ModesReport& r) {
  nlohmann::json ch = nlohmann::json::array();
  for (const StabilityChart& c : r.charts) {
    nlohmann::json zones = nlohmann::json::array();
    for (const StabilityZone& z : c.zones)
      zones.push_back({{"points", z.points},
                       {"c_min", z.c_min},
                       {"c_max", z.c_max},
                       {c.y_key + "_min", z.y_min},
                       {c.y_key + "_max", z.y_max},
                       {"worst_modulus", z.worst_modulus}});
    ch.push_back({{"axes", c.y_key == "omega" ? "stiffness x crank speed" : "stiffness x damping"},
                  {"damping", jsonNumber(c.fixed_damping)},
                  {"omega", jsonNumber(c.fixed_speed)},
                  {"c_range", {c.c.front(), c.c.back()}},
                  {c.y_key + "_range", {c.y.front(), c.y.back()}},
                  {"grid", {c.c.size(), c.y.size()}},
                  {"operating_point", {{"c", jsonNumber(c.operating_c)}, {c.y_key, jsonNumber(c.operating_y)}}},
                  {"unstable_points", c.unstable_points},
                  {"failed_points", c.failed_points},
                  {"zones", zones}});
  }
  return ch;
}

// The reduced model's steady motion; without one, the speed the frozen-angle modes were taken at
// instead (null: none).
nlohmann::json reducedSteadyJson(const ModesReport& r) {
  nlohmann::json j = steadyJson(r.steady);
  j["model"] = "reduced";
  if (!r.steady.found) j["frozen_modes_at_omega"] = jsonNumber(r.fallback_omega);
  return j;
}

nlohmann::json multibodySteadyJson(const ModesReport& r) {
  nlohmann::json j = steadyJson(r.steady_multibody);
  j["friction_normal_force_lags"] = "quasi-static (normal forces of each state)";
  return j;
}

nlohmann::json approximationsJson(const ModesReport& r) {
  nlohmann::json a = nlohmann::json::array();
  for (const auto& [name, meaning] : r.approximations) a.push_back({{"name", name}, {"meaning", meaning}});
  return a;
}

}  // namespace

nlohmann::json modesJson(const ModesReport& r) {
  nlohmann::json j;
  j["scene"] = r.scene;
  j["coupling"] = r.elastic ? "elastic" : "rigid";
  j["cpu_seconds"] = r.cpu_seconds;
  j["first_estimate_two_mass"] = twoMassJson(r);
  j["steady_motion"] = reducedSteadyJson(r);
  if (r.has_multibody_steady) j["steady_motion_multibody"] = multibodySteadyJson(r);
  j["frozen_angle_modes"] = frozenModesJson(r);
  j["models_max_relative_difference"] = jsonNumber(r.model_difference);
  j["excitation_orders"] = excitationOrdersJson(r);
  j["campbell"] = campbellJson(r);
  j["separation_margins"] = separationJson(r.separation);
  j["crankshaft_chain"] = chainJson(r.chain);
  j["stability_charts"] = stabilityChartsJson(r);
  j["warnings"] = r.warnings;
  j["notes"] = r.notes;
  j["approximations"] = approximationsJson(r);
  return j;
}

}  // namespace rollerdyn::modes
