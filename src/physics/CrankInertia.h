// Whether the crank side of an elastic drive has an inertia at every crank angle. With massless
// rods and no crank, shaft or crankshaft-flywheel inertia, the crank side's reduced inertia
// J_n2(φ) = Σ m_B·x_B'(φ)² vanishes at each dead centre (x_B' = 0 there): the crank's equation of
// motion behind an elastic coupling is singular, and an integrator crawls towards it (the
// consistency harness's seed 3146: a one-cart drive that the flywheel-by-runs tried with no
// flywheel ran for minutes). Both models refuse such a drive with the same sentence.
#pragma once

#include <string>

#include "scene/Scene.h"

namespace rollerdyn {

// "" when the crank side has an inertia of its own (or the coupling is rigid, so the motor side
// lends it its own); else why not and what to give, for the model named `model`.
inline std::string crankWithoutInertia(const Scene& sc, const std::string& model) {
  const bool rigid = sc.coupling.type == CouplingType::Rigid;
  const double J = sc.crankSideInertia() + (rigid ? sc.motorSideInertia() : 0.0);
  const bool pin_mass = sc.rods.model == RodModel::Split && sc.rods.mass > 0;
  if (J > 0 || pin_mass || sc.rods.model == RodModel::Distributed) return "";
  return model + ": the crankshaft has no inertia of its own (crank.inertia_per_crank, crank.shaft_inertia and a "
                 "crankshaft flywheel are all 0) and its rods are " +
         std::string(toString(sc.rods.model)) +
         "; with an elastic coupling its motion would be undetermined at the dead centres. Give it an inertia.";
}

}  // namespace rollerdyn
