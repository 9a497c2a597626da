// Which modelling differences between the multibody model (src/multibody) and the reduced-mass
// model (src/reduced) apply to a given Scene, each as one sentence for comparison.json and the
// validation report. Both models read the same immutable Scene, so every difference in their
// results is either one of these modelling differences or integration error.
//
// The list is derived from the Scene only (no run needed); it is what the code of the two
// models does, checked against their sources:
//   - reactions: the multibody model reads constraint forces (GuideReactions.h, with every
//     inertial force), the reduced model solves the cart's quasi-static equilibrium
//     (CartStatics.h, Loveikin, Pochka, Romasevych (2018) eq. (10)-(25), no inertial force);
//   - guide friction: multibody from the dynamic reactions, followed with a lag τ_N
//     (GuideFriction.h), reduced from the quasi-static reactions (Loveikin, Pochka, Romasevych (2018) eq. (14));
//   - kinematics: multibody closes the loop exactly, the reduced model may use the truncated
//     series of Loveikin, Pochka, Romasevych (2018) eq. (52)-(57);
//   - integrator: adaptive Simbody integrator vs CVODE, or the papers' fixed-step Baranov scheme.
// Rod inertia is NOT a difference in the motion: the reduced model's distributed-rod terms
// m_rod·(x_S'² + y_S'²) + I_S·β'² (Loveikin and Pochka (2007) eq. (9)) are the exact kinetic energy of a rigid rod,
// and split rods are lumped identically in both models (Loveikin, Pochka, Romasevych (2018) eq. (2)-(3)); the rod's inertial
// forces only change the reactions.
#pragma once

#include <string>
#include <vector>

#include "scene/Scene.h"

namespace rollerdyn {

struct ModelDifference {
  std::string topic;      // short key, e.g. "guide_friction", "kinematics", "reactions"
  std::string sentence;   // what each model does, with the paper equations
  bool affects_motion;    // true: changes crank speed / coupling torque (not only reactions)
  bool numerical;         // true: an integration difference, not a modelling one
};

// Differences that apply to `scene`, modelling ones first, then numerical ones.
std::vector<ModelDifference> modelDifferences(const Scene& scene);

// Aspects of `scene` both models describe by the same equations (one sentence each), so a
// reader sees what was checked to be identical, not only what differs.
std::vector<std::string> identicalPhysics(const Scene& scene);

// True when no modelling difference changes the motion: the crank speed and coupling torque of
// the two models must then agree to integration accuracy.
bool motionEquivalent(const Scene& scene);

// Just the sentences of modelDifferences(scene).
std::vector<std::string> differenceSentences(const Scene& scene);

}  // namespace rollerdyn
