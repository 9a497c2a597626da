// The separation margins (SeparationMargins.h) as checks of a sign-off: the verdicts are the
// margins' own, made in separationMargins(); here they get their limit, method and basis.
#include <cmath>
#include <cstdio>
#include <string>

#include "modes/SeparationMargins.h"
#include "io/FieldFormat.h"

namespace rollerdyn::modes {

namespace {

constexpr const char* kMethod =
    "API 617 / API 684 practice: every torsional natural frequency at least 10 % away from every excitation "
    "frequency at the operating speed";

std::string g4(double v) { return significant(v, 4); }

SizingCheck base(const std::string& name, const std::string& what) {
  SizingCheck c;
  c.name = name;
  c.what = what;
  c.value = NAN;
  c.limit = kRequiredSeparationMargin;
  c.passes_when = ">=";
  c.method = kMethod;
  return c;
}

// An order too weak to drive the mode is a check only where it lies within the margin (the
// reviewer accepts it, said why); further away it is no excitation to keep away from.
bool countsAsCheck(const SeparationMargin& m, double required) {
  return m.verdict != "n/a" || (std::isfinite(m.margin) && m.margin < required);
}

// The one check when no order is a check: the margins do not apply, or nothing drives the mode.
SizingCheck notApplicableCheck(const SeparationMargins& s) {
  SizingCheck c = base("separation_margin", "separation margin of the coupling's torsional mode from the excitation "
                                            "orders, SM = |p − k·ω|/(k·ω), ≥ 10 %");
  c.verdict = "not applicable";
  c.window = "steady motion at the operating crank speed";
  c.reason = s.applicable ? "no crank order drives the coupling mode (every order's harmonic of the load and inertia "
                            "torque near it is below 1 % of the largest)"
                          : s.not_applicable;
  c.basis = "the modal analysis of the scene (coupling.*, the drive's inertias) at the run's steady motion";
  return c;
}

// separation_margin_order_k for the coupling mode, separation_margin_<mode>_order_k otherwise
// (spaces as underscores).
std::string checkName(const SeparationMargin& m, bool coupling) {
  std::string name = "separation_margin_order_" + std::to_string(m.order);
  if (!coupling) name = "separation_margin_" + m.mode.substr(0, m.mode.find(" (")) + "_order_" + std::to_string(m.order);
  for (char& ch : name)
    if (ch == ' ') ch = '_';
  return name;
}

// Where the mode's frequency comes from and which orders drive it.
std::string checkBasis(const SeparationMargin& m, bool coupling) {
  const std::string p = m.p_low == m.p_high ? g4(m.p_low) + " rad/s" : g4(m.p_low) + " ... " + g4(m.p_high) + " rad/s";
  if (coupling)
    return "natural frequency p = " + p + " of the coupling mode's damped pair, from the " + m.frequency_source +
           " (ζ = " + g4(m.damping_ratio) + ", amplification factor 1/(2ζ) = " + g4(m.amplification) +
           "); orders whose harmonic of the load and inertia torque is at least 1 % of the largest drive the "
           "mode; ω the mean crank speed of the steady motion";
  return "natural frequency p = " + p + " of the " + m.mode + ", the " + m.frequency_source +
         " (crankshaft.torsional_stiffness, the throws' inertias and their carts' reduced inertias); orders "
         "whose harmonic in one throw's load and inertia torque is at least 1 % of its largest drive it; ω "
         "the mean crank speed of the steady motion";
}

SizingCheck orderCheck(const SeparationMargins& s, const SeparationMargin& m) {
  const bool coupling = m.mode == "coupling mode";
  const std::string mode = coupling ? "the coupling's torsional mode" : m.mode;
  SizingCheck c = base(checkName(m, coupling), "separation margin of " + mode + " from crank order " +
                                                   std::to_string(m.order) + ", SM = |p − k·ω|/(k·ω), ≥ 10 %");
  c.window = "steady motion at ω = " + g4(s.omega) + " rad/s";
  c.verdict = m.verdict == "n/a" ? "not applicable" : m.verdict;
  c.value = c.verdict == "not applicable" ? NAN : m.margin;
  c.reason = m.reason;
  c.basis = checkBasis(m, coupling);
  return c;
}

}  // namespace

std::vector<SizingCheck> separationChecks(const SeparationMargins& s) {
  std::vector<SizingCheck> out;
  bool any = false;
  for (const SeparationMargin& m : s.rows) any = any || countsAsCheck(m, s.required);
  if (!s.applicable || !any) return {notApplicableCheck(s)};
  for (const SeparationMargin& m : s.rows)
    if (countsAsCheck(m, s.required)) out.push_back(orderCheck(s, m));
  return out;
}

}  // namespace rollerdyn::modes
