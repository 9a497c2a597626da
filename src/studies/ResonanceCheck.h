// Torsional resonance check of the elastic coupling (Dyomin (two rotors) eq. (10), (16)-(21)): the two-mass
// drive (motor side J1, crank side J2, coupling stiffness c) has the natural frequency
//   p0 = sqrt(c·(J1 + J2)/(J1·J2))                                    (Dyomin (two rotors) eq. (10))
// and the harmonic amplitudes (16)-(21) blow up when p0 is close to ω, 2ω, 3ω or 5ω, the harmonics
// of the drive torque the paper keeps. The crank side of an installation is periodic in the crank
// angle, so its excitation has the same harmonics of the crank speed ω.
//
// Here J1 = Scene::motorSideInertia() (Loveikin, Pochka, Romasevych (2018) eq. (1)), J2 = the mean over one crank
// revolution of the crank-side reduced inertia J_n2(φ) (Loveikin, Pochka, Romasevych (2018) eq. (9), ReducedModel), and
// ω = the mean crank speed of the run. A warning is raised when |p0 - n·ω| <= 10 % of n·ω for
// n = 1, 2, 3, 5. Rigid couplings have no such mode and are never flagged.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/Scene.h"

namespace rollerdyn {

inline constexpr double kResonanceTolerance = 0.10;  // relative distance |p0 - nω|/(nω)
inline constexpr int kResonanceHarmonics[] = {1, 2, 3, 5};

struct ResonanceHit {
  int harmonic = 0;      // n
  double ratio = 0;      // p0 / (n·ω)
};

struct ResonanceReport {
  bool applicable = false;   // elastic coupling and a finite, non-zero ω
  double J1 = 0;             // motor side reduced to the crank axis [kg·m²]
  double J2_mean = 0;        // mean crank-side reduced inertia [kg·m²]
  double stiffness = 0;      // c [N·m/rad]
  double p0 = 0;             // [rad/s], Dyomin (two rotors) eq. (10)
  double omega = 0;          // mean crank speed [rad/s]
  std::vector<ResonanceHit> hits;
  std::vector<std::string> warnings;  // one sentence per hit
};

// p0 of Dyomin (two rotors) eq. (10) [rad/s].
double naturalFrequency(double stiffness, double J1, double J2);

// Mean of J_n2(φ) over one revolution [kg·m²] (720 samples, trapezoidal on a periodic function,
// exact to round-off for its low harmonics).
double meanCrankSideInertia(const Scene& scene);

// The check for a known p0 and ω (pure function, for tests and for `rollerdyn chain`).
std::vector<ResonanceHit> resonanceHits(double p0, double omega,
                                        double tolerance = kResonanceTolerance);

ResonanceReport checkResonance(const Scene& scene, double omega_mean,
                               double tolerance = kResonanceTolerance);

// Reads summary["omega_crank"]["mean"], appends the warnings to summary["warnings"] (created as
// an array if absent; kept if others added warnings) and puts the numbers under
// summary["resonance"]. Returns the warnings added (to print on the terminal).
std::vector<std::string> addResonanceWarnings(const Scene& scene, nlohmann::json& summary);

}  // namespace rollerdyn
