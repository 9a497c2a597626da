#include "scene/KeyEffects.h"

#include <algorithm>

namespace rollerdyn {

namespace {

bool startsWith(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

// The rollers' half spacing a is the arm of their normal forces about the cart's centre of mass:
// R_j1·(p − a) + R_j2·(p + a) = (R_j1 + R_j2)·p + (R_j2 − R_j1)·a, so it acts only where the two
// normals of a cart differ.
bool rollerSpacingActs(const Scene& sc) {
  for (int j = 0; j < sc.carts.count; ++j) {
    const Loads l = sc.cartLoads(j);
    if (l.roller_normal_front != l.roller_normal_rear) return true;
  }
  return false;
}

std::string why(const std::string& key, const Scene& sc, const std::string& model) {
  const bool kloss = sc.induction.model == MotorModel::Kloss || sc.induction.model == MotorModel::KlossDynamic;
  if (model == "multibody" && startsWith(key, "reduced."))
    return "it sets the reduced-mass model (run it with --model reduced, or compare)";
  if (model == "reduced") {
    if (key == "simulation.formulation" || key == "simulation.integrator" || key == "simulation.self_check_interval")
      return "it sets the multibody model's integration (the reduced model's is reduced.integrator)";
    if (startsWith(key, "loads.guide_friction.normal_force"))
      return "it sets the multibody model's guide normal force (the reduced model's is reduced.guide_normals)";
    if (key == "sizing.bearing_rating.crank_pin" || key == "sizing.bearing_rating.main_bearing")
      return "the reduced model computes no crank-pin or main-bearing forces (run the multibody model for their lives)";
  }
  if (key == "reducer.efficiency_reverse" && sc.reducer.losses == ReducerLossModel::Papers)
    return "the papers' constant η (reducer.losses: papers) multiplies the motor torque by reducer.efficiency "
           "whichever way the power flows; set reducer.losses: power_flow for a reverse efficiency";
  if (key == "motor.connection")
    return "the laws use the equivalent star's per-phase values either way; a star-delta start is set by "
           "motor.start.method (the connection shows only in `rollerdyn motor`)";
  if (kloss && startsWith(key, "motor.circuit."))
    return "it sets the equivalent circuit (motor.model: circuit or park), not the Kloss law";
  if (key == "carts.geometry.a" && !rollerSpacingActs(sc))
    return "it is the arm of the rollers' normal forces about the cart, (R_j2 − R_j1)·a, and each cart's two "
           "normals are equal (loads.roller_normal_front = loads.roller_normal_rear)";
  return "";
}

}  // namespace

std::vector<std::string> keysWithoutEffect(const Scene& sc, const std::string& model) {
  std::vector<std::string> out;
  // A starting method's keys after a --set chose another method (the parser's own finding).
  for (const IgnoredKey& k : sc.ignored_keys) out.push_back(k.key + " (" + k.origin + ") has no effect: " + k.why);
  for (const std::string& key : sc.given_keys) {
    if (std::any_of(sc.ignored_keys.begin(), sc.ignored_keys.end(), [&](const IgnoredKey& k) { return k.key == key; }))
      continue;
    const std::string reason = why(key, sc, model);
    if (!reason.empty()) out.push_back(key + " has no effect on the " + model + " model's run: " + reason);
  }
  return out;
}

}  // namespace rollerdyn
