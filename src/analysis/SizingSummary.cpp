#include "analysis/SizingSummary.h"

#include "analysis/SizingCheckJson.h"
#include "analysis/CrankshaftSummary.h"
#include "io/FieldFormat.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace rollerdyn {

namespace {

using nlohmann::json;


json jointRowJson(const JointSizing& j);

json jointJson(const JointSizing& j) {
  json row = jointRowJson(j);
  if (j.bearing > 0) {  // a main bearing of crankshaft.bearing_positions: which one and where
    row["bearing"] = j.bearing;
    row["position"] = jsonNumber(j.position);
  }
  return row;
}

json jointRowJson(const JointSizing& j) {
  constexpr double kDegPerRad = 57.295779513082320876798154814105;
  return {{"cart", j.cart > 0 ? json(j.cart) : json(nullptr)},
          {"column", j.column},
          {"mean", jsonNumber(j.load.mean)},
          {"amplitude", jsonNumber(j.load.amplitude)},
          {"peak", jsonNumber(j.load.peak)},
          {"equivalent_load", jsonNumber(j.load.equivalent)},
          {"mean_speed", jsonNumber(j.load.mean_speed)},
          {"speed_basis", j.speed_basis},
          {"rating", jsonNumber(j.rating)},
          {"motion", j.oscillating ? "oscillating" : "rotating"},
          {"oscillation_angle_deg", jsonNumber(j.oscillation_angle * kDegPerRad)},
          {"oscillation_frequency", jsonNumber(j.oscillation_frequency)},
          {"rolling_elements_min", jsonNumber(j.rolling_elements_min)},
          {"L10_revolutions", jsonNumber(j.life_revolutions)},
          {"L10_oscillations", jsonNumber(j.life_oscillations)},
          {"L10_hours", jsonNumber(j.life_hours)},
          {"life_basis", j.life_basis},
          {"life_reason", j.life_reason.empty() ? json(nullptr) : json(j.life_reason)}};
}

const char* kJointKinds[] = {"guide_roller_front", "guide_roller_rear", "rod_end", "crank_pin",
                             "main_bearing"};

// The motor over the whole run: torque, rotor losses and heating, the start's heat, line power, slip.
json motorWholeRunJson(const MotorWholeRun& r) {
  return {{"torque_shaft", {{"mean", jsonNumber(r.torque_shaft_mean)}, {"rms", jsonNumber(r.torque_shaft_rms)}, {"peak", jsonNumber(r.torque_shaft_peak)}}},
          {"rms_over_nominal", jsonNumber(r.rms_over_nominal)},
          {"rotor_losses_mean", jsonNumber(r.rotor_losses_mean)},
          {"thermal_over_nominal", jsonNumber(r.thermal_over_nominal)},
          {"thermal_basis", r.thermal_basis},
          {"start_heat", jsonNumber(r.start_heat)},
          {"start_duration", jsonNumber(r.start_duration)},
          {"start_heat_above_steady", jsonNumber(r.start_heat_above_steady)},
          {"starts_per_hour", jsonNumber(r.starts_per_hour)},
          {"power_line", {{"mean", jsonNumber(r.power_line_mean)}, {"peak", jsonNumber(r.power_line_peak)}}},
          {"slip", {{"min", jsonNumber(r.slip_min)}, {"max", jsonNumber(r.slip_max)}}}};
}

// The motor's torques, powers and slip in the steady window and over the whole run; the heating
// and breakdown verdicts come from the checks.
json motorSizingJson(const MotorSizing& m, const json& rms_check, const json& peak_check) {
  return {
      {"torque_shaft", {{"mean", jsonNumber(m.torque_shaft_mean)}, {"rms", jsonNumber(m.torque_shaft_rms)}, {"peak", jsonNumber(m.torque_shaft_peak)}}},
      {"torque_crank", {{"mean", jsonNumber(m.torque_crank_mean)}, {"rms", jsonNumber(m.torque_crank_rms)}, {"peak", jsonNumber(m.torque_crank_peak)}}},
      {"nominal_torque", jsonNumber(m.nominal_torque)},
      {"nominal_torque_source", m.nominal_source},
      {"breakdown_torque", jsonNumber(m.breakdown_torque)},
      {"breakdown_torque_catalogue", jsonNumber(m.breakdown_torque_catalogue)},
      {"rms_over_nominal", jsonNumber(m.rms_over_nominal)},
      {"rms_check", rms_check},
      {"peak_over_breakdown", jsonNumber(m.peak_over_breakdown)},
      {"torque_motoring_peak", jsonNumber(m.torque_motoring_peak)},
      {"torque_generating_peak", jsonNumber(m.torque_generating_peak)},
      {"breakdown_torque_generating", jsonNumber(m.breakdown_torque_generating)},
      {"peak_check", peak_check},
      {"power_shaft", {{"mean", jsonNumber(m.power_shaft_mean)}, {"peak", jsonNumber(m.power_shaft_peak)}}},
      {"power_line", {{"mean", jsonNumber(m.power_line_mean)}, {"peak", jsonNumber(m.power_line_peak)}}},
      {"line_power_basis", m.line_power_basis},
      {"slip", {{"min", jsonNumber(m.slip_min)}, {"max", jsonNumber(m.slip_max)}}},
      {"energy_per_revolution", jsonNumber(m.energy_per_revolution)},
      {"whole_run", motorWholeRunJson(m.whole_run)}};
}

// The flywheel the speed fluctuation asks for.
json flywheelSizingJson(const FlywheelSizing& f) {
  return {{"kinetic_energy_swing", jsonNumber(f.kinetic_energy_swing)},
          {"inertia_effective", jsonNumber(f.inertia_effective)},
          {"delta", jsonNumber(f.delta)},
          {"target_delta", jsonNumber(f.target_delta)},
          {"added_inertia_crankshaft", jsonNumber(f.added_inertia_crank)},
          {"flywheel_crankshaft", jsonNumber(f.flywheel_crankshaft)},
          {"flywheel_motor_shaft", jsonNumber(f.flywheel_motor_shaft)},
          {"excess_work", jsonNumber(f.excess_work)},
          {"omega_mean", jsonNumber(f.omega_mean)},
          {"inertia_required", jsonNumber(f.inertia_required)},
          {"added_inertia_energy_method", jsonNumber(f.added_inertia_energy_method)},
          {"method", f.method.empty() ? json(nullptr) : json(f.method)},
          {"estimate", f.basis.empty() ? json(nullptr) : json(f.estimate)},
          {"basis", f.basis.empty() ? json(nullptr) : json(f.basis)}};
}

// The coupling torque against the coupling's rating; the verdict comes from the checks.
json couplingSizingJson(const CouplingSizing& c, const json& check) {
  return {{"mean", jsonNumber(c.mean)}, {"peak", jsonNumber(c.peak)}, {"swing", jsonNumber(c.swing)},
          {"rated_torque", jsonNumber(c.rating)}, {"peak_over_rating", jsonNumber(c.peak_over_rating)},
          {"peak_whole_run", jsonNumber(c.peak_whole_run)}, {"t_peak_whole_run", jsonNumber(c.t_peak_whole_run)},
          {"peak_over_rating_whole_run", jsonNumber(c.peak_over_rating_whole_run)},
          {"check", check}};
}

// Per kind of joint: the worst bearing and every cart's, or null when the run has none.
json jointsSizingJson(const DriveSizing& s) {
  json joints = json::object();
  for (const char* kind : kJointKinds) {
    const JointSizing* w = s.worst(kind);
    if (!w) {
      joints[kind] = nullptr;
      continue;
    }
    json per = json::array();
    for (const JointSizing& x : s.joints)
      if (x.joint == kind) per.push_back(jointJson(x));
    joints[kind] = {{"what", w->what}, {"worst", jointJson(*w)}, {"per_cart", per}};
  }
  return joints;
}

// The verdict of the check so named (the last one), null when there is none or it has none.
json checkVerdict(const std::vector<SizingCheck>& checks, const char* name) {
  const SizingCheck* found = nullptr;
  for (const SizingCheck& c : checks)
    if (c.name == name) found = &c;
  return found && !found->verdict.empty() ? json(found->verdict) : json(nullptr);
}

}  // namespace

json sizingJson(const DriveSizing& s) {
  json j;
  j["window"] = {{"t_begin", jsonNumber(s.t_begin)}, {"t_end", jsonNumber(s.t_end)}, {"revolutions", jsonNumber(s.revolutions)}};
  j["whole_run"] = {{"t_begin", jsonNumber(s.run_t_begin)}, {"t_end", jsonNumber(s.run_t_end)}};
  j["motion"] = s.motion;
  json checks = json::array();
  for (const SizingCheck& c : s.checks) checks.push_back(sizingCheckJson(c));
  j["checks"] = checks;
  j["motor"] = s.motor.available ? motorSizingJson(s.motor, checkVerdict(s.checks, "motor_heating"),
                                                   checkVerdict(s.checks, "motor_breakdown"))
                                 : json(nullptr);
  j["flywheel"] = flywheelSizingJson(s.flywheel);
  j["coupling"] = s.coupling.available ? couplingSizingJson(s.coupling, checkVerdict(s.checks, "coupling")) : json(nullptr);
  j["joints"] = jointsSizingJson(s);
  j["fatigue"] = fatigueJson(s.fatigue);
  j["coupling_selection"] = couplingSelectionJson(s.coupling_selection);
  j["gear"] = gearDutyJson(s.gear);
  j["motor_duty"] = motorDutyJson(s.motor_duty);
  if (s.crankshaft.given) j["crankshaft"] = crankshaftJson(s.crankshaft);
  j["life_exponent"] = kBearingLifeExponent;
  return j;
}

const std::vector<std::pair<std::string, std::string>>& sizingMetricPaths() {
  static const std::vector<std::pair<std::string, std::string>> p = {
      {"motor_torque_rotor_rms", "sizing.motor.torque_shaft.rms"},
      {"motor_torque_rotor_peak", "sizing.motor.torque_shaft.peak"},
      {"motor_rms_over_nominal", "sizing.motor.rms_over_nominal"},
      {"motor_peak_over_breakdown", "sizing.motor.peak_over_breakdown"},
      {"motor_power_mean", "sizing.motor.power_shaft.mean"},
      {"motor_power_peak", "sizing.motor.power_shaft.peak"},
      {"energy_per_revolution", "sizing.motor.energy_per_revolution"},
      {"kinetic_energy_swing", "sizing.flywheel.kinetic_energy_swing"},
      {"coupling_torque_peak", "sizing.coupling.peak"},
      {"load_power_per_cart", "load.power_mean_per_cart_steady"},
      {"load_net_over_gross", "load.net_over_gross_steady"},
      {"motor_torque_rotor_rms_whole_run", "sizing.motor.whole_run.torque_shaft.rms"},
      {"motor_thermal_whole_run", "sizing.motor.whole_run.thermal_over_nominal"},
      {"motor_power_line_mean_whole_run", "sizing.motor.whole_run.power_line.mean"},
      {"coupling_torque_peak_whole_run", "sizing.coupling.peak_whole_run"},
      {"guide_roller_peak", "sizing.joints.guide_roller_front.worst.peak"},
      {"guide_roller_rear_peak", "sizing.joints.guide_roller_rear.worst.peak"},
      {"rod_force_peak", "sizing.joints.rod_end.worst.peak"},
      {"crank_pin_peak", "sizing.joints.crank_pin.worst.peak"},
      {"main_bearing_peak", "sizing.joints.main_bearing.worst.peak"},
      {"guide_roller_equivalent_load", "sizing.joints.guide_roller_front.worst.equivalent_load"},
      {"crank_pin_equivalent_load", "sizing.joints.crank_pin.worst.equivalent_load"},
      {"main_bearing_equivalent_load", "sizing.joints.main_bearing.worst.equivalent_load"},
  };
  return p;
}

// What the whole run holds beyond the steady window, in words: a start from rest, or (a run that
// begins at speed, or a machine without motor) no start at all.
static std::string wholeRunWords(const json& summary) {
  const json& su = jsonMember(summary, "start_up");
  if (jsonFlag(su, "from_rest"))
    return "start-up included";
  return su.is_object() ? "begins at speed: no start-up" : "no motor start in the run";
}

namespace {

// One row of the joints' table: label, cart, mean, amplitude, peak, P, C [kN], L10 [h].
std::string jointLine(const std::string& label, const json& x) {
  char buf[256];
  std::snprintf(buf, sizeof buf, "  %-24s  %4s  %9s  %14s  %9s  %6s  %6s  %7s\n", label.c_str(),
                jsonMember(x, "cart").is_number() ? std::to_string(jsonMember(x, "cart").get<int>()).c_str() : "-",
                jsonNumberText(jsonMember(x, "mean"), "%.3f", 1e-3).c_str(), jsonNumberText(jsonMember(x, "amplitude"), "%.3f", 1e-3).c_str(),
                jsonNumberText(jsonMember(x, "peak"), "%.3f", 1e-3).c_str(), jsonNumberText(jsonMember(x, "equivalent_load"), "%.3f", 1e-3).c_str(),
                jsonNumberText(jsonMember(x, "rating"), "%.1f", 1e-3).c_str(), jsonNumberText(jsonMember(x, "L10_hours"), "%.3g").c_str());
  return buf;
}

// The heading: the window the figures are taken over and the whole run.
std::string sizingHeading(const json& summary, bool steady) {
  const json& s = jsonMember(summary, "sizing");
  const json& w = jsonMember(s, "window");
  const json& wr = jsonMember(s, "whole_run");
  std::ostringstream o;
  o << "drive sizing over the " << (steady ? "steady window" : "run's last part (no steady state)") << " t = "
    << jsonNumberText(jsonMember(w, "t_begin"), "%.4g") << " ... " << jsonNumberText(jsonMember(w, "t_end"), "%.4g") << " s ("
    << jsonNumberText(jsonMember(w, "revolutions"), "%.3g") << " crank revolutions)"
    << " and over the whole run t = " << jsonNumberText(jsonMember(wr, "t_begin"), "%.4g") << " ... " << jsonNumberText(jsonMember(wr, "t_end"), "%.4g")
    << " s (" << wholeRunWords(summary) << ")\n"
    << "  M motor torque at the rotor, u reducer ratio, η reducer efficiency, ω_r rotor speed, ω0 synchronous speed\n";
  return o.str();
}

// The motor's torques at the rotor and at the crank, its nominal and breakdown torques.
std::string motorTorqueText(const json& m, const char* win) {
  std::ostringstream o;
  const json &ts = jsonMember(m, "torque_shaft"), &tc = jsonMember(m, "torque_crank");
  const json& r = jsonMember(m, "whole_run");
  o << "  motor torque at the rotor M       mean " << jsonNumberText(jsonMember(ts, "mean"), "%.4g") << ", RMS "
    << jsonNumberText(jsonMember(ts, "rms"), "%.4g") << ", peak |M| " << jsonNumberText(jsonMember(ts, "peak"), "%.4g") << " N·m" << win << "\n"
    << "                                    mean " << jsonNumberText(jsonMember(jsonMember(r, "torque_shaft"), "mean"), "%.4g") << ", RMS "
    << jsonNumberText(jsonMember(jsonMember(r, "torque_shaft"), "rms"), "%.4g") << ", peak |M| " << jsonNumberText(jsonMember(jsonMember(r, "torque_shaft"), "peak"), "%.4g")
    << " N·m (whole run)\n";
  o << "  motor torque at the crank M·u·η   mean " << jsonNumberText(jsonMember(tc, "mean"), "%.4g") << ", RMS "
    << jsonNumberText(jsonMember(tc, "rms"), "%.4g") << ", peak " << jsonNumberText(jsonMember(tc, "peak"), "%.4g") << " N·m" << win << "\n";
  o << "  nominal torque M_n                " << jsonNumberText(jsonMember(m, "nominal_torque"), "%.4g") << " N·m ("
    << jsonText(jsonMember(m, "nominal_torque_source"), "n/a") << "); breakdown torque M_kr " << jsonNumberText(jsonMember(m, "breakdown_torque"), "%.4g")
    << " N·m";
  if (jsonMember(m, "breakdown_torque_catalogue").is_number())
    o << " (the catalogue's (M_k/M_n)·P_n/ω_n: " << jsonNumberText(jsonMember(m, "breakdown_torque_catalogue"), "%.4g") << " N·m)";
  o << "\n";
  return o.str();
}

// The motor's shaft and line power, its slip and its energy per crank revolution.
std::string motorPowerText(const json& m, const char* win) {
  std::ostringstream o;
  const json& r = jsonMember(m, "whole_run");
  const json &ps = jsonMember(m, "power_shaft"), &pl = jsonMember(m, "power_line"), &sl = jsonMember(m, "slip");
  o << "  shaft power M·ω_r                 mean " << jsonNumberText(jsonMember(ps, "mean"), "%.4g", 1e-3) << ", peak "
    << jsonNumberText(jsonMember(ps, "peak"), "%.4g", 1e-3) << " kW" << win << "\n";
  o << "  power drawn from the line         mean " << jsonNumberText(jsonMember(pl, "mean"), "%.4g", 1e-3) << ", peak "
    << jsonNumberText(jsonMember(pl, "peak"), "%.4g", 1e-3) << " kW" << win << "; mean "
    << jsonNumberText(jsonMember(jsonMember(r, "power_line"), "mean"), "%.4g", 1e-3) << ", peak " << jsonNumberText(jsonMember(jsonMember(r, "power_line"), "peak"), "%.4g", 1e-3)
    << " kW (whole run)\n"
    << "                                    (" << jsonText(jsonMember(m, "line_power_basis"), "n/a") << ")\n";
  o << "  slip s = 1 - ω_r/ω0               " << jsonNumberText(jsonMember(sl, "min"), "%.4f") << " ... "
    << jsonNumberText(jsonMember(sl, "max"), "%.4f") << win << "; " << jsonNumberText(jsonMember(jsonMember(r, "slip"), "min"), "%.4f") << " ... "
    << jsonNumberText(jsonMember(jsonMember(r, "slip"), "max"), "%.4f") << " (whole run)\n";
  const json& e_rev = jsonMember(m, "energy_per_revolution");
  o << "  motor energy per crank revolution "
    << (e_rev.is_number() ? jsonNumberText(e_rev, "%.4g", 1e-3) + " kJ" : std::string("n/a (the crank does not turn in the window)"))
    << "\n";
  return o.str();
}

// The motor's torques, powers, slip and energy per revolution; `win` names the window.
std::string motorText(const json& m, const char* win) {
  if (!m.is_object()) return "  motor                             n/a (no motor torque in this run)\n";
  return motorTorqueText(m, win) + motorPowerText(m, win);
}

// The coupling's torques and its rating; nothing without them. `win` names the window.
std::string couplingText(const json& c, const char* win) {
  std::ostringstream o;
  if (!c.is_object()) return o.str();
  o << "  coupling torque (crank axis)      mean " << jsonNumberText(jsonMember(c, "mean"), "%.4g") << ", peak |M| "
    << jsonNumberText(jsonMember(c, "peak"), "%.4g") << ", swing " << jsonNumberText(jsonMember(c, "swing"), "%.4g") << " N·m" << win << "; peak |M| "
    << jsonNumberText(jsonMember(c, "peak_whole_run"), "%.4g") << " N·m at t = " << jsonNumberText(jsonMember(c, "t_peak_whole_run"), "%.4g")
    << " s (whole run)\n";
  o << "  coupling rated torque             "
    << (jsonMember(c, "rated_torque").is_number() ? jsonNumberText(jsonMember(c, "rated_torque"), "%.4g") + " N·m"
                                          : std::string("not given (sizing.coupling_rated_torque)"))
    << "\n";
  return o.str();
}

// The checks with their verdicts and the window that decided each; nothing without checks.
std::string checksText(const json& checks) {
  std::ostringstream o;
  if (!checks.is_array() || checks.empty()) return o.str();
  o << "  checks (the window named decided each):\n";
  for (const json& k : checks) {
    const std::string v = jsonText(jsonMember(k, "verdict"), "n/a");
    char buf[200];
    std::snprintf(buf, sizeof buf, "    %-15s %8s  %-14s decided by the %s", jsonText(jsonMember(k, "check"), "n/a").c_str(),
                  jsonNumberText(jsonMember(k, "value"), "%.3f").c_str(), v.c_str(), jsonText(jsonMember(k, "window"), "n/a").c_str());
    o << buf << "\n      " << jsonText(jsonMember(k, "what"), "n/a") << "; " << jsonText(jsonMember(k, "reason"), "n/a") << "\n";
  }
  return o.str();
}

// How each kind's life follows, or why it is n/a (the same reason for every cart of a kind).
std::string jointLivesText(const json& joints) {
  std::ostringstream o;
  for (const char* kind : kJointKinds) {
    const json& j = jsonMember(joints, kind);
    const json& x = jsonMember(j, "worst");
    if (!x.is_object()) continue;
    o << "    " << jsonText(jsonMember(j, "what"), "n/a") << ": ";
    if (jsonMember(x, "L10_hours").is_number()) {
      if (jsonMember(x, "L10_oscillations").is_number())
        o << "L10 " << jsonNumberText(jsonMember(x, "L10_revolutions"), "%.3g") << " revolutions = "
          << jsonNumberText(jsonMember(x, "L10_oscillations"), "%.3g") << " oscillations; ";
      o << jsonText(jsonMember(x, "life_basis"), "n/a");
    } else {
      o << "L10 n/a: " << jsonText(jsonMember(x, "life_reason"), "n/a");
    }
    o << "\n";
  }
  return o.str();
}

// The joint loads of the most loaded cart of each kind (every main bearing placed along the
// shaft), where they come from and how their lives follow.
std::string jointsText(const json& s) {
  const json& joints = jsonMember(s, "joints");
  std::ostringstream o;
  if (jsonMember(s, "joints_basis").is_string()) o << "  joint loads from the " << jsonText(jsonMember(s, "joints_basis"), "n/a") << "\n";
  o << "  joint (most loaded cart)  cart  mean [kN]  amplitude [kN]  peak [kN]  P [kN]  C [kN]  L10 [h]\n";
  const char* names[] = {"guide roller, front", "guide roller, rear", "rod end", "crank pin", "main bearings, resultant"};
  for (std::size_t k = 0; k < 5; ++k) {
    const json& x = jsonMember(jsonMember(joints, kJointKinds[k]), "worst");
    if (!x.is_object()) continue;
    if (!jsonMember(x, "bearing").is_number()) {
      o << jointLine(names[k], x);
      continue;
    }
    // Bearings placed along the shaft (crankshaft.bearing_positions): every one of them.
    for (const json& b : jsonMember(jsonMember(joints, kJointKinds[k]), "per_cart"))
      o << jointLine("main bearing " + std::to_string(jsonMember(b, "bearing").get<int>()) + ", z " +
                         jsonNumberText(jsonMember(b, "position"), "%.3g") + " m",
                     b);
  }
  o << "  P equivalent dynamic load (∫|F|³·n dt / ∫n dt)^(1/3), n the joint's rotation or swing speed; "
       "C dynamic load rating (sizing.bearing_rating.*); L10 in hours of steady running:\n";
  o << jointLivesText(joints);
  return o.str();
}

}  // namespace

std::string sizingText(const json& summary) {
  const json& s = jsonMember(summary, "sizing");
  if (!s.is_object()) return "";
  std::ostringstream o;
  const json& reached = jsonMember(jsonMember(summary, "steady_state"), "reached");
  const bool steady = !reached.is_boolean() || reached.get<bool>();
  // Each figure's window named as the heading names it: no "steady window" where there is none.
  const char* win = steady ? " (steady window)" : " (the run's last part)";
  o << sizingHeading(summary, steady) << motorText(jsonMember(s, "motor"), win) << flywheelText(summary)
    << couplingText(jsonMember(s, "coupling"), win) << signOffText(s) << dutyText(s)
    << checksText(jsonMember(s, "checks"));
  const json& joints = jsonMember(s, "joints");
  bool any_joint = false;
  for (const char* kind : kJointKinds) any_joint = any_joint || jsonMember(jsonMember(joints, kind), "worst").is_object();
  if (!any_joint) {
    o << "  joint loads                       not computed: the run has no joint reactions "
         "(simulation.reactions: false)\n";
    return o.str();
  }
  o << jointsText(s) << crankshaftText(jsonMember(s, "crankshaft"));
  return o.str();
}

}  // namespace rollerdyn
