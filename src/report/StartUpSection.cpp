#include "report/StartUpSection.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "analysis/StartUpSummary.h"
#include "report/HtmlReport.h"
#include "io/FieldFormat.h"

namespace rollerdyn {

namespace {

using nlohmann::json;

std::string row(const std::string& what, const std::string& start, const std::string& steady, const std::string& ratio,
                const std::string& unit) {
  return "<tr><td>" + htmlEscape(what) + "</td><td class=\"n\">" + htmlEscape(start) + "</td><td class=\"n\">" +
         htmlEscape(steady) + "</td><td class=\"n\">" + htmlEscape(ratio) + "</td><td>" + unit + "</td></tr>\n";
}

// One row of a value table: what, value, unit.
std::string line(const std::string& what, const std::string& v, const char* unit) {
  return "<tr><td>" + htmlEscape(what) + "</td><td class=\"n\">" + htmlEscape(v) + "</td><td>" + unit + "</td></tr>\n";
}

// Can it start: the torques at switch-on against the load, the run-up time and the rotor's loss.
std::string canItStartTable(const json& s) {
  std::ostringstream h;
  h << "<table>\n<tr><th>can it start</th><th>value</th><th>unit</th></tr>\n";
  h << line("starting torque at switch-on (the law's torque at standstill under the starting supply × u·η)",
       jsonNumberText(jsonMember(s, "starting_torque_crank")), "N·m");
  h << line("starting torque at the rated supply", jsonNumberText(jsonMember(s, "starting_torque_rated_crank")), "N·m");
  h << line("largest torque of the law's steady curve × u·η", jsonNumberText(jsonMember(s, "largest_torque_crank")), "N·m");
  h << line("load torque at the start angle (carts breaking away)", jsonNumberText(jsonMember(s, "load_torque_start")), "N·m");
  h << line("load torque averaged over a revolution", jsonNumberText(jsonMember(s, "load_torque_mean")), "N·m");
  const json& st = jsonMember(s, "steady");
  h << line("steady mean crank speed", jsonNumberText(jsonMember(st, "mean_speed")), "rad/s");
  h << line("run-up time to 95 % of it", jsonNumberText(jsonMember(s, "run_up_time"), "%.3g"), "s");
  h << line("rotor energy loss of the start, ∫M·(ω0·f/f_n − ω_r)dt (no load: J·ω0²/2)", jsonNumberText(jsonMember(s, "rotor_energy_loss")),
       "J");
  h << "</table>\n";
  return h.str();
}

// The motor torque's largest and smallest, and the coupling torque's largest |value|.
std::string torquePeakRows(const json& s) {
  std::ostringstream h;
  const json &m = jsonMember(s, "motor_torque"), &c = jsonMember(s, "coupling_torque");
  const bool negative = jsonMember(m, "min").is_number() && jsonMember(m, "min").get<double>() < 0;
  h << row("motor torque M·u·η, largest", jsonNumberText(jsonMember(m, "peak")), jsonNumberText(jsonMember(m, "steady_peak")), jsonNumberText(jsonMember(m, "ratio"), "%.3g"),
           "N·m");
  h << row(negative ? "motor torque M·u·η, most negative" : "motor torque M·u·η, smallest", jsonNumberText(jsonMember(m, "min")), "", "", "N·m");
  h << row("|coupling torque|", jsonNumberText(jsonMember(c, "peak")), jsonNumberText(jsonMember(c, "steady_peak")), jsonNumberText(jsonMember(c, "ratio"), "%.3g"), "N·m");
  return h.str();
}

// Each joint's largest load in the start and in the steady window [kN].
std::string jointPeakRows(const json& s) {
  std::ostringstream h;
  const char* kinds[][2] = {{"guide_roller_front", "guide roller, front (largest cart)"},
                            {"guide_roller_rear", "guide roller, rear"},
                            {"rod_force", "rod force"},
                            {"crank_pin", "crank pin (resultant)"},
                            {"main_bearing", "main bearings, resultant on the crankshaft (all bearings together; per-bearing loads need the bearing positions)"}};
  for (const auto& k : kinds) {
    const json& p = jsonMember(jsonMember(s, "joints"), k[0]);
    // Bearings placed along the shaft (crankshaft.bearing_positions): the most loaded of them.
    const bool each = jsonMember(p, "column").is_string() && jsonMember(p, "column").get<std::string>().rfind("bearing_x_", 0) == 0;
    if (p.is_object())
      h << row(each ? "main bearings, the most loaded one (each bearing's share of the crankshaft's beam statics)" : k[1], jsonNumberText(jsonMember(p, "peak"), "%.4g", 1e-3), jsonNumberText(jsonMember(p, "steady_peak"), "%.4g", 1e-3),
               jsonNumberText(jsonMember(p, "ratio"), "%.3g"), "kN");
  }
  return h.str();
}

// The stator current's peak, RMS and I²t (motor laws with a current).
std::string statorCurrentRows(const json& s) {
  std::ostringstream h;
  const json& I = jsonMember(s, "stator_current");
  if (I.is_object()) {
    h << row("stator current (RMS phase), largest", jsonNumberText(jsonMember(I, "peak")), "", "", "A");
    h << row("stator current, RMS", jsonNumberText(jsonMember(I, "rms")), jsonNumberText(jsonMember(I, "steady_rms")), "", "A");
    h << row("I²t of the start", jsonNumberText(jsonMember(I, "i2t")), "", "", "A²·s");
  }
  return h.str();
}

// The peaks of the start (or of the whole run when it did not run up) against the steady ones.
std::string startPeaksTable(const json& s, bool starts, bool still_starting) {
  std::ostringstream h;
  if (starts)
    h << "<table>\n<tr><th>peak</th><th>in the start</th><th>steady window</th><th>start/steady</th><th>unit</th></tr>\n";
  else
    h << "<table>\n<tr><th>peak</th><th>" << (still_starting ? "so far" : "over the run")
      << "</th><th>the run's last part</th><th>ratio</th><th>unit</th></tr>\n";
  h << torquePeakRows(s) << jointPeakRows(s) << statorCurrentRows(s);
  h << "</table>\n";
  return h.str();
}

// How long the soft starter's current limit held, by the start's outcome, after "held from the switch-on, ".
const char* currentLimitHeldUntil(const json& lim) {
  const std::string outcome = jsonMember(lim, "outcome").is_string() ? jsonMember(lim, "outcome").get<std::string>() : "";
  return outcome == "bypass"         ? "until the bypass closed (the motor up to speed)"
         : outcome == "tripped"      ? "until the starter tripped (a failed start)"
         : outcome == "switched_off" ? "until the switch-off"
                                     : "still when the run ended";
}

// The soft starter's current limit: how long it held, where the bypass closed, what it allows at standstill.
std::string currentLimitTable(const json& lim) {
  std::ostringstream h;
  if (lim.is_object()) {
    const char* how = currentLimitHeldUntil(lim);
    h << "<table>\n<tr><th>soft starter's current limit</th><th>value</th><th>unit</th></tr>\n";
    h << line("current limit I_lim (RMS stator phase current)", jsonNumberText(jsonMember(lim, "limit")), "A");
    h << line(std::string("held from the switch-on, ") + how, jsonNumberText(jsonMember(lim, "held_time"), "%.4g"), "s");
    h << line("ended at", jsonNumberText(jsonMember(lim, "end_time"), "%.4g"), "s");
    h << line("rotor speed of the bypass, where the current at U_n falls to I_lim", jsonNumberText(jsonMember(lim, "bypass_speed")),
         "rad/s");
    h << line("maximum start time (the starter trips after it; n/a: never)", jsonNumberText(jsonMember(lim, "max_start_time")), "s");
    h << line("the limit held the voltage below the ramp from", jsonNumberText(jsonMember(lim, "binding_from"), "%.4g"), "s");
    h << line("smallest voltage U/U_n while limited", jsonNumberText(jsonMember(lim, "voltage_min"), "%.3g"), "–");
    h << line("stator current peak while limited", jsonNumberText(jsonMember(lim, "current_peak")), "A");
    h << line("that peak over I_lim", jsonNumberText(jsonMember(lim, "peak_over_limit"), "%.3g"), "–");
    h << line("voltage the limit allows at standstill, U/U_n", jsonNumberText(jsonMember(lim, "standstill_voltage"), "%.3g"), "–");
    h << line("torque at standstill under it × u·η", jsonNumberText(jsonMember(lim, "standstill_torque_crank")), "N·m");
    h << line("limit that breaks the motor away at the start angle", jsonNumberText(jsonMember(lim, "breakaway_limit")), "A");
    h << "</table>\n";
  }
  return h.str();
}

// After the switch-off: stopping time and run-out.
std::string stoppingTable(const json& stop) {
  std::ostringstream h;
  if (stop.is_object()) {
    h << "<table>\n<tr><th>after the switch-off at t = " << jsonNumberText(jsonMember(stop, "t_off")) << " s</th><th>value</th><th>unit</th></tr>\n";
    h << line("stopping time (crank below 1 % of the synchronous crank speed)", jsonNumberText(jsonMember(stop, "stopping_time"), "%.3g"), "s");
    h << line("crank run-out", jsonNumberText(jsonMember(stop, "run_out_revolutions"), "%.3g"), "revolutions");
    h << line("carts' run-out (largest path of a cart)", jsonNumberText(jsonMember(stop, "run_out_cart_path"), "%.3g"), "m");
    h << "</table>\n";
  }
  return h.str();
}

// The starting method, the motor law and what the start is; the verdict and the notes.
std::string startIntroHtml(const json& s, bool starts, bool still_starting) {
  std::ostringstream h;
  h << "<p class=\"small\">Starting method: " << htmlEscape(jsonMember(s, "method").get<std::string>()) << " at t = "
    << jsonNumberText(jsonMember(s, "t_on")) << " s; motor law: " << htmlEscape(jsonMember(s, "motor_law").get<std::string>())
    << ". Torques at the crank axis (M at the rotor × u·η: u reducer ratio, η its efficiency); "
    << (starts ? "the start runs from the switch-on until the crank speed settles (the first revolution from which "
                 "every later one has the same mean speed within 1e-3)."
               : "the drive did not run up, so the peaks are over the whole run and are compared with its last part.")
    << "</p>\n";
  h << "<div class=\"status " << (starts ? "ok" : still_starting ? "warn" : "bad") << "\">" << htmlEscape(jsonMember(s, "verdict").get<std::string>())
    << "</div>\n";
  for (const json& n : jsonMember(s, "notes"))
    h << "<div class=\"status warn\">" << htmlEscape(n.get<std::string>()) << "</div>\n";
  return h.str();
}

// Which figures of the page show the start.
std::string startFiguresNote(const json& s) {
  std::ostringstream h;
  if (startUpHasOwnFigures(s))
    h << "<p class=\"small\">Figures below: <code>start_up_speed</code>, <code>start_up_torque</code>"
      << (jsonMember(s, "stator_current").is_object() ? ", <code>start_up_current</code>" : "") << " (against time).</p>\n";
  else
    h << "<p class=\"small\">Figures below: <code>crank_speed_vs_time</code>, <code>motor_torque_vs_time</code>, "
         "<code>coupling_torque_vs_time</code> (against time, the steady window marked).</p>\n";
  return h.str();
}

}  // namespace

std::string startUpSectionHtml(const json& summary) {
  std::ostringstream h;
  h << "<h2>Start-up and stopping</h2>\n";
  const json& s = jsonMember(summary, "start_up");
  if (!s.is_object()) {
    h << "<p>No start-up answers: the run switches no motor on.</p>\n";
    return h.str();
  }
  const bool starts = jsonFlag(s, "starts");
  const bool still_starting = jsonFlag(s, "still_starting");
  h << startIntroHtml(s, starts, still_starting);
  h << canItStartTable(s);
  h << startPeaksTable(s, starts, still_starting);
  h << currentLimitTable(jsonMember(s, "current_limit"));
  h << stoppingTable(jsonMember(s, "stop"));
  h << startFiguresNote(s);
  return h.str();
}

}  // namespace rollerdyn
