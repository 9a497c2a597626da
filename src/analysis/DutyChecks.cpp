// The checks of the gear application factor after ISO 6336-6 (GearDuty.h) and of the motor's
// starts after IEC 60034-1 (MotorDuty.h), each computed once here from the figures of one
// DriveSizing; the console, summary.json, the report and Python only render them. They appear where
// their section is asked for (a sizing.reducer.* or sizing.motor.* rating), and say "not applicable"
// with the reason and the key to set where an input or a window is missing.
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "analysis/CheckVerdicts.h"
#include "analysis/SizingChecks.h"

namespace rollerdyn {

namespace {

using check_words::g4;
using check_words::kNotApplicable;
using check_words::notApplicable;
using check_words::verdictOf;

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

SizingCheck lockedRotorCheck(const DriveSizing& s) {
  const MotorDuty& m = s.motor_duty;
  SizingCheck c{"motor_locked_rotor_time",
                "rotor heat of one start as time at standstill, Q_start/(M_s·ω0), over the motor's permissible "
                "locked-rotor time t_E (IEC 60034-1), ≤ 1",
                m.locked_time_ratio, verdictOf(m.locked_time_ratio), "start from rest", ""};
  if (!std::isfinite(m.locked_rotor_time)) {
    notApplicable(c, "the permissible locked-rotor time is not given: set sizing.motor.locked_rotor_time (t_E from "
                     "the motor's catalogue, warm)");
    return c;
  }
  if (!m.start_known) {
    notApplicable(c, m.start_unknown);
    return c;
  }
  if (!std::isfinite(m.equivalent_locked_time)) {
    notApplicable(c, "the motor law gives no torque at standstill under the rated supply, so P_s = M_s·ω0 is not known");
    return c;
  }
  c.reason = "Q_start = " + g4(m.start_heat) + " J in t_D = " + g4(m.start_time) + " s, like " +
             g4(m.equivalent_locked_time) + " s at standstill (P_s = " + g4(m.locked_rotor_losses) + " W), t_E = " +
             g4(m.locked_rotor_time) + " s";
  return c;
}

// Why the starts per hour cannot be judged: duty S1, Z_0 not given, no start, no steady running,
// or the nominal rotor losses not known; "" when they can.
std::string startsNotJudged(const DriveSizing& s) {
  const MotorDuty& m = s.motor_duty;
  if (!(m.starts_per_hour > 0)) return "duty S1: no starts per hour given; set sizing.starts_per_hour for duty S4";
  if (!std::isfinite(m.no_load_starts))
    return "the permissible starts without load are not given: set sizing.motor.no_load_starts (Z_0 from "
           "the motor's catalogue)";
  if (!m.start_known) return m.start_unknown;
  if (!s.steady_reached) return s.steady_not_reached + " (the steady running's rotor losses share the budget)";
  if (!std::isfinite(m.steady_loss_share))
    return "the nominal rotor losses s_n·M_n·ω0 are not known: give motor.omega_nominal and the nominal torque "
           "(sizing.motor_nominal_torque)";
  return "";
}

SizingCheck startsCheck(const DriveSizing& s) {
  const MotorDuty& m = s.motor_duty;
  SizingCheck c{"motor_starts_per_hour",
                "starts per hour N of duty S4 over the permissible Z = Z_0·(½·J_M·ω0²/Q_start)·(1 − P_steady/P_n,rotor) "
                "(IEC 60034-1, catalogue Z_0), ≤ 1",
                m.starts_ratio, verdictOf(m.starts_ratio), kWindowDuty, ""};
  const std::string why = startsNotJudged(s);
  if (!why.empty()) {
    notApplicable(c, why);
    return c;
  }
  c.reason = g4(m.starts_per_hour) + " starts per hour against Z = " + g4(m.permissible_starts) + " (Z_0 = " +
             g4(m.no_load_starts) + ", ½·J_M·ω0² = " + g4(m.no_load_start_heat) + " J, Q_start = " + g4(m.start_heat) +
             " J, steady rotor losses " + g4(m.steady_loss_share) + " of the nominal)";
  return c;
}

SizingCheck startingShareCheck(const DriveSizing& s) {
  const MotorDuty& m = s.motor_duty;
  SizingCheck c{"motor_starting_time",
                "starting time share of the hour N·t_D/3600 s of duty S4 (IEC 60034-1), < 1",
                m.starting_time_share, "", kWindowDuty, ""};
  c.verdict = std::isfinite(c.value) ? (c.value < 1.0 ? "pass" : "FAIL") : "";
  if (!(m.starts_per_hour > 0)) {
    notApplicable(c, "duty S1: no starts per hour given; set sizing.starts_per_hour for duty S4");
    return c;
  }
  if (!m.start_known) {
    notApplicable(c, m.start_unknown);
    return c;
  }
  c.reason = g4(m.starts_per_hour) + " starts of t_D = " + g4(m.start_time) +
             " s each; the rest of the hour the motor runs (energized between starts, ED = 100 %)";
  return c;
}

}  // namespace

namespace {

// The limit, method and inputs of a check, which the sign-off sheet shows beside its verdict.
SizingCheck rated(SizingCheck c, const char* method, const std::string& basis, const char* passes_when = "<=") {
  c.limit = 1.0;
  c.passes_when = passes_when;
  c.method = method;
  c.basis = basis;
  return c;
}

const char* kSpectrumBasis = "; the coupling torque at the crank axis as the reducer's output torque, in 40 torque "
                             "classes counted at their upper limits, one load cycle per crank revolution, each flank "
                             "its own spectrum";

}  // namespace

void appendDutyChecks(const DriveSizing& s, bool turning, std::vector<SizingCheck>& out) {
  if (s.gear.requested) {
    out.push_back(rated(applicationFactorCheck(s, turning),
                        "ISO 6336-6 load spectrum, Miner's rule with the gear's S-N exponent p; K_A = T_eq/T_n",
                        "sizing.reducer.application_factor, sizing.reducer.sn_exponent, M_n" + std::string(kSpectrumBasis)));
    out.push_back(rated(ratedTorqueCheck(s, turning), "ISO 6336-6 equivalent torque against the rated output torque",
                        "sizing.reducer.rated_torque, sizing.reducer.sn_exponent" + std::string(kSpectrumBasis)));
    out.push_back(rated(maxTorqueCheck(s, turning), "peak torque against the maker's permissible peak torque",
                        "sizing.reducer.max_torque; the start and the steady window of the run"));
  }
  if (s.motor_duty.requested) {
    out.push_back(rated(lockedRotorCheck(s), "IEC 60034-1 duty S4: rotor heat of one start as locked-rotor time",
                        "sizing.motor.locked_rotor_time; the start's rotor energy loss from the run"));
    out.push_back(rated(startsCheck(s), "IEC 60034-1 duty S4: permissible starts per hour from the catalogue's Z_0",
                        "sizing.starts_per_hour, sizing.motor.no_load_starts; the start's rotor energy loss from the run"));
    out.push_back(rated(startingShareCheck(s), "IEC 60034-1 duty S4: share of the hour spent starting",
                        "sizing.starts_per_hour; no rest between starts (ED = 100 %)", "<"));
  }
}

}  // namespace rollerdyn
