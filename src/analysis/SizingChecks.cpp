#include "analysis/SizingChecks.h"
#include "io/FieldFormat.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

namespace rollerdyn {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
const char* kNotApplicable = "not applicable";

std::string verdictOf(double ratio, bool strict) {
  if (!std::isfinite(ratio)) return "";
  return (strict ? ratio < 1.0 : ratio <= 1.0) ? "pass" : "FAIL";
}

std::string fmt3(double v) { return significant(v, 3); }

// A check that does not apply shows no figure beside its verdict (a 2.6 read as an overload even
// next to "not applicable"): the figure, where there is one, moves into the reason.
void notApplicable(SizingCheck& c, const std::string& why) {
  c.verdict = kNotApplicable;
  c.reason = why;
  if (std::isfinite(c.value)) c.reason += " (the figure over this run, " + fmt3(c.value) + ", decides nothing)";
  c.value = kNaN;
}

// What every check of a drive still starting when the run ended says.
const std::string kTooShort = kStillStartingWords;

std::string notTurning(const DriveSizing& s) {
  return "the drive does not turn (" + (s.motion.empty() ? std::string("not turning") : s.motion) + ")";
}

// The duty's starts per hour cannot be judged: why, or "" when they can.
std::string dutyNotJudged(const DriveSizing& s) {
  const double n = s.motor.whole_run.duty_starts_per_hour;
  if (!(n > 0)) return "";
  const std::string duty = fmt3(n) + " starts per hour (sizing.starts_per_hour)";
  if (s.can_start_from_rest == 0)
    return "the drive cannot start from rest (" + s.stall_cause + "), so the duty's " + duty +
           " cannot happen: see the start check";
  if (!s.start_simulated)
    return "the duty's " + duty + " need the start's rotor heat, and this run holds no start from rest (it begins "
           "turning, initial.crank_speed): run it from rest (initial.crank_speed: 0)";
  return "";
}

// The run from rest decides: it ran up (pass), or it did not (FAIL), or it is still starting.
void judgeSimulatedStart(SizingCheck& c, const DriveSizing& s) {
  if (s.motion == "starting") {
    notApplicable(c, kTooShort);
    return;
  }
  c.verdict = motionIsTurning(s.motion) ? "pass" : "FAIL";
  c.reason = s.start_verdict;
  if (std::isfinite(c.value)) c.reason += "; torque ratio at standstill " + fmt3(c.value);
}

// A run that begins turning: the torques at standstill alone decide (static start criterion).
void judgeStaticStart(SizingCheck& c, const DriveSizing& s) {
  c.window = "torques at standstill (the run begins turning)";
  if (s.can_start_from_rest < 0) {
    notApplicable(c, "the run holds no start from rest and the load torques at the start were not evaluated");
  } else if (s.can_start_from_rest == 0) {
    c.verdict = "FAIL";
    c.reason = s.stall_cause + "; this run begins turning (initial.crank_speed), so it does not show it";
  } else {
    c.verdict = "pass";
    c.reason = "from the torques at standstill only: the run begins turning, so the start itself (the load peaks "
               "near a dead centre with the inertia) is not simulated; run it from rest (initial.crank_speed: 0) "
               "to decide";
  }
}

SizingCheck startCheck(const DriveSizing& s) {
  SizingCheck c{"start",
                "the motor starts the machine from rest (the run from rest runs up; without one: load at the start "
                "angle / starting torque and mean load / largest torque under the starting method's supply, < 1)",
                s.start_load_ratio, "", "start from rest", ""};
  c.limit = 1.0;
  c.passes_when = "<";
  c.method = "run-up simulated from rest; without one, the load torque at standstill against the motor's torque "
             "under the starting method's supply (static start criterion)";
  c.basis = "the motor's torque-speed law (motor.*) and starting method (motor.start.*), the loads at the start angle "
            "(loads.*); a run from rest (initial.crank_speed: 0) decides with the inertia, the static criterion "
            "without it";
  if (s.start_simulated)
    judgeSimulatedStart(c, s);
  else
    judgeStaticStart(c, s);
  // A verdict never shows a figure that says the opposite: the run decides where the torques alone
  // would not (a start held back by the inertia), and the ratio moves into the reason.
  if ((c.verdict == "FAIL" && !(c.value >= 1.0)) || (c.verdict == "pass" && !(c.value < 1.0))) c.value = kNaN;
  return c;
}

// The figure that decides: the steady window's RMS rule or the whole run's thermal equivalent,
// whichever is larger; in continuous running the steady window, by the larger of the two.
void judgeHeating(SizingCheck& h, const MotorSizing& m) {
  const double steady = m.rms_over_nominal, whole = m.whole_run.thermal_over_nominal;
  const bool whole_decides = !(whole <= steady);  // NaN steady: the whole run decides
  h.value = whole_decides ? whole : steady;
  h.window = whole_decides ? (m.whole_run.duty_starts_per_hour > 0 ? kWindowDuty : kWindowWhole) : kWindowSteady;
  h.reason = whole_decides ? m.whole_run.thermal_basis + " (" + fmt3(whole) + "; steady window RMS/M_n " + fmt3(steady) + ")"
                           : "RMS torque / M_n over the steady window (" + fmt3(steady) + "; whole run thermal equivalent " +
                                 fmt3(whole) + ")";
  h.verdict = verdictOf(h.value, false);
  if (!m.whole_run.continuous_running) return;
  // Continuous running: the steady window decides, by the larger of the RMS rule and the steady losses.
  h.value = std::isfinite(whole) ? std::max(steady, whole) : steady;
  h.window = kWindowSteady;
  h.reason = "RMS torque / M_n over the steady window (" + fmt3(steady) + "); " + m.whole_run.thermal_basis;
  h.verdict = verdictOf(h.value, false);
  if (m.whole_run.starts_per_hour < 1.0) {  // NaN compares false: no verdict from an unknown start
    h.verdict = "FAIL";
    h.reason = "the motor cannot take even one start per hour at this load: " + h.reason;
  }
}

// Where the run overrules the figure: still starting, not turning, or missing what the check needs.
void overruleHeating(SizingCheck& h, const DriveSizing& s, bool turning) {
  const MotorSizing& m = s.motor;
  const std::string duty = dutyNotJudged(s);
  if (s.motion == "starting") {
    notApplicable(h, kTooShort);
  } else if (!turning) {
    // The figure of a rotor held at standstill is no margin: it moves into the reason.
    h.verdict = "FAIL";
    h.reason = notTurning(s) + ": a motor that cannot drive its load overheats whatever the torque; RMS torque / M_n "
               "over the run's last part " + fmt3(m.rms_over_nominal) + ", the thermal equivalent √(rotor losses / nominal rotor losses) " +
               fmt3(m.whole_run.thermal_over_nominal);
    if (!(h.value > 1.0)) h.value = kNaN;
  } else if (!std::isfinite(m.nominal_torque)) {
    notApplicable(h, "the nominal torque M_n is not known: give sizing.motor_nominal_torque, or "
                     "sizing.motor_nominal_power with motor.omega_nominal, or motor.omega_nominal with "
                     "motor.overload_ratio (the Kloss data)");
  } else if (!s.steady_reached) {
    notApplicable(h, s.steady_not_reached + " (the heating check needs the steady running's losses)");
  } else if (!duty.empty()) {
    notApplicable(h, duty);
  }
}

SizingCheck heatingCheck(const DriveSizing& s, bool turning) {
  const MotorSizing& m = s.motor;
  SizingCheck h{"motor_heating", "thermal equivalent torque / nominal torque M_n, ≤ 1", kNaN, "", "", ""};
  h.limit = 1.0;
  h.passes_when = "<=";
  h.method = "IEC 60034-1 duty S1 (continuous) or S4 (starts per hour): equivalent thermal torque by the RMS rule, "
             "rotor losses s·M·ω0 against the nominal s_n·M_n·ω0";
  h.basis = "M_n from " + (m.nominal_source.empty() ? std::string("the motor data") : m.nominal_source) +
            "; stator and iron losses taken to scale like the rotor's; duty from sizing.starts_per_hour (none: "
            "continuous running); a start's heat from the simulated start-up";
  judgeHeating(h, m);
  overruleHeating(h, s, turning);
  return h;
}

// The steady window's motoring and braking peaks against M_kr, in words.
std::string breakdownPeaksReason(const MotorSizing& m) {
  std::string reason = "steady window: motoring peak " + fmt3(m.torque_motoring_peak) + " N·m, braking (generating) peak " +
                       fmt3(m.torque_generating_peak) + " N·m, the larger against M_kr " + fmt3(m.breakdown_torque) + " N·m";
  if (m.torque_generating_peak > m.torque_motoring_peak)
    reason += " (the load drives the motor as a generator there; the catalogue gives no generating breakdown "
              "torque, so the motoring one is used, on the safe side" +
              (m.breakdown_torque_generating != m.breakdown_torque
                   ? "; the fitted law's own, an extrapolation, is " + fmt3(m.breakdown_torque_generating) + " N·m)"
                   : std::string(")"));
  return reason + "; whole run peak |M| " + fmt3(m.whole_run.torque_shaft_peak) + " N·m";
}

// Where the run overrules the margin: still starting, not turning, or no steady running.
void overruleBreakdown(SizingCheck& k, const DriveSizing& s, bool turning) {
  if (s.motion == "starting") {
    notApplicable(k, kTooShort);
  } else if (!turning) {
    k.verdict = "FAIL";
    k.reason = notTurning(s) + ": " +
               (s.stall_cause.empty() ? std::string("the load needs more than the motor gives") : s.stall_cause) +
               " (the measured peak |M| / M_kr " + fmt3(s.motor.peak_over_breakdown) +
               " is that of a drive that does not run, not a margin)";
    if (!(k.value >= kBreakdownMargin)) k.value = kNaN;
  } else if (!s.steady_reached) {
    notApplicable(k, s.steady_not_reached + " (a start passes M_kr by design; the margin is the steady running's)");
  }
}

SizingCheck breakdownCheck(const DriveSizing& s, bool turning) {
  const MotorSizing& m = s.motor;
  // The breakdown torque falls with the square of the voltage, and IEC 60034-1 (zone A) lets the
  // supply sit 5 % low: a steady peak above 0.95²·M_kr stalls the motor on a supply within its tolerance.
  SizingCheck k{"motor_breakdown",
                "peak |M| / breakdown torque M_kr over the steady window, < 0.9025 (M_kr at 95 % supply voltage, "
                "IEC 60034-1 zone A; a start passes M_kr by design)",
                m.peak_over_breakdown, verdictOf(m.peak_over_breakdown / kBreakdownMargin, true), kWindowSteady, ""};
  k.limit = kBreakdownMargin;
  k.passes_when = "<";
  k.method = "IEC 60034-1 zone A: supply voltage down to 95 %, breakdown torque M_kr falling with the voltage squared";
  k.basis = "M_kr of the motor's law (motor.*); the motoring M_kr also against braking peaks (the catalogue gives "
            "no generating one)";
  k.reason = breakdownPeaksReason(m);
  overruleBreakdown(k, s, turning);
  return k;
}

// A pass where the run lacks part of the working cycle (no turning, still starting, no steady
// running, no start from rest) is no verdict.
void overruleCouplingPass(SizingCheck& k, const DriveSizing& s, bool turning) {
  if (!turning)
    notApplicable(k, notTurning(s) + ": the coupling torque of a working drive is not known; " + k.reason);
  else if (s.motion == "starting")
    notApplicable(k, kTooShort + "; " + k.reason);
  else if (!s.steady_reached)
    notApplicable(k, s.steady_not_reached + "; " + k.reason);
  else if (!s.start_simulated)
    notApplicable(k, "the run holds no start from rest (it begins turning, initial.crank_speed), and a start's peak "
                     "usually decides a coupling: run it from rest (initial.crank_speed: 0); " + k.reason);
}

SizingCheck couplingCheck(const DriveSizing& s, bool turning) {
  const CouplingSizing& c = s.coupling;
  SizingCheck k{"coupling", "peak |M| / rated torque of the coupling, ≤ 1", kNaN, "", "", ""};
  k.limit = 1.0;
  k.passes_when = "<=";
  k.method = "largest simulated coupling torque against one rated torque";
  k.basis = "rating sizing.coupling_rated_torque at the crank axis; torque from the run's coupling model "
            "(coupling.*), start-up peaks included";
  const bool whole_decides = !(c.peak_whole_run <= c.peak);
  k.value = whole_decides ? c.peak_over_rating_whole_run : c.peak_over_rating;
  k.window = whole_decides ? kWindowWhole : kWindowSteady;
  char buf[200];
  std::snprintf(buf, sizeof buf, "peak %.4g N·m at t = %.4g s (whole run); steady window peak %.4g N·m",
                c.peak_whole_run, c.t_peak_whole_run, c.peak);
  k.reason = buf;
  if (!std::isfinite(c.rating)) k.reason += "; rating not given (sizing.coupling_rated_torque)";
  k.verdict = verdictOf(k.value, false);
  // A peak above the rating happened, whatever else the run lacks; a pass needs the whole working
  // cycle: the start (whose peak usually decides a coupling) and the steady running.
  if (k.verdict == "pass") overruleCouplingPass(k, s, turning);
  return k;
}

}  // namespace

std::vector<SizingCheck> sizingChecks(const DriveSizing& s, bool turning) {
  std::vector<SizingCheck> out;
  if (s.motor.available && (s.start_simulated || s.can_start_from_rest >= 0)) out.push_back(startCheck(s));
  if (s.motor.available) {
    out.push_back(heatingCheck(s, turning));
    out.push_back(breakdownCheck(s, turning));
  }
  if (s.coupling.available) out.push_back(couplingCheck(s, turning));
  appendSignOffChecks(s, turning, out);
  return out;
}

}  // namespace rollerdyn
