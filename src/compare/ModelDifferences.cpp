#include "compare/ModelDifferences.h"
#include "io/FieldFormat.h"

#include <cmath>
#include <cstdio>

namespace rollerdyn {
namespace {

// Distributed rods: the same kinetic energy in both, their inertial forces on the guides only in
// multibody.
ModelDifference rodInertiaDifference() {
  return {"rod_inertia",
          "rod inertia: distributed rod bodies (multibody) vs distributed reduced-inertia "
          "terms m_rod*(x_S'^2 + y_S'^2) + I_S*beta'^2 (reduced, Loveikin and Pochka (2007) eq. (9)); both are "
          "the exact kinetic energy of the rods, so the motion agrees, but the rods' own "
          "inertial forces reach the carts' guides only in multibody (the reduced quasi-static statics "
          "pass half the rod weight to the hinge)",
          false, false};
}

// The reactions, and with distributed rods their inertia, when the reduced model's cart statics
// leave out the inertial forces (quasi-static guide normals).
void reactionDifferences(const Scene& s, bool kinetostatic, std::vector<ModelDifference>& d) {
  // Reactions. The reduced model's reaction columns come from its cart statics: with the
  // papers' quasi-static normals without any inertial force; with kinetostatic normals the carts'
  // d'Alembert forces and the rods' inertial loads at their hinges are in, the same Newton
  // equations the multibody model's constraint forces satisfy (identicalPhysics).
  if (!kinetostatic) {
    std::string reactions =
        "guide reactions and rod forces: dynamic constraint forces of the slider and rod joints "
        "(multibody) vs quasi-static cart equilibrium without the carts' inertial forces (reduced, "
        "reduced.guide_normals = quasi_static, Loveikin, Pochka, Romasevych (2018) eq. (10)-(25)); they differ by the "
        "effect of each cart's d'Alembert force -m_B*a (comparison.csv also lists the reduced model's kinetostatic "
        "reactions, with that force added)";
    if (s.carts.geometry.com_height != 0.0)
      reactions += printfText("; the cart's centre of mass %.3g m above the hinge adds the moment of that "
                       "force to the guide reactions",
                       s.carts.geometry.com_height);
    d.push_back({"reactions", reactions, false, false});
    if (s.rods.model == RodModel::Distributed) d.push_back(rodInertiaDifference());
  }
}

// Guide friction: from which normal forces each model takes it, and with what lag.
void guideFrictionDifferences(const Scene& s, bool kinetostatic, std::vector<ModelDifference>& d) {
  if (s.hasGuideFriction()) {
    const bool lagged = s.loads.guide_normal_force == GuideNormalForce::Lagged;
    if (!kinetostatic)
      d.push_back({"guide_friction",
                   printfText("guide friction (f = %.3g): f*(|N_front| + |N_rear|) from the dynamic reactions (multibody, ",
                       s.loads.guide_friction) +
                       (lagged ? printfText("followed with a lag tau_N = %.3g s", s.loads.guide_friction_lag)
                               : std::string("solved with the motion")) +
                       ") vs from the quasi-static reactions (reduced, Loveikin, Pochka, Romasevych (2018) eq. "
                       "(14)-(25)); the friction torque, and with it crank speed and coupling torque, differ by about "
                       "f*(cart inertial force)*tan(beta)*dx_B/dphi (set reduced.guide_normals = kinetostatic for the "
                       "same law in both)",
                   true, false});
    else if (lagged)
      d.push_back({"guide_friction",
                   printfText("guide friction (f = %.3g): the same kinetostatic normal forces in both, followed with a lag "
                       "tau_N = %.3g s in multibody (loads.guide_friction.normal_force = lagged) and solved with the "
                       "motion in reduced; the lag shifts the friction by about f*tau_N*dN/dt",
                       s.loads.guide_friction, s.loads.guide_friction_lag),
                   true, false});
  }
}

// The reduced model's truncated kinematics series against the exact loop closure.
void kinematicsDifferences(const Scene& s, std::vector<ModelDifference>& d) {
  const double r = s.crank.radius, l = s.rods.length, lam = r / l;
  if (s.reduced.kinematics == KinematicsForm::Truncated && !s.hasCamDrive()) {
    // Largest position error of the series x_B = r cos θ + l(1 - λ² sin² θ / 2) against the
    // exact r cos θ + l·√(1 - λ² sin² θ), at sin² θ = 1.
    const double dx = l * std::abs(std::sqrt(1.0 - lam * lam) - (1.0 - 0.5 * lam * lam));
    d.push_back({"kinematics",
                 printfText("kinematics: truncated series for the cart position (reduced, Loveikin, Pochka, Romasevych (2018) eq. "
                     "(52)-(57)) vs exact loop closure (multibody); with r/l = %.3g the cart "
                     "positions differ by up to %.3g m and the transfer function dx_B/dphi by "
                     "O((r/l)^3)*r, which changes the reduced inertia and the load torque",
                     lam, dx),
                 true, false});
  }
}

// How each model is integrated.
void integratorDifferences(const Scene& s, std::vector<ModelDifference>& d) {
  if (s.reduced.integrator == ReducedIntegrator::Baranov)
    d.push_back({"integrator",
                 printfText("integration: the papers' fixed-step Baranov scheme in crank angle, step "
                     "%.3g deg (reduced, Loveikin and Pochka (2007) eq. (4), (10), (11)), a low-order scheme whose "
                     "error does not shrink with simulation.accuracy, vs an adaptive Simbody "
                     "integrator at relative accuracy %.3g (multibody)",
                     s.reduced.baranov_step * 180.0 / M_PI, s.simulation.accuracy),
                 true, false});
  else
    d.push_back({"integrator",
                 std::string(s.simulation.formulation == Formulation::Minimal
                                 ? "integration: CVODE Adams-Moulton on the multibody model's independent "
                                   "coordinates, the others from the closed-form loop solution (multibody, "
                                   "minimal formulation)"
                                 : "integration: Simbody " + s.simulation.integrator +
                                       " with constraint projection (multibody, constrained formulation)") +
                     " vs CVODE Adams-Moulton on the reduced equations (reduced), both at relative accuracy " +
                     printfText("%.3g", s.simulation.accuracy) +
                     "; differences of this order are integration error, not modelling",
                 false, true});
}

}  // namespace

std::vector<ModelDifference> modelDifferences(const Scene& s) {
  std::vector<ModelDifference> d;
  const bool kinetostatic = s.reduced.guide_normals == ReducedGuideNormals::Kinetostatic;
  reactionDifferences(s, kinetostatic, d);
  guideFrictionDifferences(s, kinetostatic, d);
  kinematicsDifferences(s, d);
  integratorDifferences(s, d);
  return d;
}

namespace {

// The drive (cams or cranks, the coupling) and the motor law, alike in both models.
void sameDriveAndMotor(const Scene& s, std::vector<std::string>& same) {
  if (s.hasCamDrive())
    same.push_back("drive: cams with the motion law of Loveikin and Pochka (cam drive paper) eq. (29)-(34), x_B = sigma*x(theta), in both "
                   "(a coordinate coupler in multibody, the same transfer functions in reduced); no rods");
  if (s.coupling.type == CouplingType::Elastic)
    same.push_back("drive: two masses joined by an elastic, damped coupling c*psi + k*psi' "
                   "(Loveikin, Pochka, Romasevych (2018) eq. (58)) in both");
  else
    same.push_back("drive: rigid coupling, one rotating body (multibody) and the one-mass model "
                   "J(phi) (Loveikin and Pochka (2007) eq. (1)) (reduced)");
  if (s.hasMotor()) {
    if (s.induction.model == MotorModel::Kloss)
      same.push_back("motor: the same Kloss law 2*M_kr*s*s_kr/(s^2 + s_kr^2)*u*eta (Loveikin, Pochka, Romasevych (2018) "
                     "eq. (37)) in both");
    else
      same.push_back(std::string("motor: the same motor law (motor.model: ") + toString(s.induction.model) +
                     ") and starting method in both, its electrical states integrated with the motion");
  }
}

// The rods and the roller loads, alike in both models.
void sameRodsAndLoads(const Scene& s, std::vector<std::string>& same) {
  if (s.rods.model == RodModel::Split)
    same.push_back("rods: half the rod mass on the crank pin, half on the cart (Loveikin, Pochka, Romasevych (2018) eq. "
                   "(2)-(3)) in both, including the pin half-masses' weight");
  else if (s.rods.model == RodModel::Massless)
    same.push_back("rods: massless in both");
  if (s.hasRollerLoads())
    same.push_back(std::string("roller loads: the same direction law (") +
                   toString(s.loads.roller_force_direction) +
                   ") in both; vertical roller forces do no work");
}

// The reactions and the guide friction taken from them, where both models agree.
void sameReactionsAndFriction(const Scene& s, std::vector<std::string>& same) {
  const bool kinetostatic = s.reduced.guide_normals == ReducedGuideNormals::Kinetostatic;
  if (kinetostatic)
    same.push_back("reactions: the cart's and the rod's Newton equations with their inertial forces in both "
                   "(constraint forces in multibody, kinetostatic cart statics in reduced)");
  if (!s.hasGuideFriction())
    same.push_back("guide friction: none in either model");
  else if (kinetostatic && s.loads.guide_normal_force == GuideNormalForce::Algebraic)
    same.push_back("guide friction: f*(|N_front| + |N_rear|) with the guide reactions of the same instant, the loop "
                   "solved with the motion by one law in both");
}

}  // namespace

std::vector<std::string> identicalPhysics(const Scene& s) {
  std::vector<std::string> same;
  sameDriveAndMotor(s, same);
  sameRodsAndLoads(s, same);
  sameReactionsAndFriction(s, same);
  if (s.reduced.kinematics == KinematicsForm::Exact && !s.hasCamDrive())
    same.push_back("kinematics: exact slider-crank (Loveikin, Pochka, Romasevych (2018) eq. (40)-(47)) in the reduced "
                   "model, exact loop closure in multibody");
  if (s.hasGravity())
    same.push_back("gravity: cart weight does no work on horizontal guides; rod weight enters "
                   "both models' motion");
  if (s.hasFlywheel())
    same.push_back(std::string("flywheel on the ") + toString(s.flywheel.location) +
                   " in both");
  return same;
}

bool motionEquivalent(const Scene& scene) {
  for (const ModelDifference& d : modelDifferences(scene))
    if (d.affects_motion && !d.numerical) return false;
  return true;
}

std::vector<std::string> differenceSentences(const Scene& scene) {
  std::vector<std::string> out;
  for (const ModelDifference& d : modelDifferences(scene)) out.push_back(d.sentence);
  return out;
}

}  // namespace rollerdyn
