// Guide lift-off: a cart's guide reaction N (reactions.csv N_front_j, N_rear_j; N > 0 when the
// guide presses the roller downward, Loveikin, Pochka, Romasevych (2018) fig. 3 and eq. (10)) acts
// on one side of its roller: downward where the mix's reactions R_j1 + R_j2 lift the cart more
// than its weight (balanced 4-cart drive), upward where the cart rests on its guides (carts
// without roller normal forces). Where N changes sign during the steady window, the guide would
// have to act from the other side for part of the time: the roller lifts off that guide unless a
// counter-roller holds it, which the scenes do not model (the run's reactions then hold only with
// one). Computed once here from the run's reactions over the steady window; summary.json, the
// console and the report render it.
//
// Verdict per run: "holds" (no guide reaction changes sign in the window), "lifts off" (one
// warning on stderr and in summary.json naming each cart and guide, with the share of the
// window's time the reaction spends on its minority side and its worst value there), or "not applicable" with the
// reason: no reactions computed (simulation.reactions: false), or no steady state reached.
// A sign change smaller than 10⁻⁶ of the reaction's largest magnitude counts as none (round-off).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/RunResult.h"
#include "analysis/SteadyState.h"
#include "scene/Scene.h"

namespace rollerdyn {

struct GuideLiftOffEntry {
  int cart = 0;                // 1-based
  std::string guide;           // "front" (N_j1) | "rear" (N_j2)
  bool presses_down = true;    // the prevailing side: N > 0 (downward) for most of the window
  double time_fraction = 0;    // share of the window's time with N on the other side [-]
  double worst_reaction = 0;   // the extreme N on the other side [N] (negative when presses_down)
  double prevailing_extreme = 0;  // the extreme N on the prevailing side [N]
};

struct GuideLiftOff {
  std::string verdict;         // "holds" | "lifts off" | "not applicable"
  std::string reason;          // why not applicable, and what to do; empty otherwise
  double t_begin = 0, t_end = 0;  // the window judged [s]
  int guides_checked = 0;
  std::vector<GuideLiftOffEntry> lifting;  // the guides that lift off, cart by cart
  std::vector<std::string> warnings;       // one sentence naming every entry of `lifting`
};

// `steady`: the steady window was reached with the crank turning (the window of `ss` is judged).
GuideLiftOff computeGuideLiftOff(const RunResult& run, const SteadyState& ss, bool steady);

nlohmann::json guideLiftOffJson(const GuideLiftOff& g);

}  // namespace rollerdyn
