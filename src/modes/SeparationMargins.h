// Separation margins of the torsional mode from the orders that excite it, as a torsional
// sign-off states them (API 617 / API 684 practice: every torsional natural frequency at least
// 10 % away from every excitation frequency in the operating speed range):
//   SM_k = |p − k·ω| / (k·ω)
// for each order k that drives the coupling mode (ExcitationOrders.h `forced`: its harmonic of the
// load and inertia torque is at least 1 % of the largest) at the operating crank speed ω (the
// mean speed of the steady motion). p is the natural frequency ω_n of the coupling mode's damped
// pair, the frequency where a forced response peaks:
//   - from the Floquet multipliers where they resolve the mode (√(σ² + ω_d²), the frequency the
//     resonance warning reads, so the two never disagree), else
//   - the frozen-angle band ω_n,min ... ω_n,max over the revolution (FrozenModes.h): the margin is
//     then the distance from k·ω to the band.
// With light damping ω_n is the undamped frequency √λ the Campbell diagram draws; a heavy damper
// moves it (balanced-4cart, k = 8000 N·m·s/rad: √λ ≈ 70.6 rad/s, ω_n ≈ 30.5 rad/s at ζ ≈ 0.88):
// both are given.
// Parametric resonance (2p = k·ω) is not a margin: the Floquet multipliers judge it at the
// operating speed (the stability verdict). Crossings below the operating speed are passed through
// in a start: listed, without a verdict (a transient, judged by the start's torques).
// The amplification factor AF = 1/(2ζ) of the mode is given beside each margin (API 684 waives
// the margin of a lateral critical with AF < 2.5; for torsion API 617 asks the margin or a
// forced-response analysis: this tool's run is that analysis, so a margin under 10 % FAILs and
// says where to look).
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/SizingCheck.h"
#include "modes/Campbell.h"
#include "modes/ChainModes.h"
#include "modes/DriveOrbit.h"
#include "modes/ExcitationOrders.h"
#include "modes/FrozenModes.h"

namespace rollerdyn::modes {

inline constexpr double kRequiredSeparationMargin = 0.10;  // API 617 / API 684 practice [-]

struct SeparationMargin {
  std::string mode = "coupling mode";  // the torsional mode kept away from: the coupling mode, or
                                  // "crankshaft mode N" of a torsional chain (ChainModes.h)
  int order = 0;                  // k
  double excitation = NAN;        // k·ω at the operating speed [rad/s]
  double exciting_torque = NAN;   // amplitude of the order's harmonic at the coupling [N·m]
  double p_low = NAN, p_high = NAN;  // ω_n of the mode's damped pair (or its band) [rad/s]
  double undamped_low = NAN, undamped_high = NAN;  // √λ band, the Campbell diagram's p [rad/s]
  std::string frequency_source;   // "Floquet multipliers" | "frozen-angle band"
  double margin = NAN;            // SM_k [-]
  double damping_ratio = NAN;     // ζ of the mode (Floquet, else the frozen band's smallest) [-]
  double amplification = NAN;     // AF = 1/(2ζ) [-]
  std::string verdict;            // "pass" | "FAIL" | "n/a" (an order of the layout too weak to drive the mode)
  std::string reason;
};

struct StartCrossing {
  int order = 0;
  double omega = NAN;             // crank speed where p = k·ω, below the operating speed [rad/s]
};

struct SeparationMargins {
  bool applicable = false;
  std::string not_applicable;     // why not, and what would make it apply
  double omega = NAN;             // operating crank speed [rad/s]
  double required = kRequiredSeparationMargin;
  std::vector<SeparationMargin> rows;
  std::vector<StartCrossing> start_crossings;  // forced crossings of the Campbell diagram below ω
};

// From the analysis' pieces: the steady motion (its Floquet verdict), the reduced model's frozen
// modes along it, the excitation orders at ω, and the Campbell diagram (may be not applicable).
// `frozen_natural`: ω_n of the damped pair, `frozen_undamped`: √λ, `frozen_damping`: ζ, each over
// the revolution.
SeparationMargins separationMargins(bool elastic, const SteadyMotion& steady, const Band& frozen_natural,
                                    const Band& frozen_undamped, const Band& frozen_damping,
                                    const ExcitationOrders& orders,
                                    const CampbellDiagram& campbell);

// The crankshaft's own torsional modes (a torsional chain, `chain`) added to the margins, from
// the orders that drive a throw (`throw_shares`, ExcitationOrders.h throwOrderShares: element k-1
// the share of order k; orders from 1 to its size are considered). Per mode: the driving order
// nearest to the mode's frozen-angle band (the governing margin) and every other driving order
// within 10 %; the orders too weak to drive it that lie within 10 % are counted in the governing
// row's reason (a wide band, where a throw's inertia nearly vanishes at its dead centres, holds
// dozens of them). Where the
// coupling is elastic the chain's first mode is the coupling mode, judged above from the rigid
// crankshaft's Floquet frequency, and is not repeated. The chain's band is undamped (the shaft's
// damping and the motor's slope are left out: ChainModes.h), so no damping ratio is given. With a
// rigid coupling the chain's modes are the drive's only ones: the margins then apply to them.
void addChainSeparation(SeparationMargins& s, const CrankshaftChainModes& chain, bool elastic,
                        const SteadyMotion& steady, const std::vector<double>& throw_shares);

// The margins as checks of a sign-off (SeparationChecks.cpp): one per order that drives the mode,
// value SM_k, limit 10 %; an order too weak to drive it is a "not applicable" check only within
// the 10 % (further away it is no excitation); one "not applicable" check with the reason where
// the margins do not apply or no order drives the mode. modes.json's separation_margins.checks.
std::vector<SizingCheck> separationChecks(const SeparationMargins& s);

// Renderings (SeparationMarginsOutputs.cpp): modes.json's "separation_margins" and the console's lines.
nlohmann::json separationJson(const SeparationMargins& s);
std::string separationText(const SeparationMargins& s);

}  // namespace rollerdyn::modes
