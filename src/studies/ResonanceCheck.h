// Torsional resonance check of the elastic coupling (Dyomin (two rotors) eq. (10), (16)-(21)): the two-mass
// drive (motor side J1, crank side J2, coupling stiffness c) has the natural frequency
//   p0 = sqrt(c·(J1 + J2)/(J1·J2))                                    (Dyomin (two rotors) eq. (10))
// and the harmonic amplitudes (16)-(21) blow up when p0 is close to ω, 2ω, 3ω or 5ω, the harmonics
// of the drive torque the paper keeps. The crank side of an installation is periodic in the crank
// angle, so its excitation has the same harmonics of the crank speed ω.
//
// Which harmonics excite it follows from the cart layout (excitationOrders): each cart adds the
// same periodic torque T(φ + θ_j) (θ_j its crank's angle), so harmonic k of the total is that of
// one cart times the layout factor Σ_j exp(i·k·θ_j). For n equal carts on one side at equal
// offsets spread over the turn (n·Δφ a multiple of 360°) the factor vanishes unless k is a
// multiple of n: six carts at 60° excite 6ω, 12ω, ..., and neither 3ω nor 5ω. Carts on both
// sides are mirrored slider-cranks (a cart on the far side at crank angle θ moves like one on the
// near side at π - θ, run backwards), whose harmonics do not cancel that way: such layouts, carts
// of different masses or loads (carts.mass, loads.* given per cart: each cart its own torque
// function), and any layout whose factor does not vanish (crank angles of their own,
// crank.angles_deg, crank.angle_error_deg), are checked at every order up to the highest kept.
//
// Here J1 = Scene::motorSideInertia() (Loveikin, Pochka, Romasevych (2018) eq. (1)), J2 = the mean over one crank
// revolution of the crank-side reduced inertia J_n2(φ) (Loveikin, Pochka, Romasevych (2018) eq. (9), ReducedModel), and
// ω = the mean crank speed of the run. A warning is raised when |p0 - k·ω| <= 10 % of k·ω for the
// orders k the layout excites. Rigid couplings have no such mode and are never flagged.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/Scene.h"

namespace rollerdyn {

inline constexpr double kResonanceTolerance = 0.10;  // relative distance |p0 - nω|/(nω)
// The harmonics of the drive torque Dyomin (two rotors) keeps, for a harmonic drive torque
// (`rollerdyn chain`).
inline constexpr int kResonanceHarmonics[] = {1, 2, 3, 5};

// Orders k ≤ max(12, 2n) of the crank speed that the carts' layout excites (see above), in
// ascending order; the cam drive and the crank drive alike (each cart's motion is periodic in
// its cam or crank angle).
std::vector<int> excitationOrders(const Scene& scene);

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
  std::vector<int> orders;   // the harmonics checked (excitationOrders)
  std::vector<ResonanceHit> hits;
  std::vector<std::string> warnings;  // one sentence per hit
};

// p0 of Dyomin (two rotors) eq. (10) [rad/s].
double naturalFrequency(double stiffness, double J1, double J2);

// Mean of J_n2(φ) over one revolution [kg·m²] (720 samples, trapezoidal on a periodic function,
// exact to round-off for its low harmonics).
double meanCrankSideInertia(const Scene& scene);

// The check for a known p0 and ω (pure function, for tests and for `rollerdyn chain`) at the
// given orders (default: Dyomin's 1, 2, 3, 5).
std::vector<ResonanceHit> resonanceHits(double p0, double omega,
                                        double tolerance = kResonanceTolerance,
                                        const std::vector<int>& orders = {1, 2, 3, 5});

ResonanceReport checkResonance(const Scene& scene, double omega_mean,
                               double tolerance = kResonanceTolerance);

// Reads summary["omega_crank"]["mean"], appends the warnings to summary["warnings"] (created as
// an array if absent; kept if others added warnings) and puts the numbers under
// summary["resonance"]. Returns the warnings added (to print on the terminal).
std::vector<std::string> addResonanceWarnings(const Scene& scene, nlohmann::json& summary);

}  // namespace rollerdyn
