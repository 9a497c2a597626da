// The fatigue answers (Fatigue.h) and the coupling selection (CouplingSelection.h) as members of
// summary.json's `sizing`, and their lines of the console table, rendered from that JSON only.
#include <cmath>
#include <cstdio>
#include <sstream>

#include "analysis/SizingSummary.h"
#include "io/FieldFormat.h"

namespace rollerdyn {

using nlohmann::json;

namespace {

json windowJson(const WindowDamage& w) {
  if (!w.applies) return {{"applies", false}, {"reason", w.not_applicable}};
  json top = json::array();
  for (const DamagingCycle& d : w.top)
    top.push_back({{"range", jsonNumber(d.range)}, {"mean", jsonNumber(d.mean)}, {"count", jsonNumber(d.count)},
                   {"amplitude_equivalent", jsonNumber(d.amplitude_equivalent)},
                   {"damage", jsonNumber(d.damage)}});
  return {{"applies", true}, {"t_begin", jsonNumber(w.t_begin)}, {"t_end", jsonNumber(w.t_end)},
          {"damage", jsonNumber(w.damage)}, {"cycles", jsonNumber(w.cycles)}, {"column", w.where},
          {"dominant_cycles", top}};
}

// "no damage" where a life is infinite, "n/a" where the window is missing.
std::string lifeText(const json& window, const json& life, const char* unit) {
  if (!jsonFlag(window, "applies")) return "n/a";
  return life.is_number() ? jsonNumberText(life, "%.3g") + unit
                          : std::string("no damage (all cycles below a cut-off knee)");
}

void dominantText(std::ostringstream& o, const json& window, const std::string& unit) {
  const json& top = jsonMember(window, "dominant_cycles");
  if (!top.is_array() || top.empty()) return;
  o << "      dominant cycles (range, mean [" << unit << "], count, share of the damage):";
  const double D = jsonMember(window, "damage").is_number() ? jsonMember(window, "damage").get<double>() : 0.0;
  for (const json& c : top) {
    const double d = jsonMember(c, "damage").is_number() ? jsonMember(c, "damage").get<double>() : 0.0;
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.0f %%", D > 0 ? 100.0 * d / D : 0.0);
    o << " (" << jsonNumberText(jsonMember(c, "range")) << ", " << jsonNumberText(jsonMember(c, "mean")) << ", "
      << jsonNumberText(jsonMember(c, "count"), "%.1f") << ", " << buf << ")";
  }
  o << "\n";
}

}  // namespace

json fatigueJson(const FatigueSizing& f) {
  if (!f.requested) return nullptr;
  json signals = json::object();
  for (const SignalFatigue& g : f.signals) {
    signals[g.signal] = {
        {"what", g.what},
        {"unit", g.unit},
        {"curve", g.curve_given ? json{{"endurance_amplitude", g.curve.endurance_amplitude},
                                       {"knee_cycles", g.curve.knee_cycles},
                                       {"slope", g.curve.slope},
                                       {"ultimate", jsonNumber(g.curve.ultimate > 0 ? g.curve.ultimate : NAN)}}
                                : json(nullptr)},
        {"per_start", windowJson(g.start)},
        {"steady", windowJson(g.steady)},
        {"damage_per_start", jsonNumber(g.damage_per_start)},
        {"damage_per_hour", jsonNumber(g.damage_per_hour)},
        {"starts_to_failure", jsonNumber(g.starts_to_failure)},
        {"hours_to_failure", jsonNumber(g.hours_to_failure)}};
  }
  return {{"below_knee", f.below_knee},
          {"mean_correction", f.mean_correction},
          {"required_starts", jsonNumber(f.required_starts)},
          {"required_hours", jsonNumber(f.required_hours)},
          {"signals", signals}};
}

json couplingSelectionJson(const CouplingSelection& c) {
  if (!c.requested) return nullptr;
  return {{"method", "DIN 740-2 as the coupling makers publish it (KTR, Coupling selection according to DIN 740 part 2)"},
          {"rated_torque", jsonNumber(c.rated_torque)},
          {"max_torque", jsonNumber(c.max_torque)},
          {"vibratory_torque", jsonNumber(c.vibratory_torque)},
          {"damping_power", jsonNumber(c.damping_power)},
          {"S_t", c.S_t},
          {"S_z", c.S_z},
          {"S_A", c.S_A},
          {"S_f", jsonNumber(c.S_f)},
          {"start_peak", jsonNumber(c.start_peak)},
          {"steady_peak", jsonNumber(c.steady_peak)},
          {"vibratory_amplitude", jsonNumber(c.steady_amplitude)},
          {"excitation_order", c.excitation_order},
          {"excitation_frequency", jsonNumber(c.excitation_frequency)},
          {"damping_power_run", jsonNumber(c.damping_power_run)},
          {"damping_basis", c.damping_basis},
          {"rated_ratio", jsonNumber(c.rated_ratio)},
          {"max_ratio", jsonNumber(c.max_ratio)},
          {"vibratory_ratio", jsonNumber(c.vibratory_ratio)},
          {"damping_ratio", jsonNumber(c.damping_ratio)}};
}

namespace {

// One signal's damage per start and per hour, each with its life and dominant cycles.
std::string signalFatigueText(const json& g) {
  std::ostringstream o;
  const std::string unit = jsonText(jsonMember(g, "unit"));
  const json &ps = jsonMember(g, "per_start"), &st = jsonMember(g, "steady");
  o << "    " << jsonText(jsonMember(g, "what")) << ":\n";
  o << "      per start:  damage " << jsonNumberText(jsonMember(g, "damage_per_start"), "%.3g")
    << ", starts to failure " << lifeText(ps, jsonMember(g, "starts_to_failure"), "");
  if (!jsonMember(ps, "applies").get<bool>()) o << " (" << jsonText(jsonMember(ps, "reason")) << ")";
  o << "\n";
  dominantText(o, ps, unit);
  o << "      per hour:   damage " << jsonNumberText(jsonMember(g, "damage_per_hour"), "%.3g")
    << " 1/h, hours to failure " << lifeText(st, jsonMember(g, "hours_to_failure"), " h");
  if (!jsonMember(st, "applies").get<bool>()) o << " (" << jsonText(jsonMember(st, "reason")) << ")";
  o << "\n";
  dominantText(o, st, unit);
  return o.str();
}

// The fatigue lines: the method, then each signal's.
std::string fatigueText(const json& f) {
  if (!f.is_object()) return "";
  std::ostringstream o;
  o << "  fatigue (rainflow after ASTM E1049-85, Miner's rule; below the knee: "
    << jsonText(jsonMember(f, "below_knee")) << "; mean correction: " << jsonText(jsonMember(f, "mean_correction"))
    << ")\n";
  for (const auto& [name, g] : jsonMember(f, "signals").items()) o << signalFatigueText(g);
  return o.str();
}

// The coupling selection's lines: the run's torques and power, the factors and the ratings.
std::string couplingSelectionText(const json& c) {
  if (!c.is_object()) return "";
  std::ostringstream o;
  o << "  coupling selection (" << jsonText(jsonMember(c, "method")) << "), torques at the crank axis:\n"
    << "    peak torque: start " << jsonNumberText(jsonMember(c, "start_peak")) << ", steady "
    << jsonNumberText(jsonMember(c, "steady_peak")) << " N·m; vibratory amplitude T_W "
    << jsonNumberText(jsonMember(c, "vibratory_amplitude"))
    << " N·m at f = " << jsonNumberText(jsonMember(c, "excitation_frequency")) << " Hz (S_f "
    << jsonNumberText(jsonMember(c, "S_f"), "%.3g") << "); damping power P_W "
    << jsonNumberText(jsonMember(c, "damping_power_run")) << " W\n"
    << "    factors S_t " << jsonNumberText(jsonMember(c, "S_t"), "%.3g") << ", S_z "
    << jsonNumberText(jsonMember(c, "S_z"), "%.3g") << ", S_A " << jsonNumberText(jsonMember(c, "S_A"), "%.3g")
    << "; ratings T_KN " << jsonNumberText(jsonMember(c, "rated_torque")) << ", T_Kmax "
    << jsonNumberText(jsonMember(c, "max_torque")) << ", T_KW " << jsonNumberText(jsonMember(c, "vibratory_torque"))
    << " N·m, P_KW " << jsonNumberText(jsonMember(c, "damping_power")) << " W (n/a: not given)\n";
  return o.str();
}

}  // namespace

std::string signOffText(const json& sizing) {
  return fatigueText(jsonMember(sizing, "fatigue")) + couplingSelectionText(jsonMember(sizing, "coupling_selection"));
}

}  // namespace rollerdyn
