// The checks of the fatigue damage (Fatigue.h) and of the coupling selection after DIN 740-2
// (CouplingSelection.h), each computed once here from the figures of one DriveSizing; the console,
// summary.json, the report and Python only render them. A check appears only where its input is
// given (an S-N curve or a requirement; a coupling rating), and says "not applicable" with the
// reason and what to do where its window is missing.
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "analysis/CheckVerdicts.h"
#include "analysis/SizingChecks.h"

namespace rollerdyn {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
using check_words::g4;
using check_words::kNotApplicable;
using check_words::notApplicable;
using check_words::verdictOf;

std::string lifeWords(double v, const char* unit) { return std::isinf(v) ? std::string("no damage") : g4(v) + unit; }

constexpr const char* kDin740 = "DIN 740-2 coupling selection (as KTR, Flender and Mayr publish it)";

void fatigueMethod(SizingCheck& c, const FatigueSizing& f, const SignalFatigue& g) {
  c.limit = 1.0;
  c.passes_when = "<=";
  c.method = "rainflow counting after ASTM E1049-85, Palmgren-Miner linear damage sum";
  c.basis = "S-N curve " + g.key + "; below the knee: " + f.below_knee + "; mean correction: " + f.mean_correction;
}

// The ratings of the coupling selection: limit 1 on the ratio, DIN 740-2, the factors named.
SizingCheck din740(SizingCheck c, const std::string& rating_key) {
  c.limit = 1.0;
  c.passes_when = "<=";
  c.method = kDin740;
  c.basis = "rating " + rating_key + " at the crank axis; factors S_t, S_z, S_A from sizing.coupling.*; torques of "
            "the run in place of the method's estimates";
  return c;
}

SizingCheck startCheck(const FatigueSizing& f, const SignalFatigue& g) {
  SizingCheck c{"fatigue_starts_" + g.signal,
                "fatigue of the " + g.what + " per start: required starts × Miner's damage of one start, ≤ 1",
                kNaN, "", "start from rest", ""};
  fatigueMethod(c, f, g);
  if (!g.start.applies) {
    notApplicable(c, g.start.not_applicable);
    return c;
  }
  c.reason = "damage per start " + g4(g.damage_per_start) + ", so " + lifeWords(g.starts_to_failure, " starts") +
             " to failure (" + g.start.where + ", t = " + g4(g.start.t_begin) + " ... " + g4(g.start.t_end) + " s)";
  if (!std::isfinite(f.required_starts)) {
    c.reason += "; no requirement to compare with (sizing.fatigue.required_starts)";
    return c;
  }
  c.value = f.required_starts * g.damage_per_start;
  c.verdict = verdictOf(c.value);
  c.reason += " against " + g4(f.required_starts) + " required";
  return c;
}

SizingCheck hoursCheck(const FatigueSizing& f, const SignalFatigue& g) {
  SizingCheck c{"fatigue_hours_" + g.signal,
                "fatigue of the " + g.what + " in steady running: required hours × Miner's damage per hour, ≤ 1",
                kNaN, "", kWindowSteady, ""};
  fatigueMethod(c, f, g);
  if (!g.steady.applies) {
    notApplicable(c, g.steady.not_applicable);
    return c;
  }
  c.reason = "damage per hour " + g4(g.damage_per_hour) + ", so " + lifeWords(g.hours_to_failure, " h") +
             " to failure (" + g.steady.where + ", steady window scaled by 3600 s/" +
             g4(g.steady.t_end - g.steady.t_begin) + " s)";
  if (!std::isfinite(f.required_hours)) {
    c.reason += "; no requirement to compare with (sizing.fatigue.required_hours)";
    return c;
  }
  c.value = f.required_hours * g.damage_per_hour;
  c.verdict = verdictOf(c.value);
  c.reason += " against " + g4(f.required_hours) + " h required";
  return c;
}

// A coupling check that needs the steady window (and, for a pass, whatever `more` names).
SizingCheck couplingSteadyCheck(const DriveSizing& s, bool turning, std::string name, std::string what, double value,
                                std::string reason) {
  SizingCheck c{std::move(name), std::move(what), value, verdictOf(value), kWindowSteady, std::move(reason)};
  if (!turning) notApplicable(c, "the drive does not turn (" + s.motion + "): the coupling's load in running is not known");
  else if (!s.steady_reached) notApplicable(c, s.steady_not_reached);
  return c;
}

std::string serviceFactorWords(const CouplingSelection& c) { return "S_t = " + g4(c.S_t); }

SizingCheck couplingRatedCheck(const DriveSizing& s, bool turning) {
  const CouplingSelection& c = s.coupling_selection;
  return din740(couplingSteadyCheck(s, turning, "coupling_rated_torque",
                                    "steady peak torque × S_t / T_KN (DIN 740-2), ≤ 1", c.rated_ratio,
                                    "T_N = " + g4(c.steady_peak) + " N·m (steady window peak), " +
                                        serviceFactorWords(c) + ", T_KN = " + g4(c.rated_torque) + " N·m"),
                "sizing.coupling.rated_torque (T_KN)");
}

SizingCheck couplingMaxCheck(const DriveSizing& s, bool turning) {
  const CouplingSelection& c = s.coupling_selection;
  SizingCheck k{"coupling_max_torque", "largest peak torque × S_A·S_z·S_t / T_Kmax (DIN 740-2), ≤ 1", c.max_ratio,
                verdictOf(c.max_ratio), kWindowWhole,
                "T_S = max(start " + g4(c.start_peak) + ", steady " + g4(c.steady_peak) + ") N·m, S_A = " +
                    g4(c.S_A) + ", S_z = " + g4(c.S_z) + ", " + serviceFactorWords(c) + ", T_Kmax = " +
                    g4(c.max_torque) + " N·m"};
  k = din740(k, "sizing.coupling.max_torque (T_Kmax)");
  // A peak above the rating happened whatever the run lacks; a pass needs the start and the running.
  if (k.verdict == "FAIL") return k;
  if (!turning) notApplicable(k, "the drive does not turn (" + s.motion + ")");
  else if (!c.start_in_run)
    notApplicable(k, "the run holds no start from rest, whose peak usually decides T_Kmax: run it from rest "
                     "(initial.crank_speed: 0)");
  else if (!s.steady_reached) notApplicable(k, s.steady_not_reached);
  return k;
}

SizingCheck couplingVibratoryCheck(const DriveSizing& s, bool turning) {
  const CouplingSelection& c = s.coupling_selection;
  SizingCheck k = couplingSteadyCheck(
      s, turning, "coupling_vibratory_torque", "vibratory torque amplitude × S_t·S_f / T_KW (DIN 740-2), ≤ 1",
      c.vibratory_ratio,
      "T_W = " + g4(c.steady_amplitude) + " N·m, crank order " + std::to_string(c.excitation_order) + " at f = " +
          g4(c.excitation_frequency) + " Hz, S_f = " + g4(c.S_f) + ", " + serviceFactorWords(c) + ", T_KW = " +
          g4(c.vibratory_torque) + " N·m");
  k = din740(k, "sizing.coupling.vibratory_torque (T_KW)");
  if (k.verdict != kNotApplicable && c.excitation_order == 0)
    notApplicable(k, "the excitation frequency is not known (the steady window holds no whole crank revolution): "
                     "run longer (simulation.t_end)");
  return k;
}

SizingCheck couplingDampingCheck(const DriveSizing& s, bool turning) {
  const CouplingSelection& c = s.coupling_selection;
  SizingCheck k = couplingSteadyCheck(s, turning, "coupling_damping_power",
                                      "damping power × S_t / P_KW (DIN 740-2), ≤ 1", c.damping_ratio,
                                      "P_W = " + g4(c.damping_power_run) + " W (" + c.damping_basis + "), " +
                                          serviceFactorWords(c) + ", P_KW = " + g4(c.damping_power) + " W");
  k = din740(k, "sizing.coupling.damping_power (P_KW)");
  if (k.verdict != kNotApplicable && !std::isfinite(c.damping_power_run)) notApplicable(k, c.damping_basis);
  return k;
}

// The checks of the ratings given (sizing.coupling.*), in this order.
void couplingChecks(const DriveSizing& s, bool turning, std::vector<SizingCheck>& out) {
  const CouplingSelection& c = s.coupling_selection;
  if (std::isfinite(c.rated_torque)) out.push_back(couplingRatedCheck(s, turning));
  if (std::isfinite(c.max_torque)) out.push_back(couplingMaxCheck(s, turning));
  if (std::isfinite(c.vibratory_torque)) out.push_back(couplingVibratoryCheck(s, turning));
  if (std::isfinite(c.damping_power)) out.push_back(couplingDampingCheck(s, turning));
}

}  // namespace

void appendSignOffChecks(const DriveSizing& s, bool turning, std::vector<SizingCheck>& out) {
  for (const SignalFatigue& g : s.fatigue.signals) {
    out.push_back(startCheck(s.fatigue, g));
    out.push_back(hoursCheck(s.fatigue, g));
  }
  if (s.coupling_selection.requested) couplingChecks(s, turning, out);
  appendDutyChecks(s, turning, out);
}

}  // namespace rollerdyn
