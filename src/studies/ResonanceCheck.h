// The resonance and stability verdict of a run, made once here for every output (summary.json,
// console, report, sweep, Python), and its first estimate.
//
// One crank speed. Every number of the verdict is taken at one ω: the run's steady mean crank
// speed (summary["omega_crank"]["mean"] of a run whose crank turns and that reached its steady
// state). A run without it (the drive stalled, rocks, is still starting, at rest; the steady state
// not reached; no motor) has no steady motion: resonance and stability are "not applicable", with
// the reason and what to do.
//
// First estimate (Dyomin (two rotors) eq. (10), (16)-(21)): the two-mass drive (motor side J1,
// crank side at its mean inertia J2 over a revolution, coupling stiffness c) has the natural
// frequency
//   p0 = sqrt(c·(J1 + J2)/(J1·J2))                                    (Dyomin (two rotors) eq. (10))
// and its forced response blows up when p0 is close to an order k·ω that drives it. The orders
// checked are exactly those the drive's exciting torque has (modes/ExcitationOrders.h): the
// harmonics of the load torque plus the inertia's own torque ½·J_n2'·ω² at ω, each order whose
// amplitude is at least 1 % of the largest harmonic (six equal carts at 60° on one side: 6, 12, 18,
// 24; carts of unequal masses or loads, or crank angles of their own, add the orders their
// difference excites). Within 10 % of k·ω: a hit.
//
// Verdict. The modal analysis (the drive linearized about its steady motion: frozen-angle modes,
// Floquet multipliers, modes/ModalAnalysis.h) decides wherever it can be made: its warnings
// (unstable steady motion, parametric resonance, the coupling mode's Floquet frequency within 5 %
// of an exciting order) are the run's resonance warnings. A first-estimate hit the analysis does
// not confirm is no warning: one line says that the modal analysis refutes it and why (the
// distance of the mode from the exciting orders, its damping, its decay), at the same ω. Only
// where the analysis cannot be made (no steady motion of the linearized drive) does a hit stand as
// a warning, labelled unchecked.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "modes/ModalAnalysis.h"
#include "scene/Scene.h"

namespace rollerdyn {

inline constexpr double kResonanceTolerance = 0.10;  // relative distance |p0 - kω|/(kω)

struct ResonanceHit {
  int harmonic = 0;      // order k
  double ratio = 0;      // p0 / (k·ω)
};

// The first estimate at one crank speed.
struct ResonanceReport {
  bool applicable = false;   // elastic coupling and a finite, non-zero ω
  double J1 = 0;             // motor side reduced to the crank axis [kg·m²]
  double J2_mean = 0;        // mean crank-side reduced inertia [kg·m²]
  double stiffness = 0;      // c [N·m/rad]
  double p0 = 0;             // [rad/s], Dyomin (two rotors) eq. (10)
  double omega = 0;          // the crank speed [rad/s]
  std::vector<int> orders;   // the orders checked: those that drive the coupling mode at ω
  std::vector<ResonanceHit> hits;
  std::vector<std::string> sentences;  // one per hit: what the estimate says (not yet a warning)
};

// p0 of Dyomin (two rotors) eq. (10) [rad/s].
double naturalFrequency(double stiffness, double J1, double J2);

// Mean of J_n2(φ) over one revolution [kg·m²] (720 samples, trapezoidal on a periodic function,
// exact to round-off for its low harmonics).
double meanCrankSideInertia(const Scene& scene);

// The harmonics of the drive torque Dyomin (two rotors) keeps for his two rotors on an elastic
// chain driven by a harmonic torque (`rollerdyn chain`, which has no crank and no cart layout).
inline constexpr int kResonanceHarmonics[] = {1, 2, 3, 5};

// The hits for a known p0 and ω at the given orders (pure function; default: Dyomin's 1, 2, 3, 5).
std::vector<ResonanceHit> resonanceHits(double p0, double omega, double tolerance = kResonanceTolerance,
                                        const std::vector<int>& orders = {1, 2, 3, 5});

// The first estimate at crank speed `omega` against the orders that drive the coupling mode there.
ResonanceReport checkResonance(const Scene& scene, double omega, double tolerance = kResonanceTolerance);

// What the run gives the verdict: how the crank moved and its steady mean speed.
struct RunState {
  std::string motion;          // RunMotion.h: turning, stalled, rocking, starting, at_rest, coasting, unknown
  bool steady = false;         // the steady state was reached
  double omega = NAN;          // mean crank speed of the metrics window [rad/s]
};
RunState runStateOf(const nlohmann::json& summary);

struct RunResonance {
  bool elastic = false;
  // Whether the run has a steady motion to judge, and if not why and what to do.
  bool applicable = false;
  std::string reason;
  double omega = NAN;                // the run's steady mean crank speed: the one ω of every number
  ResonanceReport first_estimate;
  modes::ExcitationOrders orders;    // at omega
  // The modal analysis.
  bool modal_made = false;           // a steady motion of the linearized drive was found
  std::string modal_note;            // why not, when not
  std::shared_ptr<const modes::ModesReport> modal;  // the analysis the verdict rests on (null: none made)
  double analysis_omega = NAN;       // the speed of the steady motion the drive is linearized about
  // "resonance", "unstable", "no resonance", "unchecked first estimate", "no hit" (no modal analysis,
  // no first-estimate hit) or "not applicable".
  std::string verdict;
  std::string first_estimate_status; // "no order within 10 %", "refuted by the modal analysis",
                                     // "confirmed by the modal analysis", "unchecked", "not applicable"
  std::string conclusion;            // why there is no resonance (modal analysis made, no warning)
  // Stability of the steady motion (Floquet): "stable", "parametrically unstable", "unstable speed
  // mode", "not applicable"; with the reason.
  std::string stability;
  std::string stability_reason;
  double max_multiplier_modulus = NAN;
  std::vector<std::string> warnings; // the run's resonance warnings
  std::string verdict_line;          // "resonance verdict: ..." beside a first-estimate hit, or ""
};

// The verdict of a run on `scene` in state `state`. `analysis`: a full modal analysis made for
// this scene (simulate --modes, report), or nullptr (a light one is made where it applies: reduced
// model, no Campbell diagram or charts; tens of milliseconds).
RunResonance judgeRunResonance(const Scene& scene, const RunState& state, const modes::ModesReport* analysis);

// Puts the verdict into the summary: "resonance" (the first estimate), "resonance_modal" (the
// analysis' numbers), "resonance_verdict", "stability", and the warnings appended to "warnings".
void putRunResonance(const RunResonance& v, nlohmann::json& summary);

}  // namespace rollerdyn
