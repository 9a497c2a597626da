#include "scene/Scene.h"

#include <cmath>

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

double Scene::cartMassWithRodShare() const {
  return carts.mass + (rods.model == RodModel::Split ? 0.5 * rods.mass : 0.0);
}

bool Scene::hasRollerLoads() const {
  return loads.roller_force_front != 0.0 || loads.roller_force_rear != 0.0 ||
         loads.roller_normal_front != 0.0 || loads.roller_normal_rear != 0.0;
}

std::vector<std::string> Scene::effects() const {
  std::vector<std::string> e;
  if (hasMotor()) e.push_back("kloss_motor");
  e.push_back(coupling.type == CouplingType::Rigid ? "rigid_coupling" : "elastic_coupling");
  if (hasCouplingDamping()) e.push_back("coupling_damping");
  if (hasCamDrive()) e.push_back("cam_drive");  // no rods: the cam pushes the cart (Loveikin and Pochka (cam drive paper))
  else e.push_back(std::string("rods_") + toString(rods.model));
  if (hasRollerLoads()) e.push_back("roller_loads");
  if (hasGuideFriction()) e.push_back("guide_friction");
  if (hasGravity()) e.push_back("gravity");
  if (hasFlywheel()) e.push_back("flywheel");
  return e;
}

const char* toString(RodModel m) {
  switch (m) {
    case RodModel::Distributed: return "distributed";
    case RodModel::Split: return "split";
    case RodModel::Massless: return "massless";
  }
  return "?";
}
const char* toString(CouplingType t) { return t == CouplingType::Rigid ? "rigid" : "elastic"; }
const char* toString(RollerForceDirection d) {
  return d == RollerForceDirection::AsPrinted ? "as_printed" : "opposes_velocity";
}
const char* toString(KinematicsForm k) { return k == KinematicsForm::Truncated ? "truncated" : "exact"; }
const char* toString(FlywheelLocation l) {
  return l == FlywheelLocation::MotorShaft ? "motor_shaft" : "crankshaft";
}
const char* toString(ReducedIntegrator i) { return i == ReducedIntegrator::Baranov ? "baranov" : "cvode"; }
const char* toString(DriveType d) { return d == DriveType::Cam ? "cam" : "crank"; }
const char* toString(MotorModel m) {
  switch (m) {
    case MotorModel::Kloss: return "kloss";
    case MotorModel::KlossDynamic: return "kloss_dynamic";
    case MotorModel::Circuit: return "circuit";
    case MotorModel::Park: return "park";
  }
  return "?";
}
const char* toString(WindingConnection c) { return c == WindingConnection::Delta ? "delta" : "star"; }

double InductionMotor::phaseVoltage() const { return voltage / std::sqrt(3.0); }
double InductionMotor::supplyAngularFrequency() const { return 2.0 * M_PI * frequency; }

const char* toString(Formulation f) { return f == Formulation::Minimal ? "minimal" : "constrained"; }

}  // namespace rollerdyn
