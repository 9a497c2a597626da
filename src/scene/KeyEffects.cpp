#include "scene/KeyEffects.h"

#include <algorithm>
#include <cmath>

#include "scene/NominalTorqueSource.h"
#include "scene/SceneSchema.h"
#include "scene/MotorModels.h"

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

// The equivalent circuit's current data: the Kloss laws have no stator current, so under them
// these keys only feed `rollerdyn motor` and a run with motor.model circuit or park.
bool isCurrentData(const std::string& key) {
  return key == "motor.voltage" || key == "motor.catalogue.current" || key == "motor.catalogue.power_factor" ||
         key == "motor.catalogue.efficiency" || key == "motor.catalogue.starting_current_ratio" ||
         key == "motor.catalogue.cages";
}

// The cart's moment balance about the rod hinge B (reduced/CartStatics.h) holds the arms p, b, a,
// e, d/2 and com_height. Its only unknown beyond ΣX and ΣY is how the guide normal splits between
// the two guide rollers, N1 against N2, and a run uses that split only through the guide friction
// φ_f·f·(|N1| + |N2|) (with the self-locking test) and through the reactions: guide-roller loads
// and lives at |v|/(d/2), lift-off. The multibody model is the same: the guides' prismatic joint
// takes every moment on the cart, and the arms only place forces on a body that cannot turn.
bool isCartMomentArm(const std::string& key) {
  return key == "carts.geometry.p" || key == "carts.geometry.b" || key == "carts.geometry.a" ||
         key == "carts.geometry.e" || key == "carts.geometry.d" || key == "carts.geometry.com_height";
}
bool guideSplitActs(const Scene& sc) { return sc.hasGuideFriction() || sc.simulation.reactions; }

// The depth e is the arm of the compacting rollers' horizontal force H (physics/RollerLoads.h), which
// is zero at every speed where a cart has neither roller forces nor rolling resistance.
bool rollerForceActs(const Scene& sc) {
  for (int j = 0; j < sc.carts.count; ++j) {
    const Loads l = sc.cartLoads(j);
    if (l.roller_force_front + l.roller_force_rear != 0.0 ||
        l.rolling_resistance * (l.roller_normal_front + l.roller_normal_rear) != 0.0)
      return true;
  }
  return false;
}

// Kloss's critical slip s_kr, in any of its three descriptions.
bool isKlossSlip(const std::string& key) {
  return key == "motor.critical_slip" || key == "motor.omega_critical" || key == "motor.overload_ratio";
}

// Keys of events the run's end comes before: the motor switched off, restarted or changed over to
// delta at or after t_end.
std::string afterTheRunsEnd(const std::string& key, const Scene& sc) {
  const double t_end = sc.simulation.t_end;
  const MotorStop& stop = sc.motor_stop;
  if (startsWith(key, "motor.stop.") && !(stop.t_off < t_end))
    return "the motor is switched off at or after the run's end (motor.stop.t_off, t_end = " + formatNumber(t_end) +
           " s), so the run holds no stop";
  if (key == "motor.stop.t_restart" && !(stop.t_restart < t_end))
    return "the restart comes at or after the run's end (simulation.t_end)";
  if ((key == "motor.stop.brake_torque" || key == "motor.stop.brake_delay") && !(stop.t_off + stop.brake_delay < t_end))
    return "the brake would engage at or after the run's end (motor.stop.t_off + motor.stop.brake_delay)";
  const MotorStart& start = sc.motor_start;
  if (start.method == StartMethod::StarDelta && std::isfinite(start.changeover_time) &&
      (key == "motor.start.changeover_time" || key == "motor.start.changeover_gap") &&
      !(start.changeover_time < t_end))
    return "the changeover to delta would come at or after the run's end (simulation.t_end): the whole run is in star";
  return "";
}

// Keys the other model reads.
std::string whyNotThisModel(const std::string& key, const std::string& model) {
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
  return "";
}

// Keys that set results this run does not compute (reactions, a bearing's share).
std::string whyNotTheseResults(const std::string& key, const Scene& sc, const std::string& model) {
  // The ratings turn joint loads into lives; without reactions no joint is loaded (a rating names
  // the joint whose life it gives, and that joint's loads are the reactions).
  if (startsWith(key, "sizing.bearing_rating.") && !sc.simulation.reactions)
    return "no reactions are computed (simulation.reactions: false), so no joint's load and no rating life";
  if (key == "crankshaft.bending_stiffness")
    return "with one E·I along the whole shaft on rigid supports the main bearings' reactions do not depend on "
           "its value, with two bearings or more (the continuous beam's reactions follow from the positions alone)";
  if (key == "crankshaft.torsional_stiffness" && model == "reduced")
    return "the reduced model keeps the papers' rigid crankshaft (one crank angle for every cart); the torsional "
           "chain is the multibody model's";
  if ((key == "crankshaft.throw_positions" || key == "crankshaft.bearing_positions") && model == "reduced")
    return "the reduced model computes no crank-pin forces, which each main bearing's share needs (run the "
           "multibody model)";
  if ((key == "crankshaft.throw_positions" || key == "crankshaft.bearing_positions") && !sc.simulation.reactions)
    return "no reactions are computed (simulation.reactions: false), so no bearing's share either";
  return "";
}

// The keys a law on the Kloss curve does not read: the machine's circuit and currents, and f_n
// unless a converter or the dynamic law's default T_e reads it.
std::string whyNotTheKlossLaw(const std::string& key, const Scene& sc) {
  if (startsWith(key, "motor.circuit."))
    return "it sets the equivalent circuit (motor.model: " + motorModelWords(false, "or") + "), not the Kloss law";
  // f_n: the speed of a Kloss law is motor.omega_sync; f_n only turns a converter's frequencies
  // into ratios and gives the dynamic Kloss law its default T_e = 1/(2π·f_n·s_kr).
  if (key == "motor.frequency" && sc.motor_start.method != StartMethod::FrequencyConverter &&
      (sc.induction.model != MotorModel::KlossDynamic || sc.induction.torque_time_constant > 0))
    return "a Kloss law's speed is motor.omega_sync; f_n only scales a frequency converter's frequencies and "
           "sets the dynamic Kloss law's default T_e = 1/(2π·f_n·s_kr)";
  if (isCurrentData(key))
    return "the Kloss law has no stator current: it is the equivalent circuit's data (motor.model " +
           motorModelWords(false, "or") + ", and `rollerdyn motor`)";
  return "";
}

// The Kloss keys a machine law (circuit, park) does not read: it has its own breakdown point.
std::string whyNotTheMachineLaw(const std::string& key, const Scene& sc) {
  if (isKlossSlip(key) &&
      !(key == "motor.overload_ratio" && nominalTorqueSource(sc) == NominalTorqueSource::OverloadRatio))
    return "it sets the Kloss law's critical slip; the equivalent circuit has its own breakdown point (from "
           "motor.catalogue or motor.circuit)";
  // M_kr: every scale that reads the motor's breakdown torque reads the law's own under a
  // catalogue law (motor/BreakdownTorque.h); only M_n = M_kr/λ still reads the key.
  if (key == "motor.breakdown_torque" && nominalTorqueSource(sc) != NominalTorqueSource::OverloadRatio)
    return "it is the Kloss law's breakdown torque M_kr; the equivalent circuit has its own breakdown point (from "
           "motor.catalogue or motor.circuit), which the run and the sizing use";
  return "";
}

// A key of another motor law's own (its row's own_keys, MotorModels.h): the chosen law never reads it.
std::string whyNotThisLawsOwnKeys(const std::string& key, const Scene& sc) {
  for (const MotorModelInfo& law : motorModelTable())
    for (const MotorLawKey& own : law.own_keys)
      if (law.model != sc.induction.model && own.spec().path == key)
        return std::string("only motor.model ") + law.word + " (" + law.meaning + ") reads it; this run's law is " +
               motorModelInfo(sc.induction.model).word;
  return "";
}

// The reducer's and the motor's keys the chosen laws do not read.
std::string whyNotTheseLaws(const std::string& key, const Scene& sc) {
  if (key == "reducer.efficiency_reverse" && sc.reducer.losses == ReducerLossModel::Papers)
    return "the papers' constant η (reducer.losses: papers) multiplies the motor torque by reducer.efficiency "
           "whichever way the power flows; set reducer.losses: power_flow for a reverse efficiency";
  if (key == "motor.connection")
    return "the laws use the equivalent star's per-phase values either way; a star-delta start is set by "
           "motor.start.method (the connection shows only in `rollerdyn motor`)";
  if (const std::string other = whyNotThisLawsOwnKeys(key, sc); !other.empty()) return other;
  return hasKlossCurve(sc.induction.model) ? whyNotTheKlossLaw(key, sc) : whyNotTheMachineLaw(key, sc);
}

// The drive train's keys that this scene's layout leaves without a motion to act on.
std::string whyNotThisDriveTrain(const std::string& key, const Scene& sc) {
  if (key == "reducer.backlash" && sc.coupling.type == CouplingType::Rigid)
    return "the coupling is rigid (coupling.type: rigid): motor and crank turn together, so the teeth never part";
  if (key == "reducer.backlash" && sc.reducer.backlash == 0.0)
    return "a backlash of 0 is the default: the teeth never part";
  if (key == "crank.offset_deg" && sc.carts.count == 1)
    return "there is one cart (carts.count: 1), so there is no second crank for the angle between consecutive "
           "cranks to place";
  if (key == "initial.twist" && sc.coupling.type == CouplingType::Rigid)
    return "the coupling is rigid (coupling.type: rigid): motor and crank turn together, with no twist between them";
  return "";
}

// The carts' geometry keys that this scene's loads leave without a force to act on.
std::string whyNotThisCartGeometry(const std::string& key, const Scene& sc, const std::string& model) {
  if (isCartMomentArm(key) && !guideSplitActs(sc))
    return "it is an arm in the cart's moment balance, which splits the guide normal between the two guide rollers; "
           "this run uses that split nowhere: there is no guide friction (loads.guide_friction.coefficient: 0) "
           "and no reactions are computed (simulation.reactions: false)";
  if (key == "carts.geometry.e" && !rollerForceActs(sc))
    return "it is the depth of the compacting rollers' horizontal force below the rod hinge, and that force is zero "
           "on every cart (loads.roller_force_front + loads.roller_force_rear = 0 and no rolling resistance)";
  // The reduced model's quasi-static guide normals leave out the carts' inertial forces, whose
  // height com_height is; with guide friction the run's friction-work check still reads them.
  if (key == "carts.geometry.com_height" && model == "reduced" &&
      sc.reduced.guide_normals == ReducedGuideNormals::QuasiStatic && !sc.hasGuideFriction())
    return "it is the height of the cart's inertial force, which the quasi-static guide normals leave out "
           "(reduced.guide_normals: quasi_static; kinetostatic includes it)";
  if (key == "carts.geometry.a" && !rollerSpacingActs(sc))
    return "it is the arm of the rollers' normal forces about the cart, (R_j2 − R_j1)·a, and each cart's two "
           "normals are equal (loads.roller_normal_front = loads.roller_normal_rear)";
  return "";
}

std::string why(const std::string& key, const Scene& sc, const std::string& model) {
  for (const std::string& reason :
       {whyNotThisModel(key, model), whyNotTheseResults(key, sc, model), whyNotTheseLaws(key, sc),
        afterTheRunsEnd(key, sc), whyNotThisDriveTrain(key, sc), whyNotThisCartGeometry(key, sc, model)})
    if (!reason.empty()) return reason;
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
