#include "scene/Scene.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "scene/MotorModels.h"
#include "scene/SceneChoices.h"

namespace rollerdyn {

double Scene::motorSideInertia() const {
  // Loveikin, Pochka, Romasevych (2018) eq. (1): J_n1 = (J_p + J_m)·δ·u²; Loveikin and Pochka (2007) adds the reducer's own inertia
  // (I_o = I_motor + I_m + I_red). A motor-shaft flywheel turns with the rotor.
  const double flywheel_motor =
      (flywheel.location == FlywheelLocation::MotorShaft) ? flywheel.inertia : 0.0;
  const double u = reducer.ratio;
  return (motor.rotor_inertia + coupling.inertia + reducer.inertia + flywheel_motor) *
         reducer.delta * u * u;
}

double Scene::crankSideInertia() const {
  const double flywheel_crank =
      (flywheel.location == FlywheelLocation::Crankshaft) ? flywheel.inertia : 0.0;
  return carts.count * crank.inertia_per_crank + crank.shaft_inertia + flywheel_crank;
}

double Scene::crankPhase(int j) const {
  // The uniform layout keeps its one expression, so a scene without lists gives the same bits.
  if (crank.angles.empty() && crank.angle_errors.empty()) return j * crank.offset;
  const double nominal = crank.angles.empty() ? j * crank.offset : crank.angles[j];
  return crank.angle_errors.empty() ? nominal : nominal + crank.angle_errors[j];
}

double Scene::cartMassWithRodShare(int j) const {
  return cartMass(j) + (rods.model == RodModel::Split ? 0.5 * rods.mass : 0.0);
}

double Scene::cartMassWithRodShare() const {
  if (!carts.masses.empty())
    throw std::logic_error("Scene::cartMassWithRodShare(): carts.mass is a list; ask for cart j's mass");
  return carts.mass + (rods.model == RodModel::Split ? 0.5 * rods.mass : 0.0);
}

double Scene::lightestCartMassWithRodShare() const {
  if (carts.masses.empty()) return cartMassWithRodShare();
  double m = cartMassWithRodShare(0);
  for (int j = 1; j < carts.count; ++j) m = std::min(m, cartMassWithRodShare(j));
  return m;
}

Loads Scene::cartLoads(int j) const {
  if (cart_loads.empty()) return loads;
  Loads l = loads;
  const CartLoads& c = cart_loads[j];
  l.roller_force_front = c.roller_force_front;
  l.roller_force_rear = c.roller_force_rear;
  l.roller_normal_front = c.roller_normal_front;
  l.roller_normal_rear = c.roller_normal_rear;
  l.rolling_resistance = c.rolling_resistance;
  return l;
}

double Scene::rollerForceSum() const {
  if (cart_loads.empty())
    return carts.count * (std::abs(loads.roller_force_front) + std::abs(loads.roller_force_rear));
  double sum = 0.0;
  for (const CartLoads& c : cart_loads) sum += std::abs(c.roller_force_front) + std::abs(c.roller_force_rear);
  return sum;
}

bool Scene::cartsIdentical() const {
  for (int j = 1; j < carts.count; ++j) {
    if (cartMass(j) != cartMass(0)) return false;
    if (cart_loads.empty()) continue;
    const CartLoads &a = cart_loads[j], &b = cart_loads[0];
    if (a.roller_force_front != b.roller_force_front || a.roller_force_rear != b.roller_force_rear ||
        a.roller_normal_front != b.roller_normal_front || a.roller_normal_rear != b.roller_normal_rear ||
        a.rolling_resistance != b.rolling_resistance)
      return false;
  }
  return true;
}

bool Scene::hasRollerLoads() const {
  if (!cart_loads.empty()) {
    for (const CartLoads& c : cart_loads)
      if (c.roller_force_front != 0.0 || c.roller_force_rear != 0.0 || c.roller_normal_front != 0.0 ||
          c.roller_normal_rear != 0.0)
        return true;
    return false;
  }
  return loads.roller_force_front != 0.0 || loads.roller_force_rear != 0.0 ||
         loads.roller_normal_front != 0.0 || loads.roller_normal_rear != 0.0;
}

std::vector<std::string> Scene::effects() const {
  std::vector<std::string> e;
  // The motor by its law (motor.model): kloss_motor, kloss_dynamic_motor, circuit_motor, park_motor.
  if (hasMotor()) e.push_back(std::string(toString(induction.model)) + "_motor");
  e.push_back(coupling.type == CouplingType::Rigid ? "rigid_coupling" : "elastic_coupling");
  if (hasCouplingDamping()) e.push_back("coupling_damping");
  if (hasBacklash()) e.push_back("backlash");
  if (hasCamDrive()) e.push_back("cam_drive");  // no rods: the cam pushes the cart (Loveikin and Pochka (cam drive paper))
  else e.push_back(std::string("rods_") + toString(rods.model));
  if (hasRollerLoads()) e.push_back("roller_loads");
  if (hasGuideFriction()) e.push_back("guide_friction");
  if (hasGravity()) e.push_back("gravity");
  if (hasFlywheel()) e.push_back("flywheel");
  if (crankshaft.torsionalChain()) e.push_back("crankshaft_torsion");
  return e;
}

std::string effectWords(const std::string& e) {
  for (const MotorModelInfo& law : motorModelTable())
    if (e == std::string(law.word) + "_motor")
      return std::string("induction motor, ") + law.effect + " (motor.model: " + law.word + ")";
  if (e == "rigid_coupling") return "rigid coupling (coupling.type: rigid)";
  if (e == "elastic_coupling") return "torsional spring of the coupling (coupling.stiffness)";
  if (e == "coupling_damping") return "damping of the coupling (coupling.damping)";
  if (e == "backlash") return "backlash of the reducer's teeth, no torque inside the gap (reducer.backlash)";
  if (e == "crankshaft_torsion")
    return "crankshaft as a torsional chain, one body per throw (crankshaft.torsional_stiffness)";
  if (e == "cam_drive") return "cam drive, no rods (drive.type: cam)";
  if (e == "rods_distributed") return "rods with distributed mass (rods.model: distributed)";
  if (e == "rods_split") return "rods' mass split, half at the crank pin, half at the cart (rods.model: split)";
  if (e == "rods_massless") return "massless rods (rods.model: massless)";
  if (e == "roller_loads") return "technological roller loads (loads.*)";
  if (e == "guide_friction") return "guide friction (loads.guide_friction)";
  if (e == "gravity") return "gravity (loads.gravity)";
  if (e == "flywheel") return "flywheel (flywheel.inertia)";
  return e;
}

// The words are the schema's (SceneChoices.h); each key is looked up once.
const char* toString(RodModel m) {
  static const KeySpec& key = choiceKey("rods.model");
  return choiceWord(key, m);
}
const char* toString(ReducerLossModel m) {
  static const KeySpec& key = choiceKey("reducer.losses");
  return choiceWord(key, m);
}
const char* toString(CouplingType t) {
  static const KeySpec& key = choiceKey("coupling.type");
  return choiceWord(key, t);
}
const char* toString(RollerForceDirection d) {
  static const KeySpec& key = choiceKey("loads.roller_force_direction");
  return choiceWord(key, d);
}
const char* toString(KinematicsForm k) {
  static const KeySpec& key = choiceKey("reduced.kinematics");
  return choiceWord(key, k);
}
const char* toString(FlywheelLocation l) {
  static const KeySpec& key = choiceKey("flywheel.location");
  return choiceWord(key, l);
}
const char* toString(ReducedIntegrator i) {
  static const KeySpec& key = choiceKey("reduced.integrator");
  return choiceWord(key, i);
}
const char* toString(DriveType d) {
  static const KeySpec& key = choiceKey("drive.type");
  return choiceWord(key, d);
}
const char* toString(MotorModel m) {
  static const KeySpec& key = choiceKey("motor.model");
  return choiceWord(key, m);
}
const char* toString(WindingConnection c) {
  static const KeySpec& key = choiceKey("motor.connection");
  return choiceWord(key, c);
}
const char* toString(Formulation f) {
  static const KeySpec& key = choiceKey("simulation.formulation");
  return choiceWord(key, f);
}
const char* toString(GuideNormalForce g) {
  static const KeySpec& key = choiceKey("loads.guide_friction.normal_force");
  return choiceWord(key, g);
}
const char* toString(ReducedGuideNormals g) {
  static const KeySpec& key = choiceKey("reduced.guide_normals");
  return choiceWord(key, g);
}
const char* toString(StartMethod m) {
  static const KeySpec& key = choiceKey("motor.start.method");
  return choiceWord(key, m);
}

double InductionMotor::phaseVoltage() const { return voltage / std::sqrt(3.0); }
double InductionMotor::supplyAngularFrequency() const { return 2.0 * M_PI * frequency; }

int Scene::selfCheckInterval() const {
  if (simulation.self_check_interval > 0) return simulation.self_check_interval;
  return std::max(50, 10 * carts.count);
}

}  // namespace rollerdyn
