// The checks of the gear application factor after ISO 6336-6 (GearDuty.h) and of the motor's
// starts after IEC 60034-1 (MotorDuty.h), each computed once here from the figures of one
// DriveSizing; the console, summary.json, the report and Python only render them. They appear where
// their section is asked for (a sizing.reducer.* or sizing.motor.* rating), and say "not applicable"
// with the reason and the key to set where an input or a window is missing.
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "analysis/SizingChecks.h"

namespace rollerdyn {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
const char* kNotApplicable = "not applicable";

std::string g4(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

std::string verdictOf(double ratio) {
  if (!std::isfinite(ratio)) return "";
  return ratio <= 1.0 ? "pass" : "FAIL";
}

void notApplicable(SizingCheck& c, const std::string& why) {
  c.verdict = kNotApplicable;
  c.reason = why;
  c.value = kNaN;
}

// Why the duty hour's equivalent torque decides nothing, or "".
std::string dutyMissing(const DriveSizing& s, bool turning) {
  const GearDuty& g = s.gear;
  if (!turning) return "the drive does not turn (" + s.motion + "): the reducer's load spectrum in running is not known";
  if (!g.duty_applies) return g.duty_not_applicable;
  return "";
}

std::string spectrumWords(const GearDuty& g) {
  return "T_eq = " + g4(g.equivalent_torque) + " N·m on the " + g.deciding_flank + " (drive flank " +
         g4(g.equivalent_torque_drive) + ", other flank " + g4(g.equivalent_torque_coast) + " N·m; p = " +
         g4(g.exponent) + ", " + g4(g.hour_revolutions) + " crank revolutions per hour); " + g.duty_basis;
}

SizingCheck applicationFactorCheck(const DriveSizing& s, bool turning) {
  const GearDuty& g = s.gear;
  SizingCheck c{"gear_application_factor",
                "gear application factor after ISO 6336-6: K_A = T_eq/T_n of the run's load spectrum over the K_A the "
                "gears were designed with, ≤ 1",
                g.application_ratio, verdictOf(g.application_ratio), kWindowSteady, ""};
  if (g.starts_per_hour > 0) c.window = kWindowDuty;
  if (!std::isfinite(g.assumed_application_factor)) {
    notApplicable(c, "the K_A the gears were designed with is not given: set sizing.reducer.application_factor (e.g. "
                     "1.75 for an electric motor driving heavy shocks, ISO 6336-1 Table B.1)");
    return c;
  }
  if (!std::isfinite(g.nominal_torque)) {
    notApplicable(c, "T_n = u·η·M_n is not known: M_n " + g.nominal_source);
    return c;
  }
  const std::string missing = dutyMissing(s, turning);
  if (!missing.empty()) {
    notApplicable(c, missing);
    return c;
  }
  c.reason = "K_A = " + g4(g.application_factor) + " against " + g4(g.assumed_application_factor) + " assumed; T_n = " +
             g4(g.nominal_torque) + " N·m (u·η·M_n, M_n from " + g.nominal_source + "); " + spectrumWords(g);
  return c;
}

SizingCheck ratedTorqueCheck(const DriveSizing& s, bool turning) {
  const GearDuty& g = s.gear;
  SizingCheck c{"gear_rated_torque",
                "equivalent torque of the reducer's load spectrum (ISO 6336-6) / its rated output torque T_2N, ≤ 1",
                g.rated_ratio, verdictOf(g.rated_ratio), g.starts_per_hour > 0 ? kWindowDuty : kWindowSteady, ""};
  if (!std::isfinite(g.rated_torque)) {
    notApplicable(c, "the reducer's rated output torque is not given: set sizing.reducer.rated_torque (T_2N at "
                     "service factor 1, reduced to the crank axis)");
    return c;
  }
  const std::string missing = dutyMissing(s, turning);
  if (!missing.empty()) {
    notApplicable(c, missing);
    return c;
  }
  c.reason = spectrumWords(g) + "; T_2N = " + g4(g.rated_torque) +
             " N·m taken as the constant torque the reducer carries for the same life";
  return c;
}

SizingCheck maxTorqueCheck(const DriveSizing& s, bool turning) {
  const GearDuty& g = s.gear;
  SizingCheck c{"gear_max_torque", "largest |T| at the reducer's output / its permissible peak torque T_2max, ≤ 1",
                g.max_ratio, verdictOf(g.max_ratio), kWindowWhole, ""};
  if (!std::isfinite(g.max_torque)) {
    notApplicable(c, "the reducer's permissible peak torque is not given: set sizing.reducer.max_torque (T_2max, "
                     "reduced to the crank axis)");
    return c;
  }
  c.reason = "peak " + g4(g.peak) + " N·m at t = " + g4(g.t_peak) + " s (start and steady window), T_2max = " +
             g4(g.max_torque) + " N·m";
  // A peak above the rating happened whatever the run lacks; a pass needs the start and the running.
  if (c.verdict == "FAIL") return c;
  if (!turning) notApplicable(c, "the drive does not turn (" + s.motion + ")");
  else if (!g.start.applies) notApplicable(c, g.start.not_applicable + "; a start's peak usually decides T_2max");
  else if (!s.steady_reached) notApplicable(c, s.steady_not_reached);
  return c;
}

}  // namespace

void appendDutyChecks(const DriveSizing& s, bool turning, std::vector<SizingCheck>& out) {
  if (s.gear.requested) {
    out.push_back(applicationFactorCheck(s, turning));
    out.push_back(ratedTorqueCheck(s, turning));
    out.push_back(maxTorqueCheck(s, turning));
  }
}

}  // namespace rollerdyn
