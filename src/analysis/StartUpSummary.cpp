#include "analysis/StartUpSummary.h"
#include "io/FieldFormat.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace rollerdyn {

namespace {

using nlohmann::json;

double ratio(double a, double b) { return std::isfinite(a) && std::isfinite(b) && b > 0 ? a / b : NAN; }

std::string f(const json& v, const char* format, double scale = 1.0) {
  if (!v.is_number()) return "n/a";
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v.get<double>() * scale);
  return buf;
}

const char* jointWords(const std::string& joint) {
  if (joint == "guide_roller_front") return "guide roller, front";
  if (joint == "guide_roller_rear") return "guide roller, rear";
  if (joint == "rod_force") return "rod force";
  if (joint == "crank_pin") return "crank pin";
  if (joint == "main_bearing") return "main bearings (resultant)";
  return "?";
}

// After a switch-off: the stopping time, or that the machine had not stopped (not "n/a s").
std::string stopText(const json& stop) {
  if (!stop.is_object()) return "";
  const json& T = jsonMember(stop, "stopping_time");
  return "  switch-off at " + f(jsonMember(stop, "t_off"), "%.4g") + " s: " +
         (T.is_number() ? "stopping time " + f(T, "%.3g") + " s" : std::string("not at rest when the run ends")) +
         ", crank run-out " + f(jsonMember(stop, "run_out_revolutions"), "%.3g") + " rev, carts' run-out " +
         f(jsonMember(stop, "run_out_cart_path"), "%.3g") + " m" + (T.is_number() ? "" : " so far") + "\n";
}

json currentLimitJson(const StartUpCurrentLimit& c) {
  if (!c.applies) return nullptr;
  return {{"limit", jsonNumber(c.limit)},
          {"bypass_speed", jsonNumber(c.bypass_speed)},
          {"max_start_time", jsonNumber(c.max_start_time)},
          {"outcome", c.outcome},
          {"end_time", jsonNumber(c.end_time)},
          {"held_time", jsonNumber(c.held_time)},
          {"binding_from", jsonNumber(c.binding_from)},
          {"voltage_min", jsonNumber(c.voltage_min)},
          {"current_peak", jsonNumber(c.current_peak)},
          {"peak_over_limit", jsonNumber(ratio(c.current_peak, c.limit))},
          {"standstill_voltage", jsonNumber(c.standstill_voltage)},
          {"standstill_torque_crank", jsonNumber(c.standstill_torque_crank)},
          {"breakaway_limit", jsonNumber(c.breakaway_limit)},
          {"rotor_speed_max", jsonNumber(c.rotor_speed_max)},
          {"stopped_the_start", c.stopped_the_start}};
}

// The soft starter's current limit, two lines; "" without one.
std::string currentLimitText(const json& c) {
  if (!c.is_object()) return "";
  const std::string outcome = jsonMember(c, "outcome").is_string() ? jsonMember(c, "outcome").get<std::string>() : "";
  const std::string end = f(jsonMember(c, "end_time"), "%.4g");
  const std::string how = outcome == "bypass"         ? "until the bypass closed at t = " + end + " s"
                          : outcome == "tripped"      ? "until the starter tripped at t = " + end + " s"
                          : outcome == "switched_off" ? "until the switch-off at t = " + end + " s"
                                                      : std::string("still when the run ends");
  const json& binding = jsonMember(c, "binding_from");
  std::ostringstream o;
  o << "  current limit I_lim           " << f(jsonMember(c, "limit"), "%g") << " A held "
    << f(jsonMember(c, "held_time"), "%.4g") << " s from switch-on, " << how << " (bypass at ω_r = "
    << f(jsonMember(c, "bypass_speed"), "%.4g") << " rad/s, where I_1(U_n) = I_lim; start time "
    << (jsonMember(c, "max_start_time").is_number() ? f(jsonMember(c, "max_start_time"), "%g") + " s" : std::string("unlimited"))
    << ")\n";
  o << "                                "
    << (binding.is_number() ? "limiting from t = " + f(binding, "%.4g") + " s, U/U_n down to " +
                                  f(jsonMember(c, "voltage_min"), "%.3g")
                            : std::string("the limit never held the voltage below the ramp"))
    << "; stator current peak " << f(jsonMember(c, "current_peak"), "%.4g") << " A (x"
    << f(jsonMember(c, "peak_over_limit"), "%.3g") << " I_lim); at standstill the limit allows U/U_n = "
    << f(jsonMember(c, "standstill_voltage"), "%.3g") << ", torque " << f(jsonMember(c, "standstill_torque_crank"), "%.4g")
    << " N·m at the crank\n";
  return o.str();
}

// The switch-on: method, motor law, whether and how the drive started, the verdict.
void addSwitchOnJson(json& j, const StartUp& s) {
  j["method"] = s.method;
  j["motor_law"] = s.motor_law;
  j["motor_model"] = s.model_word;
  j["t_on"] = s.t_on;
  j["from_rest"] = s.from_rest;
  j["supply_switches"] = s.supply_switches;
  j["starts"] = s.starts;
  j["still_starting"] = s.still_starting;
  j["verdict"] = s.verdict;
}

// The starting torque (at switch-on, rated, held at standstill) against the load at the start angle.
void addStartingTorqueJson(json& j, const StartUp& s) {
  j["starting_torque_crank"] = jsonNumber(s.starting_torque_crank);
  j["starting_torque_rated_crank"] = jsonNumber(s.starting_torque_rated_crank);
  j["largest_torque_crank"] = jsonNumber(s.largest_torque_crank);
  j["held_supply"] = s.held_supply;
  j["held_supply_is_rated"] = s.held_supply_is_rated;
  j["starting_torque_held_crank"] = jsonNumber(s.starting_torque_held_crank);
  j["largest_torque_held_crank"] = jsonNumber(s.largest_torque_held_crank);
  j["load_torque_start"] = jsonNumber(s.load_torque_start);
  j["load_torque_mean"] = jsonNumber(s.load_torque_mean);
  j["can_start_from_rest"] = s.can_start_from_rest < 0 ? json(nullptr) : json(s.can_start_from_rest == 1);
  j["start_load_ratio"] = jsonNumber(s.start_load_ratio);
  j["stall_cause"] = s.stall_cause.empty() ? json(nullptr) : json(s.stall_cause);
}

// The start's peaks against steady running's: motor torque, coupling torque, each joint.
void addStartPeaksJson(json& j, const StartUp& s) {
  j["motor_torque"] = {{"peak", jsonNumber(s.motor_torque_peak)},
                       {"min", jsonNumber(s.motor_torque_min)},
                       {"steady_peak", jsonNumber(s.motor_torque_steady_peak)},
                       {"ratio", jsonNumber(ratio(s.motor_torque_peak, s.motor_torque_steady_peak))}};
  j["coupling_torque"] = {{"peak", jsonNumber(s.coupling_torque_peak)},
                          {"steady_peak", jsonNumber(s.coupling_torque_steady_peak)},
                          {"ratio", jsonNumber(ratio(s.coupling_torque_peak, s.coupling_torque_steady_peak))}};
  json joints = json::object();
  for (const StartJointPeak& p : s.joints)
    joints[p.joint] = {{"peak", jsonNumber(p.start_peak)},
                       {"steady_peak", jsonNumber(p.steady_peak)},
                       {"ratio", jsonNumber(p.ratio)},
                       {"column", p.column}};
  j["joints"] = joints;
}

// The stator current over the start: peak, RMS and I²t; null for a law without a current.
json statorCurrentJson(const StartUp& s) {
  return std::isfinite(s.current_peak) ? json{{"peak", jsonNumber(s.current_peak)},
                                              {"rms", jsonNumber(s.current_rms)},
                                              {"i2t", jsonNumber(s.current_i2t)},
                                              {"steady_rms", jsonNumber(s.current_steady_rms)}}
                                        : json(nullptr);
}

// After a switch-off: the stopping time and the run-out; null without a switch-off.
json stopJson(const StartUp& s) {
  return std::isfinite(s.t_off) ? json{{"t_off", s.t_off},
                                       {"stopping_time", jsonNumber(s.stopping_time)},
                                       {"run_out_revolutions", jsonNumber(s.run_out_revolutions)},
                                       {"run_out_cart_path", jsonNumber(s.run_out_cart_path)}}
                                 : json(nullptr);
}

}  // namespace

json startUpJson(const StartUp& s) {
  if (!s.applicable) return nullptr;
  json j;
  addSwitchOnJson(j, s);
  addStartingTorqueJson(j, s);
  j["steady"] = {{"mean_speed", jsonNumber(s.steady_mean_speed)},
                 {"reached", s.steady_reached},
                 {"t_begin", jsonNumber(s.steady_begin)},
                 {"t_end", jsonNumber(s.steady_end)}};
  j["run_up_time"] = jsonNumber(s.run_up_time);
  j["start_end"] = jsonNumber(s.start_end);
  addStartPeaksJson(j, s);
  j["stator_current"] = statorCurrentJson(s);
  j["rotor_energy_loss"] = jsonNumber(s.rotor_energy_loss);
  j["stop"] = stopJson(s);
  j["current_limit"] = currentLimitJson(s.current_limit);
  j["notes"] = s.notes;
  j["keys_not_reached"] = s.keys_not_reached;
  return j;
}

namespace {

// The switch-on: method, motor law, verdict, and the starting torque against the load at the start
// angle (and, when the supply is held reduced at standstill, the torque it gives).
std::string switchOnText(const json& s) {
  std::ostringstream o;
  o << "start-up     " << jsonMember(s, "method").get<std::string>() << " at t = " << f(jsonMember(s, "t_on"), "%.4g")
    << " s, motor law: " << jsonMember(s, "motor_law").get<std::string>() << "\n";
  o << "             " << jsonMember(s, "verdict").get<std::string>() << "\n";
  // The static characteristic's largest torque is the breakdown torque; a transient (the Park
  // machine's switching oscillation) can exceed it, and the motor-torque line below shows that peak.
  o << "  starting torque at the crank  " << f(jsonMember(s, "starting_torque_crank"), "%.4g")
    << " N·m at switch-on (" << f(jsonMember(s, "starting_torque_rated_crank"), "%.4g")
    << " under the rated supply; the static characteristic's largest, the breakdown torque, "
    << f(jsonMember(s, "largest_torque_crank"), "%.4g") << ") against a load of " << f(jsonMember(s, "load_torque_start"), "%.4g")
    << " N·m at the start angle, " << f(jsonMember(s, "load_torque_mean"), "%.4g") << " N·m mean\n";
  const json& held = jsonMember(s, "held_supply");
  const json& held_rated = jsonMember(s, "held_supply_is_rated");
  if (held.is_string() && held_rated.is_boolean() && !held_rated.get<bool>())
    o << "  held at standstill            " << held.get<std::string>() << " until the rotor turns: starting torque "
      << f(jsonMember(s, "starting_torque_held_crank"), "%.4g") << " N·m, largest " << f(jsonMember(s, "largest_torque_held_crank"), "%.4g")
      << " N·m at the crank\n";
  return o.str();
}

// Each joint's peak load in the start against its peak in steady running (or over the run).
std::string jointPeaksText(const json& joints, const std::string& in_start, const std::string& steady) {
  std::ostringstream o;
  for (const char* kind : {"guide_roller_front", "guide_roller_rear", "rod_force", "crank_pin", "main_bearing"}) {
    const json& p = jsonMember(joints, kind);
    if (!p.is_object()) continue;
    // Bearings placed along the shaft (crankshaft.bearing_positions): the most loaded one's column.
    const json& col = jsonMember(p, "column");
    const bool each = col.is_string() && col.get<std::string>().rfind("bearing_x_", 0) == 0;
    const std::string words = each ? "main bearings (most loaded)" : jointWords(kind);
    o << "  " << words << std::string(30 - words.size(), ' ') << "peak " << f(jsonMember(p, "peak"), "%.4g", 1e-3)
      << " kN" << in_start << ", " << steady << " " << f(jsonMember(p, "steady_peak"), "%.4g", 1e-3) << " kN (x" << f(jsonMember(p, "ratio"), "%.3g")
      << ")\n";
  }
  return o.str();
}

// The stop, the notes and the legend: all a run without a start shows after its switch-on.
std::string noStartText(const json& s) {
  std::ostringstream o;
  o << stopText(jsonMember(s, "stop"));
  for (const json& n : jsonMember(s, "notes")) o << "  note: " << n.get<std::string>() << "\n";
  o << "  (torques at the crank axis; M motor torque at the rotor, u reducer ratio, η reducer efficiency)\n";
  return o.str();
}

// Whether the drive ran up, and the words for the two intervals the peaks compare: a drive that
// never ran up has a run and its end, not a start and a steady state.
struct StartIntervals {
  bool starts, still, reached;
  std::string in_start, steady;
  explicit StartIntervals(const json& s)
      : starts(jsonFlag(s, "starts")),
        still(jsonFlag(s, "still_starting")),
        reached(jsonFlag(jsonMember(s, "steady"), "reached")),
        in_start(starts ? " in the start" : (still ? " so far" : " over the run")),
        steady(starts && reached ? "steady" : "at the end") {}
};

// The run-up time and the start's interval, or why there is none.
std::string runUpText(const json& s, const StartIntervals& w) {
  const json& st = jsonMember(s, "steady");
  std::ostringstream o;
  if (w.starts)
    o << "  run-up time (to 95 % of " << f(jsonMember(st, "mean_speed"), "%.4g") << " rad/s)  "
      << f(jsonMember(s, "run_up_time"), "%.3g") << " s; start = t_on ... " << f(jsonMember(s, "start_end"), "%.4g")
      << " s (until the crank speed settles), steady window " << f(jsonMember(st, "t_begin"), "%.4g") << " ... "
      << f(jsonMember(st, "t_end"), "%.4g") << " s" << (w.reached ? "" : " (steady state NOT reached)") << "\n";
  else
    o << "  run-up time                   none: " << (w.still ? "the drive is still starting when the run ends" : "the drive does not start")
      << "; peaks below over t_on ... " << f(jsonMember(s, "start_end"), "%.4g") << " s against the run's last part "
      << f(jsonMember(st, "t_begin"), "%.4g") << " ... " << f(jsonMember(st, "t_end"), "%.4g") << " s (no steady state)\n";
  return o.str();
}

// The motor's and the coupling's torque peaks in the start against those at the end.
std::string torquePeaksText(const json& s, const StartIntervals& w) {
  std::ostringstream o;
  const json &m = jsonMember(s, "motor_torque"), &c = jsonMember(s, "coupling_torque");
  const bool negative = jsonMember(m, "min").is_number() && jsonMember(m, "min").get<double>() < 0;
  o << "  motor torque M·u·η            peak " << f(jsonMember(m, "peak"), "%.4g") << (negative ? ", most negative " : ", smallest ")
    << f(jsonMember(m, "min"), "%.4g") << " N·m" << w.in_start << "; " << w.steady << " peak |M| " << f(jsonMember(m, "steady_peak"), "%.4g")
    << " N·m (x" << f(jsonMember(m, "ratio"), "%.3g") << ")\n";
  const json &peak = jsonMember(m, "peak"), &largest = jsonMember(s, "largest_torque_crank");
  if (peak.is_number() && largest.is_number() && peak.get<double>() > 1.001 * largest.get<double>())
    o << "                                (the peak is the switching transient: above the static characteristic's "
         "largest torque, "
      << f(largest, "%.4g") << " N·m, which no steady running reaches)\n";
  o << "  coupling torque |M|           peak " << f(jsonMember(c, "peak"), "%.4g") << " N·m" << w.in_start << ", " << w.steady << " "
    << f(jsonMember(c, "steady_peak"), "%.4g") << " N·m (x" << f(jsonMember(c, "ratio"), "%.3g") << ")\n";
  return o.str();
}

// The motor's electrical side of the start: stator current, current limit, rotor energy loss.
std::string startElectricsText(const json& s, const StartIntervals& w) {
  std::ostringstream o;
  const json& I = jsonMember(s, "stator_current");
  if (I.is_object())
    o << "  stator current (phase, RMS)   peak " << f(jsonMember(I, "peak"), "%.4g") << " A, RMS" << w.in_start << " "
      << f(jsonMember(I, "rms"), "%.4g") << " A (" << w.steady << " " << f(jsonMember(I, "steady_rms"), "%.4g") << " A), I²t "
      << f(jsonMember(I, "i2t"), "%.4g") << " A²·s\n";
  o << currentLimitText(jsonMember(s, "current_limit"));
  o << "  rotor energy loss" << (w.starts ? " of the start " : w.in_start + " ") << f(jsonMember(s, "rotor_energy_loss"), "%.4g")
    << " J (slip power ∫M·(ω0·f/f_n - ω_r)dt)\n";
  return o.str();
}

}  // namespace

std::string startUpText(const json& summary) {
  const json& s = jsonMember(summary, "start_up");
  if (!s.is_object()) return "";
  std::ostringstream o;
  o << switchOnText(s);
  if (jsonMember(s, "from_rest").is_boolean() && !jsonMember(s, "from_rest").get<bool>()) return o.str() + noStartText(s);
  const StartIntervals w(s);
  o << runUpText(s, w) << torquePeaksText(s, w);
  o << jointPeaksText(jsonMember(s, "joints"), w.in_start, w.steady);
  o << startElectricsText(s, w);
  o << stopText(jsonMember(s, "stop"));
  for (const json& n : jsonMember(s, "notes")) o << "  note: " << n.get<std::string>() << "\n";
  o << "  (torques at the crank axis; M motor torque at the rotor, u reducer ratio, η reducer efficiency, ω0 "
       "synchronous speed, f/f_n supply frequency ratio)\n";
  return o.str();
}

bool startUpHasOwnFigures(const json& s) {
  if (!s.is_object()) return false;
  const bool switches = s.value("supply_switches", false);
  return switches || s.value("motor_model", std::string("kloss")) != "kloss";
}

}  // namespace rollerdyn
