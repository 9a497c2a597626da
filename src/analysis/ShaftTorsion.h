// The crankshaft's torsion in a run with a torsional chain (crankshaft.torsional_stiffness, the
// multibody model's shaft_torque_k columns): per shaft segment between neighbouring throws its
// stiffness, its peak |torque| over the whole run (a start's peak included) and over the steady
// window, and its peak twist |T|/c. Computed once here; summary.json ("crankshaft_torsion") and
// the console render it. Not applicable (with the reason) for a rigid crankshaft, or a run
// without the columns (the reduced model keeps the papers' rigid crankshaft).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/RunResult.h"
#include "analysis/SteadyState.h"
#include "scene/Scene.h"

namespace rollerdyn {

struct ShaftSegmentTorsion {
  int cart_a = 0, cart_b = 0;           // the carts whose throws it joins (1-based), from the coupling side
  double stiffness = 0;                 // c_k = G·I_p/Δz [N·m/rad]
  double torque_peak_run = 0;           // max |T| over the whole run [N·m]
  double torque_peak_steady = NAN;      // max |T| over the steady window [N·m]; NaN without one
  double twist_peak = 0;                // max |T|/c_k over the whole run [rad]
};

struct ShaftTorsionSummary {
  bool applies = false;
  std::string reason;                   // why not applicable
  std::vector<ShaftSegmentTorsion> segments;
  std::vector<std::string> warnings;    // an undamped chain: what a start leaves ringing in the window
};

ShaftTorsionSummary computeShaftTorsion(const Scene& scene, const RunResult& run, const SteadyState& ss, bool steady);
nlohmann::json shaftTorsionJson(const ShaftTorsionSummary& s);
// The console's lines for summary.json "crankshaft_torsion" (empty for a rigid crankshaft).
std::string shaftTorsionText(const nlohmann::json& torsion);

}  // namespace rollerdyn
