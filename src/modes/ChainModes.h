// The torsional modes of the crankshaft as a chain (crankshaft.torsional_stiffness,
// physics/TorsionalChain.h): a lumped, undamped chain of rotors, frozen at a crank angle,
//   motor side J_n1 —c— throw 1 —c_1— throw 2 — … —c_(n-1)— throw n
// (a rigid coupling puts J_n1 on throw 1), each throw k carrying its own inertia and its cart's
// reduced inertia J_j(θ_j) at its crank angle (physics/CartReducedInertia.h). Natural frequencies
// p = √λ of K·v = λ·M·v, free at both ends, so one rigid-body mode (p = 0) is dropped. The
// angle-dependent inertias make each p vary over a revolution: it is given as the band over
// `angles` frozen angles, the exact linear answer for a constant inertia only (the frozen-angle
// approximation, named in the outputs); the coupling damping and the motor's slope are left out
// (undamped frequencies). Holzer's method (the residual torque at the free end of the chain for a
// trial frequency; Holzer (1921), as in Den Hartog, Mechanical Vibrations, §5.7) is the
// independent check of the eigen-solution (tests, `rollerdyn validate`).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/Scene.h"

namespace rollerdyn::modes {

// Natural frequencies p [rad/s] of a free-free chain of rotors J[i] [kg·m²] joined by springs c[i]
// between rotor i and i+1 [N·m/rad], ascending, the rigid-body mode's 0 first.
std::vector<double> chainNaturalFrequencies(const std::vector<double>& J, const std::vector<double>& c);
// Holzer's residual torque at the far free end for a trial frequency p [rad/s], with the first
// rotor's amplitude 1 rad: zero at each natural frequency [N·m].
double holzerResidual(const std::vector<double>& J, const std::vector<double>& c, double p);
// The natural frequencies p > 0 below p_max by Holzer's residual: sign changes on a grid of
// `steps` frequencies refined by bisection to a relative 1e-12 [rad/s].
std::vector<double> holzerFrequencies(const std::vector<double>& J, const std::vector<double>& c, double p_max,
                                      int steps = 20000);

struct ChainSegment {
  int cart_a = 0, cart_b = 0;  // the carts whose throws the segment joins (1-based)
  double length = 0;           // Δz [m]
  double stiffness = 0;        // c_k = G·I_p/Δz [N·m/rad]
};

struct ChainModeBand {
  double p_min = 0, p_max = 0;  // natural frequency over a revolution [rad/s]
  double f_min = 0, f_max = 0;  // the same in Hz
  std::string shape;            // which spring the mode twists most (largest share of strain energy)
};

struct CrankshaftChainModes {
  bool applies = false;
  std::string not_applicable;        // why not (no crankshaft.torsional_stiffness, cam drive)
  std::vector<ChainSegment> segments;
  std::vector<ChainModeBand> modes;  // the elastic modes, ascending
  int angles = 0;                    // frozen angles over one revolution
  std::string approximations;        // in words, for every output that shows them
};

CrankshaftChainModes crankshaftChainModes(const Scene& scene, int angles = 72);
// modes.json's `crankshaft_chain` and the console's lines (ChainModesOutputs.cpp).
nlohmann::json chainJson(const CrankshaftChainModes& m);
std::string chainText(const CrankshaftChainModes& m);

// The lumped chain's inertias at crank angle φ2 of cart 1 [kg·m²] (motor side first with an
// elastic coupling) and its springs [N·m/rad]; exposed for the tests and the validation.
void chainAtAngle(const Scene& scene, double phi, std::vector<double>& J, std::vector<double>& c);

}  // namespace rollerdyn::modes
