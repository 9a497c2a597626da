#include "analysis/ShaftTorsion.h"

#include <cmath>
#include <sstream>

#include "io/FieldFormat.h"
#include "physics/TorsionalChain.h"

namespace rollerdyn {

namespace {

// Why the run has no shaft torsion to report; "" when it has.
std::string noTorsionReason(const Scene& sc, const RunResult& run) {
  if (!sc.crankshaft.torsionalChain()) return "the crankshaft is rigid (no crankshaft.torsional_stiffness)";
  if (!run.timeseries.has("shaft_torque_1"))
    return run.model == "reduced" ? "the reduced model keeps the papers' rigid crankshaft (run the multibody model)"
                                  : "the run has no shaft torques";
  return "";
}

// Segment k of the chain: its throws' carts, its stiffness, its torque's peaks over the run's
// finite rows and over the steady window, and the twist of the run's peak.
ShaftSegmentTorsion segmentTorsion(const TorsionalChainLayout& chain, std::size_t k, const RunResult& run,
                                   const SteadyState& ss, bool steady) {
  ShaftSegmentTorsion s;
  s.cart_a = chain.cart_of_throw[k] + 1;
  s.cart_b = chain.cart_of_throw[k + 1] + 1;
  s.stiffness = chain.stiffness[k];
  const std::vector<double> T = run.timeseries.column("shaft_torque_" + std::to_string(k + 1));
  double steady_peak = 0;
  bool any_steady = false;
  for (size_t i = 0; i < T.size(); ++i) {
    if (!std::isfinite(T[i])) break;
    s.torque_peak_run = std::max(s.torque_peak_run, std::abs(T[i]));
    if (steady && i >= ss.row_begin && i < ss.row_end) {
      steady_peak = std::max(steady_peak, std::abs(T[i]));
      any_steady = true;
    }
  }
  if (any_steady) s.torque_peak_steady = steady_peak;
  s.twist_peak = s.torque_peak_run / s.stiffness;
  return s;
}

}  // namespace

ShaftTorsionSummary computeShaftTorsion(const Scene& sc, const RunResult& run, const SteadyState& ss, bool steady) {
  ShaftTorsionSummary out;
  out.reason = noTorsionReason(sc, run);
  if (!out.reason.empty()) return out;
  const TorsionalChainLayout chain = torsionalChainLayout(sc);
  for (size_t k = 0; k < chain.stiffness.size(); ++k) out.segments.push_back(segmentTorsion(chain, k, run, ss, steady));
  out.applies = true;
  if (!(sc.crankshaft.torsional_damping > 0))
    out.warnings.push_back(
        "the crankshaft's torsional chain has no damping (crankshaft.torsional_damping not given): the shaft modes a "
        "start excites ring undamped through the whole run, and the steady window's shaft torques (crankshaft_torsion) "
        "include that ringing; give crankshaft.torsional_damping = 2·ζ·G·I_p/p for a damping ratio ζ at a shaft mode p");
  return out;
}

nlohmann::json shaftTorsionJson(const ShaftTorsionSummary& s) {
  if (!s.applies) return {{"applicable", false}, {"reason", s.reason}};
  nlohmann::json seg = nlohmann::json::array();
  for (const ShaftSegmentTorsion& g : s.segments)
    seg.push_back({{"between_carts", {g.cart_a, g.cart_b}},
                   {"stiffness", g.stiffness},
                   {"torque_peak_run", g.torque_peak_run},
                   {"torque_peak_steady", std::isfinite(g.torque_peak_steady) ? nlohmann::json(g.torque_peak_steady)
                                                                               : nlohmann::json(nullptr)},
                   {"twist_peak", g.twist_peak}});
  return {{"applicable", true}, {"segments", seg}};
}

std::string shaftTorsionText(const nlohmann::json& torsion) {
  if (!jsonMember(torsion, "applicable").is_boolean()) return "";
  if (!jsonMember(torsion, "applicable").get<bool>()) {
    const std::string why = jsonMember(torsion, "reason").is_string() ? jsonMember(torsion, "reason").get<std::string>() : "";
    return why.rfind("the crankshaft is rigid", 0) == 0 ? "" : "shaft torsion n/a: " + why + "\n";
  }
  std::ostringstream o;
  o << "shaft torsion  per segment between throws (carts a-b): peak |T| whole run / steady window, peak twist\n";
  for (const nlohmann::json& g : jsonMember(torsion, "segments")) {
    const nlohmann::json& c = jsonMember(g, "between_carts");
    o << "             " << c[0].dump() << "-" << c[1].dump() << ": " << jsonNumberText(jsonMember(g, "torque_peak_run"))
      << " / " << jsonNumberText(jsonMember(g, "torque_peak_steady")) << " N·m, "
      << jsonNumberText(jsonMember(g, "twist_peak"), "%.3g") << " rad\n";
  }
  return o.str();
}

}  // namespace rollerdyn
