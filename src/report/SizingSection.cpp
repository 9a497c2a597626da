#include "report/SizingSection.h"

#include <cstdio>
#include <sstream>

#include "analysis/SignOffSheet.h"
#include "report/HtmlReport.h"
#include "report/SectionRows.h"
#include "io/FieldFormat.h"

namespace rollerdyn {

namespace {

using nlohmann::json;

using section_rows::kRowsHead;
using section_rows::row;
using section_rows::text;

std::string checkCell(const json& v) {
  if (!v.is_string()) return "<td>n/a</td>";
  // The verdict's own colour in every row: green pass, red FAIL, grey where the check does not apply,
  // amber where the motor data contradict the catalogue.
  const std::string verdict = v.get<std::string>();
  const char* cls = verdict == "pass" ? "ok" : verdict == "FAIL" ? "bad" : verdict == "not applicable" ? "na" : "warn";
  return std::string("<td class=\"") + cls + "\">" + htmlEscape(verdict) + "</td>";
}

// A check's limit with the sense of its comparison ("≤ 1", "< 0.9025"); "" without one.
std::string limitText(const json& c) {
  const json& limit = jsonMember(c, "limit");
  if (!limit.is_number()) return "";
  const json& sense = jsonMember(c, "passes_when");
  return htmlEscape(comparisonSymbol(sense.is_string() ? sense.get<std::string>() : "")) + " " +
         jsonNumberText(limit, "%.4g");
}

// The crank's motion and, for a stalled drive, why it stalled.
std::string motionStatusHtml(const json& s) {
  std::ostringstream h;
  const std::string motion = jsonMember(s, "motion").is_string() ? jsonMember(s, "motion").get<std::string>() : "unknown";
  const bool turning = motion == "turning";
  h << "<div class=\"status " << (turning ? "ok" : "bad") << "\">Motion of the crank: <b>" << htmlEscape(motion)
    << "</b>"
    << (motion == "rocking" ? " (it swings back and forth instead of turning)" : "")
    << (turning ? "" : "; δ, H, k_p, the energy per revolution and the flywheel size have no meaning and are n/a")
    << "</div>\n";
  if (jsonMember(s, "stall").is_object())
    h << "<div class=\"status bad\">Why the drive stalled: " << text(jsonMember(jsonMember(s, "stall"), "explanation")) << "</div>\n";
  return h.str();
}

// The motor's torques, powers and slip over the steady window and the whole run.
// "mean / RMS / peak" of a torque's statistics [N·m].
std::string meanRmsPeak(const json& t) {
  return jsonNumberText(jsonMember(t, "mean")) + " / " + jsonNumberText(jsonMember(t, "rms")) + " / " +
         jsonNumberText(jsonMember(t, "peak"));
}

// "mean / peak" of a power's statistics, in kW.
std::string meanPeakKilo(const json& p) {
  return jsonNumberText(jsonMember(p, "mean"), "%.4g", 1e-3) + " / " + jsonNumberText(jsonMember(p, "peak"), "%.4g", 1e-3);
}

// The motor over the steady window: torques, powers, slip and energy per revolution.
void steadyMotorRows(std::ostringstream& h, const json& m) {
  row(h, "torque M at the rotor: mean / RMS / peak |M|", meanRmsPeak(jsonMember(m, "torque_shaft")), "N·m");
  row(h, "torque at the crank M·u·η: mean / RMS / peak", meanRmsPeak(jsonMember(m, "torque_crank")), "N·m");
  row(h, "nominal torque M_n", jsonNumberText(jsonMember(m, "nominal_torque")), "N·m", text(jsonMember(m, "nominal_torque_source")));
  row(h, "breakdown torque M_kr", jsonNumberText(jsonMember(m, "breakdown_torque")), "N·m");
  row(h, "shaft power M·ω_r: mean / peak", meanPeakKilo(jsonMember(m, "power_shaft")), "kW");
  row(h, "power drawn from the line: mean / peak", meanPeakKilo(jsonMember(m, "power_line")), "kW",
      text(jsonMember(m, "line_power_basis")));
  row(h, "slip s: min … max", jsonNumberText(jsonMember(jsonMember(m, "slip"), "min"), "%.4f") + " … " + jsonNumberText(jsonMember(jsonMember(m, "slip"), "max"), "%.4f"), "-");
  row(h, "motor energy per crank revolution", jsonNumberText(jsonMember(m, "energy_per_revolution"), "%.4g", 1e-3), "kJ");
}

// The motor over the whole run, start-up included.
void wholeRunMotorRows(std::ostringstream& h, const json& r) {
  row(h, "whole run: torque M at the rotor mean / RMS / peak |M|", meanRmsPeak(jsonMember(r, "torque_shaft")), "N·m",
      "start-up included");
  row(h, "whole run: power from the line mean / peak", meanPeakKilo(jsonMember(r, "power_line")), "kW");
  row(h, "whole run: mean rotor losses s·M·ω0", jsonNumberText(jsonMember(r, "rotor_losses_mean"), "%.4g", 1e-3), "kW");
}

std::string motorTableHtml(const json& m) {
  std::ostringstream h;
  h << "<h3>Motor</h3>\n";
  if (!m.is_object()) {
    h << "<p>No motor torque in this run.</p>\n";
    return h.str();
  }
  h << kRowsHead;
  steadyMotorRows(h, m);
  wholeRunMotorRows(h, jsonMember(m, "whole_run"));
  h << "</table>\n";
  return h.str();
}

// The sizing checks with their verdicts; nothing without checks.
std::string checksTableHtml(const json& checks) {
  std::ostringstream h;
  if (!checks.is_array() || checks.empty()) return h.str();
  h << "<h3>Checks</h3>\n<p class=\"small\">Each check names the window that decided it: the steady window or "
       "the whole run (start-up included); the sign-off sheet (rollerdyn signoff) lists them with what each "
       "rests on.</p>\n<table>\n<tr><th>check</th><th>ratio</th><th>result</th>"
       "<th>decided by</th><th>why</th><th>limit</th><th>method</th></tr>\n";
  // Columns after "why" only: scripts/consistency_lib/parse.py reads the first three by position.
  for (const json& c : checks)
    h << "<tr><td>" << text(jsonMember(c, "what")) << "</td><td class=\"n\">" << jsonNumberText(jsonMember(c, "value"), "%.3f") << "</td>"
      << checkCell(jsonMember(c, "verdict")) << "<td>" << text(jsonMember(c, "window")) << "</td><td class=\"small\">"
      << text(jsonMember(c, "reason")) << "</td><td class=\"n\">" << limitText(c) << "</td><td class=\"small\">"
      << (jsonMember(c, "method").is_string() ? text(jsonMember(c, "method")) : std::string()) << "</td></tr>\n";
  h << "</table>\n";
  return h.str();
}

// The technological load's work per cart; nothing where it was not computed.
std::string loadSectionHtml(const json& load) {
  std::ostringstream h;
  if (!load.is_object() || !jsonMember(load, "available").is_boolean() || !jsonMember(load, "available").get<bool>())
    return h.str();
  h << "<h3>Technological load</h3>\n<p>" << text(jsonMember(load, "reading")) << "</p>\n";
  if (jsonMember(load, "warning").is_string())
    h << "<div class=\"status bad\">" << text(jsonMember(load, "warning")) << "</div>\n";
  h << "<table>\n<tr><th>cart</th><th>work, whole run [kJ]</th><th>work, steady window [kJ]</th>"
       "<th>mean power, steady window [W]</th></tr>\n";
  for (const json& c : jsonMember(load, "per_cart"))
    h << "<tr><td class=\"n\">" << jsonMember(c, "cart").dump() << "</td><td class=\"n\">"
      << jsonNumberText(jsonMember(c, "work_whole_run"), "%.4g", 1e-3) << "</td><td class=\"n\">" << jsonNumberText(jsonMember(c, "work_steady"), "%.4g", 1e-3)
      << "</td><td class=\"n\">" << jsonNumberText(jsonMember(c, "power_mean_steady")) << "</td></tr>\n";
  h << "</table>\n";
  return h.str();
}

// The flywheel's figures, the proposal and the runs that check it.
std::string flywheelTableHtml(const json& f) {
  std::ostringstream h;
  h << "<h3>Flywheel</h3>\n" << kRowsHead;
  row(h, "kinetic-energy swing ΔT over one steady revolution", jsonNumberText(jsonMember(f, "kinetic_energy_swing")), "J",
      "largest over the window's revolutions");
  row(h, "drive inertia at the crank J (mean 2T/ω²)", jsonNumberText(jsonMember(f, "inertia_effective")), "kg·m²");
  row(h, "target δ* (sizing.target_delta)", jsonNumberText(jsonMember(f, "target_delta")), "-");
  // The proposal is an estimate (never run by simulate): said so, with the runs that check it.
  const bool estimate = jsonFlag(f, "estimate");
  const std::string est = estimate ? " (ESTIMATE, not run)" : "";
  row(h, "flywheel on the crankshaft reaching δ*" + est, jsonNumberText(jsonMember(f, "flywheel_crankshaft")), "kg·m²", text(jsonMember(f, "method")));
  row(h, "or on the motor shaft" + est, jsonNumberText(jsonMember(f, "flywheel_motor_shaft")), "kg·m²", "counts u²·δ_red times");
  if (jsonMember(f, "basis").is_string()) row(h, "what the flywheel proposed rests on", "", "", text(jsonMember(f, "basis")));
  const json& check = jsonMember(f, "check_by_runs");
  if (jsonMember(check, "run_at_proposal").is_string())
    row(h, "check the estimate: δ of a run with flywheel.inertia = " + jsonNumberText(jsonMember(check, "flywheel_inertia")) +
               " kg·m² (" + jsonMember(check, "location").get<std::string>() + ")",
        "", "", "<code>" + text(jsonMember(check, "run_at_proposal")) + "</code>");
  if (jsonMember(check, "smallest_from_runs").is_string())
    row(h, "the smallest flywheel that meets δ*, from runs", "", "", "<code>" + text(jsonMember(check, "smallest_from_runs")) + "</code>");
  if (jsonMember(check, "note").is_string()) row(h, "check the estimate", "", "", text(jsonMember(check, "note")));
  h << "</table>\n";
  return h.str();
}

// The coupling's torques; nothing without them.
std::string couplingTableHtml(const json& c) {
  std::ostringstream h;
  if (!c.is_object()) return h.str();
  h << "<h3>Coupling</h3>\n" << kRowsHead;
  row(h, "torque at the crank axis: mean / peak |M| / swing",
      jsonNumberText(jsonMember(c, "mean")) + " / " + jsonNumberText(jsonMember(c, "peak")) + " / " + jsonNumberText(jsonMember(c, "swing")), "N·m");
  row(h, "whole run: peak |M| and when", jsonNumberText(jsonMember(c, "peak_whole_run")) + " at t = " + jsonNumberText(jsonMember(c, "t_peak_whole_run")) + " s",
      "N·m", "start-up included");
  row(h, "rated torque (sizing.coupling_rated_torque)", jsonNumberText(jsonMember(c, "rated_torque")), "N·m");
  h << "</table>\n";
  return h.str();
}

// One joint's row of the joints table: `what` names its kind.
std::string jointRowHtml(const json& x, const std::string& what) {
  std::ostringstream h;
  h << "<tr><td>"
    << (jsonMember(x, "bearing").is_number()  // a main bearing placed along the shaft
            ? "main bearing " + jsonMember(x, "bearing").dump() + " at z = " +
                  jsonNumberText(jsonMember(x, "position"), "%.4g") + " m"
            : what)
    << "</td><td class=\"n\">" << (jsonMember(x, "cart").is_number() ? jsonMember(x, "cart").dump() : "-")
    << "</td><td class=\"n\">" << jsonNumberText(jsonMember(x, "mean"), "%.3f", 1e-3) << "</td><td class=\"n\">"
    << jsonNumberText(jsonMember(x, "amplitude"), "%.3f", 1e-3) << "</td><td class=\"n\">" << jsonNumberText(jsonMember(x, "peak"), "%.3f", 1e-3)
    << "</td><td class=\"n\">" << jsonNumberText(jsonMember(x, "equivalent_load"), "%.3f", 1e-3) << "</td><td class=\"n\">"
    << jsonNumberText(jsonMember(x, "rating"), "%.1f", 1e-3) << "</td><td class=\"n\">" << jsonNumberText(jsonMember(x, "L10_hours"), "%.3g")
    << "</td><td class=\"small\">" << text(jsonMember(x, "speed_basis")) << "</td></tr>\n";
  return h.str();
}

// The joints' and bearings' loads and lives, and below the table how each kind's life follows.
std::string jointsTableHtml(const json& joints) {
  std::ostringstream h;
  h << "<h3>Joints and bearings</h3>\n<p class=\"small\">P: equivalent dynamic load (∫|F|³·n dt / ∫n dt)^(1/3), "
       "n the joint's rotation or swing speed (ISO 281 style); C: the dynamic load rating from "
       "sizing.bearing_rating.*; L10: the basic rating life in hours of steady running, how it follows "
       "(or why it does not apply) below the table.</p>\n"
    << "<table>\n<tr><th>joint</th><th>cart</th><th>mean [kN]</th><th>amplitude [kN]</th><th>peak [kN]</th>"
       "<th>P [kN]</th><th>C [kN]</th><th>L10 [h]</th><th>speed weighting</th></tr>\n";
  const char* kinds[] = {"guide_roller_front", "guide_roller_rear", "rod_end", "crank_pin", "main_bearing"};
  std::ostringstream notes;
  for (const char* kind : kinds) {
    const json& per = jsonMember(jsonMember(joints, kind), "per_cart");
    if (!per.is_array()) continue;
    const std::string what = text(jsonMember(jsonMember(joints, kind), "what"));
    for (const json& x : per) h << jointRowHtml(x, what);
    const json& w = jsonMember(jsonMember(joints, kind), "worst");
    notes << "<li>" << what << ": "
          << (jsonMember(w, "L10_hours").is_number() ? text(jsonMember(w, "life_basis"))
                                                     : "L10 n/a: " + text(jsonMember(w, "life_reason")))
          << "</li>\n";
  }
  h << "</table>\n";
  if (!notes.str().empty()) h << "<ul class=\"small\">\n" << notes.str() << "</ul>\n";
  return h.str();
}

}  // namespace

std::string sizingSectionHtml(const json& s) {
  std::ostringstream h;
  h << "<h2>Motion and drive sizing</h2>\n" << motionStatusHtml(s);
  const json& z = jsonMember(s, "sizing");
  if (!z.is_object()) {
    h << "<p>No sizing figures in summary.json.</p>\n";
    return h.str();
  }
  const json& w = jsonMember(z, "window");
  h << "<p class=\"small\">Over the steady window t = " << jsonNumberText(jsonMember(w, "t_begin")) << " … " << jsonNumberText(jsonMember(w, "t_end"))
    << " s (" << jsonNumberText(jsonMember(w, "revolutions"), "%.3g") << " crank revolutions), and where marked over the whole run "
    << "(start-up included). M: motor torque at the rotor; "
       "u: reducer ratio; η: reducer efficiency; ω_r: rotor speed; ω0: synchronous speed; "
       "s = 1 − ω_r/ω0: slip.</p>\n";
  h << motorTableHtml(jsonMember(z, "motor")) << checksTableHtml(jsonMember(z, "checks"))
    << loadSectionHtml(jsonMember(s, "load")) << flywheelTableHtml(jsonMember(z, "flywheel"))
    << couplingTableHtml(jsonMember(z, "coupling")) << signOffSectionHtml(z) << dutySectionHtml(z)
    << jointsTableHtml(jsonMember(z, "joints"));
  return h.str();
}

}  // namespace rollerdyn
