// The report's tables of the fatigue damage and the coupling selection after DIN 740-2, rendered
// from summary.json's sizing.fatigue and sizing.coupling_selection (analysis/SignOffSummary.cpp);
// the verdicts are those of sizing.checks, shown in the checks table.
#include <sstream>

#include "io/FieldFormat.h"
#include "report/HtmlReport.h"
#include "report/SectionRows.h"
#include "report/SizingSection.h"

namespace rollerdyn {

namespace {

using nlohmann::json;

using section_rows::applies;
using section_rows::kRowsHead;
using section_rows::row;
using section_rows::text;

std::string dominant(const json& w, const std::string& unit) {
  const json& top = jsonMember(w, "dominant_cycles");
  if (!top.is_array() || top.empty()) return "";
  std::string s = "dominant cycles (range, mean in " + unit + ", count): ";
  for (const json& c : top)
    s += "(" + jsonNumberText(jsonMember(c, "range")) + ", " + jsonNumberText(jsonMember(c, "mean")) + ", " +
         jsonNumberText(jsonMember(c, "count"), "%.1f") + ") ";
  return htmlEscape(s);
}

// One signal's damage per start and per hour of steady running, and the lives they give (n/a with
// the reason where the start or the steady window is missing).
void fatigueSignalRows(std::ostringstream& h, const std::string& name, const json& g) {
  const std::string what = jsonMember(g, "what").is_string() ? jsonMember(g, "what").get<std::string>() : name;
  const std::string unit = jsonMember(g, "unit").is_string() ? jsonMember(g, "unit").get<std::string>() : "";
  const json &ps = jsonMember(g, "per_start"), &st = jsonMember(g, "steady");
  if (applies(ps)) {
    row(h, what + ": damage per start", jsonNumberText(jsonMember(g, "damage_per_start"), "%.3g"), "-", dominant(ps, unit));
    row(h, what + ": starts to failure", jsonNumberText(jsonMember(g, "starts_to_failure"), "%.3g"), "-",
        jsonMember(g, "starts_to_failure").is_number() ? "" : "no cycle damages");
  } else {
    row(h, what + ": damage per start", "n/a", "-", text(jsonMember(ps, "reason")));
  }
  if (applies(st)) {
    row(h, what + ": damage per hour of steady running", jsonNumberText(jsonMember(g, "damage_per_hour"), "%.3g"), "1/h",
        dominant(st, unit));
    row(h, what + ": hours to failure", jsonNumberText(jsonMember(g, "hours_to_failure"), "%.3g"), "h",
        jsonMember(g, "hours_to_failure").is_number() ? "" : "no cycle damages");
  } else {
    row(h, what + ": damage per hour", "n/a", "1/h", text(jsonMember(st, "reason")));
  }
}

void fatigueTable(std::ostringstream& h, const json& f) {
  h << "<h3>Fatigue per start and per hour</h3>\n<p class=\"small\">Rainflow counting after ASTM E1049-85 and "
       "Miner's rule; below the knee: "
    << text(jsonMember(f, "below_knee")) << "; mean correction: " << text(jsonMember(f, "mean_correction"))
    << ".</p>\n" << kRowsHead;
  for (const auto& [name, g] : jsonMember(f, "signals").items()) fatigueSignalRows(h, name, g);
  h << "</table>\n";
}

void couplingTable(std::ostringstream& h, const json& c) {
  h << "<h3>Coupling selection after DIN 740-2</h3>\n<p class=\"small\">" << text(jsonMember(c, "method"))
    << "; torques at the crank axis; the verdicts are in the checks table.</p>\n"
    << kRowsHead;
  row(h, "peak torque of the start / of the steady window",
      jsonNumberText(jsonMember(c, "start_peak")) + " / " + jsonNumberText(jsonMember(c, "steady_peak")), "N·m");
  row(h, "vibratory torque amplitude T_W at f", jsonNumberText(jsonMember(c, "vibratory_amplitude")) + " at " +
      jsonNumberText(jsonMember(c, "excitation_frequency")) + " Hz", "N·m",
      "crank order " + jsonNumberText(jsonMember(c, "excitation_order"), "%.0f") + ", S_f = " +
          jsonNumberText(jsonMember(c, "S_f"), "%.3g"));
  row(h, "damping power P_W", jsonNumberText(jsonMember(c, "damping_power_run")), "W", text(jsonMember(c, "damping_basis")));
  row(h, "factors S_t / S_z / S_A",
      jsonNumberText(jsonMember(c, "S_t"), "%.3g") + " / " + jsonNumberText(jsonMember(c, "S_z"), "%.3g") + " / " +
          jsonNumberText(jsonMember(c, "S_A"), "%.3g"), "-");
  row(h, "T_N·S_t / T_KN", jsonNumberText(jsonMember(c, "rated_ratio"), "%.3f"), "-",
      "T_KN = " + jsonNumberText(jsonMember(c, "rated_torque")) + " N·m");
  row(h, "T_S·S_A·S_z·S_t / T_Kmax", jsonNumberText(jsonMember(c, "max_ratio"), "%.3f"), "-",
      "T_Kmax = " + jsonNumberText(jsonMember(c, "max_torque")) + " N·m");
  row(h, "T_W·S_t·S_f / T_KW", jsonNumberText(jsonMember(c, "vibratory_ratio"), "%.3f"), "-",
      "T_KW = " + jsonNumberText(jsonMember(c, "vibratory_torque")) + " N·m");
  row(h, "P_W·S_t / P_KW", jsonNumberText(jsonMember(c, "damping_ratio"), "%.3f"), "-",
      "P_KW = " + jsonNumberText(jsonMember(c, "damping_power")) + " W");
  h << "</table>\n";
}

}  // namespace

std::string signOffSectionHtml(const json& sizing) {
  std::ostringstream h;
  if (jsonMember(sizing, "fatigue").is_object()) fatigueTable(h, jsonMember(sizing, "fatigue"));
  if (jsonMember(sizing, "coupling_selection").is_object()) couplingTable(h, jsonMember(sizing, "coupling_selection"));
  return h.str();
}

}  // namespace rollerdyn
