// The gear load spectrum after ISO 6336-6 (GearDuty.h) and the motor's starts after IEC 60034-1
// (MotorDuty.h) as members of summary.json's `sizing`, and their lines of the console table,
// rendered from that JSON only (the verdicts are sizing.checks').
#include <cmath>
#include <cstdio>
#include <sstream>

#include "analysis/SizingSummary.h"
#include "io/FieldFormat.h"

namespace rollerdyn {

using nlohmann::json;

namespace {

json flankJson(const FlankSpectrum& f) {
  json classes = json::array();
  for (const TorqueClass& c : f.classes) classes.push_back({{"torque", c.torque}, {"cycles", c.cycles}});
  return {{"cycles", f.cycles}, {"equivalent_torque", jsonNumber(f.equivalent_torque)}, {"classes", classes}};
}

json spectrumJson(const GearSpectrum& s) {
  if (!s.applies) return {{"applies", false}, {"reason", s.not_applicable}};
  return {{"applies", true},         {"t_begin", jsonNumber(s.t_begin)}, {"t_end", jsonNumber(s.t_end)},
          {"revolutions", jsonNumber(s.revolutions)}, {"drive", flankJson(s.drive)}, {"coast", flankJson(s.coast)}};
}

void spectrumLine(std::ostringstream& o, const char* name, const json& s) {
  o << "    " << name;
  if (!jsonFlag(s, "applies")) {
    o << "n/a (" << jsonText(jsonMember(s, "reason")) << ")\n";
    return;
  }
  const json &d = jsonMember(s, "drive"), &c = jsonMember(s, "coast");
  o << jsonNumberText(jsonMember(s, "revolutions"), "%.3g")
    << " revolutions (t = " << jsonNumberText(jsonMember(s, "t_begin")) << " ... "
    << jsonNumberText(jsonMember(s, "t_end")) << " s): drive flank " << jsonNumberText(jsonMember(d, "cycles"), "%.3g")
    << " rev, T_eq " << jsonNumberText(jsonMember(d, "equivalent_torque")) << " N·m; other flank "
    << jsonNumberText(jsonMember(c, "cycles"), "%.3g") << " rev, T_eq "
    << jsonNumberText(jsonMember(c, "equivalent_torque")) << " N·m\n";
}

void gearText(std::ostringstream& o, const json& g) {
  o << "  reducer load spectrum (" << jsonText(jsonMember(g, "method")) << "), " << jsonText(jsonMember(g, "torque"))
    << ":\n"
    << "    p = " << jsonNumberText(jsonMember(g, "exponent"), "%.3g") << ", classes of "
    << jsonNumberText(jsonMember(g, "class_width"))
    << " N·m (each at its upper limit); T_n = u·η·M_n = " << jsonNumberText(jsonMember(g, "nominal_torque"))
    << " N·m\n";
  spectrumLine(o, "start:         ", jsonMember(g, "start"));
  spectrumLine(o, "steady window: ", jsonMember(g, "steady"));
  const json& d = jsonMember(g, "duty");
  if (jsonFlag(d, "applies"))
    o << "    duty hour:     T_eq " << jsonNumberText(jsonMember(d, "equivalent_torque")) << " N·m ("
      << jsonText(jsonMember(d, "deciding_flank")) << "), K_A = T_eq/T_n "
      << jsonNumberText(jsonMember(g, "application_factor"), "%.3g") << " (assumed "
      << jsonNumberText(jsonMember(g, "assumed_application_factor"), "%.3g") << "); "
      << jsonText(jsonMember(d, "basis")) << "\n";
  else
    o << "    duty hour:     n/a (" << jsonText(jsonMember(d, "reason")) << ")\n";
  o << "    peak |T| " << jsonNumberText(jsonMember(g, "peak"))
    << " N·m at t = " << jsonNumberText(jsonMember(g, "t_peak")) << " s; ratings T_2N "
    << jsonNumberText(jsonMember(g, "rated_torque")) << ", T_2max " << jsonNumberText(jsonMember(g, "max_torque"))
    << " N·m (n/a: not given)\n";
}

// The duty hour's equivalent torques, or why there is none.
json dutyHourJson(const GearDuty& g) {
  return g.duty_applies ? json{{"applies", true},
                               {"basis", g.duty_basis},
                               {"revolutions_per_hour", jsonNumber(g.hour_revolutions)},
                               {"equivalent_torque_drive", jsonNumber(g.equivalent_torque_drive)},
                               {"equivalent_torque_coast", jsonNumber(g.equivalent_torque_coast)},
                               {"equivalent_torque", jsonNumber(g.equivalent_torque)},
                               {"deciding_flank", g.deciding_flank}}
                        : json{{"applies", false}, {"reason", g.duty_not_applicable}};
}

}  // namespace

json gearDutyJson(const GearDuty& g) {
  if (!g.requested) return nullptr;
  return {{"method", "ISO 6336-6:2019, load spectrum and Miner-equivalent torque"},
          {"torque", "coupling torque (what the reducer's output shaft transmits), at the crank axis"},
          {"exponent", g.exponent},
          {"class_width", jsonNumber(g.class_width)},
          {"nominal_torque", jsonNumber(g.nominal_torque)},
          {"nominal_source", g.nominal_source},
          {"assumed_application_factor", jsonNumber(g.assumed_application_factor)},
          {"rated_torque", jsonNumber(g.rated_torque)},
          {"max_torque", jsonNumber(g.max_torque)},
          {"starts_per_hour", g.starts_per_hour},
          {"start", spectrumJson(g.start)},
          {"steady", spectrumJson(g.steady)},
          {"duty", dutyHourJson(g)},
          {"application_factor", jsonNumber(g.application_factor)},
          {"peak", jsonNumber(g.peak)},
          {"t_peak", jsonNumber(g.t_peak)},
          {"application_ratio", jsonNumber(g.application_ratio)},
          {"rated_ratio", jsonNumber(g.rated_ratio)},
          {"max_ratio", jsonNumber(g.max_ratio)}};
}

json motorDutyJson(const MotorDuty& m) {
  if (!m.requested) return nullptr;
  return {{"method", "IEC 60034-1, duty S1 / S4"},
          {"duty_type", m.duty_type},
          {"designation", m.designation},
          {"starts_per_hour", m.starts_per_hour},
          {"start_known", m.start_known},
          {"start_unknown", m.start_unknown},
          {"start_time", jsonNumber(m.start_time)},
          {"start_heat", jsonNumber(m.start_heat)},
          {"locked_rotor_torque", jsonNumber(m.locked_rotor_torque)},
          {"locked_rotor_losses", jsonNumber(m.locked_rotor_losses)},
          {"equivalent_locked_time", jsonNumber(m.equivalent_locked_time)},
          {"locked_rotor_time", jsonNumber(m.locked_rotor_time)},
          {"rotor_inertia", jsonNumber(m.rotor_inertia)},
          {"load_inertia", jsonNumber(m.load_inertia)},
          {"no_load_start_heat", jsonNumber(m.no_load_start_heat)},
          {"no_load_starts", jsonNumber(m.no_load_starts)},
          {"steady_loss_share", jsonNumber(m.steady_loss_share)},
          {"permissible_starts", jsonNumber(m.permissible_starts)},
          {"starting_time_share", jsonNumber(m.starting_time_share)},
          {"locked_time_ratio", jsonNumber(m.locked_time_ratio)},
          {"starts_ratio", jsonNumber(m.starts_ratio)}};
}

std::string dutyText(const json& sizing) {
  std::ostringstream o;
  const json& g = jsonMember(sizing, "gear");
  if (g.is_object()) gearText(o, g);
  const json& m = jsonMember(sizing, "motor_duty");
  if (m.is_object()) {
    o << "  motor duty (" << jsonText(jsonMember(m, "method")) << "): " << jsonText(jsonMember(m, "designation"))
      << "\n";
    if (jsonFlag(m, "start_known"))
      o << "    one start: t_D " << jsonNumberText(jsonMember(m, "start_time"), "%.3g") << " s, rotor heat Q_start "
        << jsonNumberText(jsonMember(m, "start_heat"), "%.4g")
        << " J = " << jsonNumberText(jsonMember(m, "equivalent_locked_time"), "%.3g")
        << " s at standstill (P_s = M_s·ω0 " << jsonNumberText(jsonMember(m, "locked_rotor_losses")) << " W; t_E "
        << jsonNumberText(jsonMember(m, "locked_rotor_time"), "%.3g") << " s)\n"
        << "    permissible starts Z " << jsonNumberText(jsonMember(m, "permissible_starts"), "%.3g")
        << " per hour (Z_0 " << jsonNumberText(jsonMember(m, "no_load_starts"), "%.3g") << ", ½·J_M·ω0² "
        << jsonNumberText(jsonMember(m, "no_load_start_heat")) << " J, steady rotor losses "
        << jsonNumberText(jsonMember(m, "steady_loss_share"), "%.3g")
        << " of nominal); starting time share N·t_D/3600 s "
        << jsonNumberText(jsonMember(m, "starting_time_share"), "%.3g") << "\n";
    else
      o << "    n/a (" << jsonText(jsonMember(m, "start_unknown")) << ")\n";
  }
  return o.str();
}

}  // namespace rollerdyn
