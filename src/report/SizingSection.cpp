#include "report/SizingSection.h"

#include <cstdio>
#include <sstream>

#include "report/HtmlReport.h"

namespace rollerdyn {

namespace {

using nlohmann::json;

const json& at(const json& j, const char* k) {
  static const json null_json;
  return j.is_object() && j.contains(k) ? j.at(k) : null_json;
}

std::string n(const json& v, const char* f = "%.4g", double scale = 1.0) {
  if (!v.is_number()) return "n/a";
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v.get<double>() * scale);
  return buf;
}

std::string text(const json& v) { return v.is_string() ? htmlEscape(v.get<std::string>()) : "n/a"; }

std::string checkCell(const json& v) {
  if (!v.is_string()) return "<td>n/a</td>";
  const std::string verdict = v.get<std::string>();
  const bool pass = verdict == "pass";
  return std::string("<td class=\"") + (pass ? "ok" : "bad") + "\">" + htmlEscape(verdict) + "</td>";
}

void row(std::ostringstream& h, const std::string& what, const std::string& value, const char* unit,
         const std::string& note = "") {
  h << "<tr><td>" << htmlEscape(what) << "</td><td class=\"n\">" << value << "</td><td>" << unit
    << "</td><td>" << note << "</td></tr>\n";
}

}  // namespace

std::string sizingSectionHtml(const json& s) {
  std::ostringstream h;
  h << "<h2>Motion and drive sizing</h2>\n";
  const std::string motion = at(s, "motion").is_string() ? at(s, "motion").get<std::string>() : "unknown";
  const bool turning = motion == "turning";
  h << "<div class=\"status " << (turning ? "ok" : "bad") << "\">Motion of the crank: <b>" << htmlEscape(motion)
    << "</b>"
    << (motion == "rocking" ? " (it swings back and forth instead of turning)" : "")
    << (turning ? "" : "; δ, H, k_p, the energy per revolution and the flywheel size have no meaning and are n/a")
    << "</div>\n";
  if (at(s, "stall").is_object())
    h << "<div class=\"status bad\">Why the drive stalled: " << text(at(at(s, "stall"), "explanation")) << "</div>\n";
  const json& z = at(s, "sizing");
  if (!z.is_object()) {
    h << "<p>No sizing figures in summary.json.</p>\n";
    return h.str();
  }
  const json& w = at(z, "window");
  h << "<p class=\"small\">Over the steady window t = " << n(at(w, "t_begin")) << " … " << n(at(w, "t_end"))
    << " s (" << n(at(w, "revolutions"), "%.3g") << " crank revolutions), and where marked over the whole run "
    << "(start-up included). M: motor torque at the rotor; "
       "u: reducer ratio; η: reducer efficiency; ω_r: rotor speed; ω0: synchronous speed; "
       "s = 1 − ω_r/ω0: slip.</p>\n";
  const json& m = at(z, "motor");
  h << "<h3>Motor</h3>\n";
  if (!m.is_object()) {
    h << "<p>No motor torque in this run.</p>\n";
  } else {
    const json &ts = at(m, "torque_shaft"), &tc = at(m, "torque_crank");
    h << "<table>\n<tr><th>quantity</th><th>value</th><th>unit</th><th>note</th></tr>\n";
    row(h, "torque M at the rotor: mean / RMS / peak |M|",
        n(at(ts, "mean")) + " / " + n(at(ts, "rms")) + " / " + n(at(ts, "peak")), "N·m");
    row(h, "torque at the crank M·u·η: mean / RMS / peak",
        n(at(tc, "mean")) + " / " + n(at(tc, "rms")) + " / " + n(at(tc, "peak")), "N·m");
    row(h, "nominal torque M_n", n(at(m, "nominal_torque")), "N·m", text(at(m, "nominal_torque_source")));
    row(h, "breakdown torque M_kr", n(at(m, "breakdown_torque")), "N·m");
    row(h, "shaft power M·ω_r: mean / peak",
        n(at(at(m, "power_shaft"), "mean"), "%.4g", 1e-3) + " / " + n(at(at(m, "power_shaft"), "peak"), "%.4g", 1e-3), "kW");
    row(h, "power drawn from the line: mean / peak",
        n(at(at(m, "power_line"), "mean"), "%.4g", 1e-3) + " / " + n(at(at(m, "power_line"), "peak"), "%.4g", 1e-3), "kW",
        text(at(m, "line_power_basis")));
    row(h, "slip s: min … max", n(at(at(m, "slip"), "min"), "%.4f") + " … " + n(at(at(m, "slip"), "max"), "%.4f"), "-");
    row(h, "motor energy per crank revolution", n(at(m, "energy_per_revolution"), "%.4g", 1e-3), "kJ");
    const json& r = at(m, "whole_run");
    row(h, "whole run: torque M at the rotor mean / RMS / peak |M|",
        n(at(at(r, "torque_shaft"), "mean")) + " / " + n(at(at(r, "torque_shaft"), "rms")) + " / " +
            n(at(at(r, "torque_shaft"), "peak")),
        "N·m", "start-up included");
    row(h, "whole run: power from the line mean / peak",
        n(at(at(r, "power_line"), "mean"), "%.4g", 1e-3) + " / " + n(at(at(r, "power_line"), "peak"), "%.4g", 1e-3), "kW");
    row(h, "whole run: mean rotor losses s·M·ω0", n(at(r, "rotor_losses_mean"), "%.4g", 1e-3), "kW");
    h << "</table>\n";
  }
  const json& checks = at(z, "checks");
  if (checks.is_array() && !checks.empty()) {
    h << "<h3>Checks</h3>\n<p class=\"small\">Each check names the window that decided it: the steady window or "
         "the whole run (start-up included).</p>\n<table>\n<tr><th>check</th><th>ratio</th><th>result</th>"
         "<th>decided by</th><th>why</th></tr>\n";
    for (const json& c : checks)
      h << "<tr><td>" << text(at(c, "what")) << "</td><td class=\"n\">" << n(at(c, "value"), "%.3f") << "</td>"
        << checkCell(at(c, "verdict")) << "<td>" << text(at(c, "window")) << "</td><td class=\"small\">"
        << text(at(c, "reason")) << "</td></tr>\n";
    h << "</table>\n";
  }
  const json& load = at(s, "load");
  if (load.is_object() && at(load, "available").is_boolean() && at(load, "available").get<bool>()) {
    h << "<h3>Technological load</h3>\n<p>" << text(at(load, "reading")) << "</p>\n";
    if (at(load, "warning").is_string())
      h << "<div class=\"status bad\">" << text(at(load, "warning")) << "</div>\n";
    h << "<table>\n<tr><th>cart</th><th>work, whole run [kJ]</th><th>work, steady window [kJ]</th>"
         "<th>mean power, steady window [W]</th></tr>\n";
    for (const json& c : at(load, "per_cart"))
      h << "<tr><td class=\"n\">" << at(c, "cart").dump() << "</td><td class=\"n\">"
        << n(at(c, "work_whole_run"), "%.4g", 1e-3) << "</td><td class=\"n\">" << n(at(c, "work_steady"), "%.4g", 1e-3)
        << "</td><td class=\"n\">" << n(at(c, "power_mean_steady")) << "</td></tr>\n";
    h << "</table>\n";
  }
  const json& f = at(z, "flywheel");
  h << "<h3>Flywheel</h3>\n<table>\n<tr><th>quantity</th><th>value</th><th>unit</th><th>note</th></tr>\n";
  row(h, "kinetic-energy swing ΔT over one steady revolution", n(at(f, "kinetic_energy_swing")), "J",
      "largest over the window's revolutions");
  row(h, "drive inertia at the crank J (mean 2T/ω²)", n(at(f, "inertia_effective")), "kg·m²");
  row(h, "target δ* (sizing.target_delta)", n(at(f, "target_delta")), "-");
  row(h, "flywheel on the crankshaft reaching δ*", n(at(f, "flywheel_crankshaft")), "kg·m²", text(at(f, "method")));
  row(h, "or on the motor shaft", n(at(f, "flywheel_motor_shaft")), "kg·m²", "counts u²·δ_red times");
  h << "</table>\n";
  const json& c = at(z, "coupling");
  if (c.is_object()) {
    h << "<h3>Coupling</h3>\n<table>\n<tr><th>quantity</th><th>value</th><th>unit</th><th>note</th></tr>\n";
    row(h, "torque at the crank axis: mean / peak |M| / swing",
        n(at(c, "mean")) + " / " + n(at(c, "peak")) + " / " + n(at(c, "swing")), "N·m");
    row(h, "whole run: peak |M| and when", n(at(c, "peak_whole_run")) + " at t = " + n(at(c, "t_peak_whole_run")) + " s",
        "N·m", "start-up included");
    row(h, "rated torque (sizing.coupling_rated_torque)", n(at(c, "rated_torque")), "N·m");
    h << "</table>\n";
  }
  h << "<h3>Joints and bearings</h3>\n<p class=\"small\">P: equivalent dynamic load (∫|F|³·n dt / ∫n dt)^(1/3), "
       "n the joint's rotation speed (ISO 281 style); L10 = (C/P)³·10⁶ revolutions, in hours at the mean "
       "speed, C the dynamic load rating from sizing.bearing_rating.*.</p>\n"
    << "<table>\n<tr><th>joint</th><th>cart</th><th>mean [kN]</th><th>amplitude [kN]</th><th>peak [kN]</th>"
       "<th>P [kN]</th><th>C [kN]</th><th>L10 [h]</th><th>speed weighting</th></tr>\n";
  const json& joints = at(z, "joints");
  const char* kinds[] = {"guide_roller_front", "guide_roller_rear", "rod_end", "crank_pin", "main_bearing"};
  const char* names[] = {"guide roller, front", "guide roller, rear", "rod end (cart hinge)", "crank pin (rod big end)",
                         "main bearing"};
  for (int k = 0; k < 5; ++k) {
    const json& per = at(at(joints, kinds[k]), "per_cart");
    if (!per.is_array()) continue;
    for (const json& x : per)
      h << "<tr><td>" << names[k] << "</td><td class=\"n\">" << (at(x, "cart").is_number() ? at(x, "cart").dump() : "-")
        << "</td><td class=\"n\">" << n(at(x, "mean"), "%.3f", 1e-3) << "</td><td class=\"n\">"
        << n(at(x, "amplitude"), "%.3f", 1e-3) << "</td><td class=\"n\">" << n(at(x, "peak"), "%.3f", 1e-3)
        << "</td><td class=\"n\">" << n(at(x, "equivalent_load"), "%.3f", 1e-3) << "</td><td class=\"n\">"
        << n(at(x, "rating"), "%.1f", 1e-3) << "</td><td class=\"n\">" << n(at(x, "L10_hours"), "%.3g")
        << "</td><td class=\"small\">" << text(at(x, "speed_basis")) << "</td></tr>\n";
  }
  h << "</table>\n";
  return h.str();
}

}  // namespace rollerdyn
