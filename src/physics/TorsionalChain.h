// The crankshaft as a torsional chain (crankshaft.torsional_stiffness): one rotor per crank throw,
// in the order of the throws along the shaft (z ascending, away from the coupling), neighbouring
// throws joined by the shaft segment between them, a torsional spring of stiffness
//   c_k = G·I_p / (z_(k+1) - z_k)        (uniform shaft, Saint-Venant torsion of a round shaft)
// The coupling drives the first throw (smallest z); the shaft between the coupling flange and that
// throw counts as rigid. Each throw carries J'_K (crank.inertia_per_crank) and an equal share of
// crank.shaft_inertia; a crankshaft flywheel sits at the drive end. The multibody model builds one
// body per throw from this (MultibodyModel.cpp, CrankshaftTorsion.h) and the chain's modes are
// computed from it (modes/ChainModes.h), so both read one layout.
#pragma once

#include <vector>

#include "scene/Scene.h"

namespace rollerdyn {

struct TorsionalChainLayout {
  std::vector<int> cart_of_throw;     // per throw k in z order: the cart j whose crank it carries
  std::vector<int> throw_of_cart;     // per cart j: its throw's index k in z order
  std::vector<double> inertia;        // per throw k: its own inertia about the shaft axis, J'_K + J_shaft/n
                                      // (+ a crankshaft flywheel on throw 0) [kg·m²]; no cart, rod or pin mass
  std::vector<double> stiffness;      // per segment k (throw k to k+1): c_k = G·I_p/Δz [N·m/rad]
  std::vector<double> damping;        // per segment k: d_k = β·G·I_p/Δz (Kelvin-Voigt) [N·m·s/rad]
  std::vector<double> length;         // per segment k: Δz [m]
};

// The chain of a scene with crankshaft.torsional_stiffness; precondition (checked, std::logic_error):
// scene.crankshaft.torsionalChain() with distinct throw positions (the parser refuses the others).
TorsionalChainLayout torsionalChainLayout(const Scene& scene);

}  // namespace rollerdyn
