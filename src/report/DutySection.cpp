// The report's tables of the reducer's load spectrum after ISO 6336-6 and of the motor's starts after
// IEC 60034-1, rendered from summary.json's sizing.gear and sizing.motor_duty
// (analysis/DutySummary.cpp); the verdicts are those of sizing.checks, shown in the checks table.
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

// "T_i: n_i" of each class of a flank.
std::string classes(const json& flank) {
  std::string s;
  for (const json& c : jsonMember(flank, "classes"))
    s += (s.empty() ? "" : ", ") + jsonNumberText(jsonMember(c, "torque")) + ": " + jsonNumberText(jsonMember(c, "cycles"), "%.3g");
  return s.empty() ? "no cycles" : htmlEscape("classes (upper limit T_i in N·m: revolutions n_i) " + s);
}

void spectrumRows(std::ostringstream& h, const std::string& name, const json& s) {
  if (!applies(s)) {
    row(h, name, "n/a", "", text(jsonMember(s, "reason")));
    return;
  }
  const json &d = jsonMember(s, "drive"), &c = jsonMember(s, "coast");
  row(h, name + ": crank revolutions N_L", jsonNumberText(jsonMember(s, "revolutions"), "%.4g"), "-",
      "t = " + jsonNumberText(jsonMember(s, "t_begin")) + " … " + jsonNumberText(jsonMember(s, "t_end")) + " s");
  row(h, name + ": T_eq of the drive flank", jsonNumberText(jsonMember(d, "equivalent_torque")), "N·m", classes(d));
  row(h, name + ": T_eq of the other flank (T < 0)", jsonNumberText(jsonMember(c, "equivalent_torque")), "N·m", classes(c));
}

// The duty hour's equivalent torque and the application factor it gives, or why they do not apply.
void dutyHourRows(std::ostringstream& h, const json& g) {
  const json& d = jsonMember(g, "duty");
  if (!applies(d)) {
    row(h, "duty hour: T_eq", "n/a", "N·m", text(jsonMember(d, "reason")));
    return;
  }
  row(h, "duty hour: T_eq", jsonNumberText(jsonMember(d, "equivalent_torque")), "N·m",
      text(jsonMember(d, "deciding_flank")) + "; " + text(jsonMember(d, "basis")));
  row(h, "K_A = T_eq / T_n (assumed)",
      jsonNumberText(jsonMember(g, "application_factor"), "%.3f") + " (" +
          jsonNumberText(jsonMember(g, "assumed_application_factor"), "%.3g") + ")", "-");
}

void gearTable(std::ostringstream& h, const json& g) {
  h << "<h3>Reducer load spectrum and application factor after ISO 6336-6</h3>\n<p class=\"small\">"
    << text(jsonMember(g, "method")) << "; the " << text(jsonMember(g, "torque"))
    << ". Load cycles: crank revolutions in each torque class, a class at its upper limit; T_eq = (Σ n_i·T_i^p / N_L)^(1/p) "
       "per flank with N_L all revolutions; K_A = T_eq / T_n with T_n = u·η·M_n. The verdicts are in the checks "
       "table.</p>\n" << kRowsHead;
  row(h, "S-N exponent p / class width ΔT",
      jsonNumberText(jsonMember(g, "exponent"), "%.3g") + " / " + jsonNumberText(jsonMember(g, "class_width")), "- / N·m");
  row(h, "T_n = u·η·M_n", jsonNumberText(jsonMember(g, "nominal_torque")), "N·m", "M_n: " + text(jsonMember(g, "nominal_source")));
  spectrumRows(h, "start", jsonMember(g, "start"));
  spectrumRows(h, "steady window", jsonMember(g, "steady"));
  dutyHourRows(h, g);
  row(h, "T_eq / T_2N", jsonNumberText(jsonMember(g, "rated_ratio"), "%.3f"), "-",
      "T_2N = " + jsonNumberText(jsonMember(g, "rated_torque")) + " N·m");
  row(h, "peak |T| / T_2max", jsonNumberText(jsonMember(g, "max_ratio"), "%.3f"), "-",
      "peak " + jsonNumberText(jsonMember(g, "peak")) + " N·m at t = " + jsonNumberText(jsonMember(g, "t_peak")) +
          " s; T_2max = " + jsonNumberText(jsonMember(g, "max_torque")) + " N·m");
  h << "</table>\n";
}

void motorDutyTable(std::ostringstream& h, const json& m) {
  h << "<h3>Motor duty after IEC 60034-1</h3>\n<p class=\"small\">" << text(jsonMember(m, "designation"))
    << ". The verdicts are in the checks table.</p>\n" << kRowsHead;
  if (!jsonFlag(m, "start_known")) {
    row(h, "one start", "n/a", "", text(jsonMember(m, "start_unknown")));
  } else {
    row(h, "start time t_D", jsonNumberText(jsonMember(m, "start_time"), "%.3g"), "s");
    row(h, "rotor heat of one start Q_start", jsonNumberText(jsonMember(m, "start_heat")), "J");
    row(h, "rotor losses at standstill P_s = M_s·ω0", jsonNumberText(jsonMember(m, "locked_rotor_losses")), "W",
        "M_s = " + jsonNumberText(jsonMember(m, "locked_rotor_torque")) + " N·m");
    row(h, "equivalent locked-rotor time Q_start / P_s (t_E)",
        jsonNumberText(jsonMember(m, "equivalent_locked_time"), "%.3g") + " (" +
            jsonNumberText(jsonMember(m, "locked_rotor_time"), "%.3g") + ")", "s");
    row(h, "rotor heat of a start without load ½·J_M·ω0²", jsonNumberText(jsonMember(m, "no_load_start_heat")), "J",
        "J_M = " + jsonNumberText(jsonMember(m, "rotor_inertia"), "%.3g") + " kg·m², J_ext = " +
            jsonNumberText(jsonMember(m, "load_inertia"), "%.3g") + " kg·m² at the motor shaft");
    row(h, "permissible starts Z (Z_0)",
        jsonNumberText(jsonMember(m, "permissible_starts"), "%.3g") + " (" +
            jsonNumberText(jsonMember(m, "no_load_starts"), "%.3g") + ")", "1/h",
        "steady rotor losses / nominal " + jsonNumberText(jsonMember(m, "steady_loss_share"), "%.3g"));
    row(h, "starting time share N·t_D / 3600 s", jsonNumberText(jsonMember(m, "starting_time_share"), "%.3g"), "-");
  }
  h << "</table>\n";
}

}  // namespace

std::string dutySectionHtml(const json& sizing) {
  std::ostringstream h;
  if (jsonMember(sizing, "gear").is_object()) gearTable(h, jsonMember(sizing, "gear"));
  if (jsonMember(sizing, "motor_duty").is_object()) motorDutyTable(h, jsonMember(sizing, "motor_duty"));
  return h.str();
}

}  // namespace rollerdyn
