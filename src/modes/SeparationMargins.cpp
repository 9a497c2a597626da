#include "modes/SeparationMargins.h"
#include "io/FieldFormat.h"

#include <algorithm>
#include <cstdio>

namespace rollerdyn::modes {
namespace {

// Distance of f from the interval [lo, hi] (0 inside it).
double distanceToBand(double f, double lo, double hi) {
  if (f < lo) return lo - f;
  if (f > hi) return f - hi;
  return 0.0;
}

// The coupling mode's frequency band and damping: the Floquet multipliers' ω_n where they
// resolve the torsional mode, else the frozen-angle band with its smallest ζ.
struct CouplingModeBand {
  double p_lo, p_hi, zeta;
  bool floquet;
};

CouplingModeBand couplingModeBand(const SteadyMotion& steady, const Band& frozen_natural, const Band& frozen_damping) {
  const FloquetVerdict& v = steady.verdict;
  const bool floquet = v.has_torsional && v.torsional_resolved && std::isfinite(v.torsional_frequency);
  double p_lo = frozen_natural.min, p_hi = frozen_natural.max, zeta = frozen_damping.min;
  if (floquet) {
    zeta = v.torsional_damping_ratio;
    p_lo = p_hi = v.torsionalNaturalFrequency();
  }
  return {p_lo, p_hi, zeta, floquet};
}

// The orders that drive the coupling get a verdict; the layout's other orders up to 1.2 times the
// mode's frequency are shown with their margin and why they have none (their harmonic is small).
std::vector<int> shownOrders(const ExcitationOrders& orders, double omega, double p_hi) {
  std::vector<int> shown = orders.forced;
  for (int k : orders.layout)
    if (k * omega <= 1.2 * p_hi && std::find(shown.begin(), shown.end(), k) == shown.end()) shown.push_back(k);
  std::sort(shown.begin(), shown.end());
  return shown;
}

// The verdict on order k's margin: n/a for an order too weak to drive the mode, else pass or FAIL
// against the required margin.
void judgeCouplingMargin(SeparationMargin& m, bool drives, double required, double exciting_largest) {
  if (!drives) {
    m.verdict = "n/a";
    m.reason = printfText("order %d's harmonic is %.2g %% of the largest (< 1 %%): it does not drive the coupling mode",
                   m.order, 100 * m.exciting_torque / exciting_largest);
  } else if (m.margin >= required) {
    m.verdict = "pass";
    m.reason = printfText("k*omega = %.4g rad/s is %.3g %% away from the mode (>= 10 %%)", m.excitation, 100 * m.margin);
  } else {
    m.verdict = "FAIL";
    m.reason = printfText("k*omega = %.4g rad/s is only %.3g %% away from the mode (< 10 %%); accept it only where the "
                   "run's coupling torque over the steady window (its peak, swing and fatigue) is within the "
                   "coupling's ratings (a forced-response analysis, API 617), amplification factor 1/(2*zeta) = %.3g",
                   m.excitation, 100 * m.margin, m.amplification);
  }
}

// Order k's row against the coupling mode at the operating speed omega.
SeparationMargin couplingMargin(int k, double omega, const CouplingModeBand& band, const Band& frozen_undamped,
                                const ExcitationOrders& orders) {
  SeparationMargin m;
  m.order = k;
  m.excitation = k * omega;
  m.exciting_torque = (k >= 1 && k <= int(orders.table.size())) ? orders.table[size_t(k - 1)].exciting_torque : NAN;
  m.p_low = band.p_lo;
  m.p_high = band.p_hi;
  m.undamped_low = frozen_undamped.min;
  m.undamped_high = frozen_undamped.max;
  m.frequency_source = band.floquet ? "Floquet multipliers" : "frozen-angle band";
  m.margin = distanceToBand(m.excitation, band.p_lo, band.p_hi) / m.excitation;
  m.damping_ratio = band.zeta;
  m.amplification = band.zeta > 0 ? 0.5 / band.zeta : INFINITY;
  return m;
}

bool drivesTheCoupling(const ExcitationOrders& orders, int k) {
  return std::find(orders.forced.begin(), orders.forced.end(), k) != orders.forced.end();
}

// The forced crossings of the Campbell diagram below the operating speed (passed at start-up).
std::vector<StartCrossing> startCrossings(const CampbellDiagram& campbell, const ExcitationOrders& orders,
                                          double omega) {
  std::vector<StartCrossing> crossings;
  if (campbell.applicable)
    for (const CampbellCrossing& c : campbell.crossings)
      if (!c.parametric && c.omega < omega && drivesTheCoupling(orders, c.order))
        crossings.push_back({c.order, c.omega});
  return crossings;
}

// Why the margins do not apply (no torsional mode, no steady motion), empty when they do.
std::string notApplicable(bool elastic, const SteadyMotion& steady) {
  if (!elastic)
    return "rigid coupling (coupling.type: rigid): the drive has no torsional mode to keep away from the orders";
  if (!steady.found)
    return "no steady motion of the drive (" + steady.failure + "): no operating speed to take the excitation orders at";
  return "";
}

}  // namespace

SeparationMargins separationMargins(bool elastic, const SteadyMotion& steady, const Band& frozen_natural,
                                    const Band& frozen_undamped, const Band& frozen_damping,
                                    const ExcitationOrders& orders,
                                    const CampbellDiagram& campbell) {
  SeparationMargins s;
  s.not_applicable = notApplicable(elastic, steady);
  if (!s.not_applicable.empty()) return s;
  const CouplingModeBand band = couplingModeBand(steady, frozen_natural, frozen_damping);
  if (!(std::isfinite(band.p_lo) && std::isfinite(band.p_hi))) {
    s.not_applicable = "the coupling mode has no natural frequency along the steady motion (frozen-angle modes failed)";
    return s;
  }
  s.applicable = true;
  s.omega = steady.omega_mean;
  for (int k : shownOrders(orders, s.omega, band.p_hi)) {
    SeparationMargin m = couplingMargin(k, s.omega, band, frozen_undamped, orders);
    judgeCouplingMargin(m, drivesTheCoupling(orders, k), s.required, orders.exciting_largest);
    s.rows.push_back(m);
  }
  s.start_crossings = startCrossings(campbell, orders, s.omega);
  return s;
}

namespace {

// The order that drives a throw (share at least kForcedOrderShare) nearest the band, 0 when none.
int governingOrder(const ChainModeBand& band, const std::vector<double>& throw_shares, double w) {
  int governing = 0;
  double governing_margin = INFINITY;
  for (size_t i = 0; i < throw_shares.size(); ++i) {
    const double k = double(i + 1), sm = distanceToBand(k * w, band.p_min, band.p_max) / (k * w);
    if (throw_shares[i] >= kForcedOrderShare && sm < governing_margin) {
      governing_margin = sm;
      governing = int(i + 1);
    }
  }
  return governing;
}

// The orders too weak to drive the mode that lie within 10 % of its band: counted,
// not listed (a wide band, where a throw's inertia nearly vanishes at its dead centres, holds dozens).
int weakOrdersNear(const ChainModeBand& band, const std::vector<double>& throw_shares, double w, double required) {
  int weak_near = 0;
  for (size_t i = 0; i < throw_shares.size(); ++i) {
    const double k = double(i + 1);
    if (throw_shares[i] < kForcedOrderShare && distanceToBand(k * w, band.p_min, band.p_max) / (k * w) < required)
      ++weak_near;
  }
  return weak_near;
}

// Order k's row against a crankshaft mode's band (verdict and reason set by judgeChainMargin).
SeparationMargin chainMargin(const std::string& name, int k, double w, const ChainModeBand& band) {
  SeparationMargin r;
  r.mode = name;
  r.order = k;
  r.excitation = k * w;
  r.p_low = r.undamped_low = band.p_min;
  r.p_high = r.undamped_high = band.p_max;
  r.frequency_source = "crankshaft chain's frozen-angle band, undamped";
  r.margin = distanceToBand(r.excitation, band.p_min, band.p_max) / r.excitation;
  return r;
}

void judgeChainMargin(SeparationMargin& r, double required, int weak_near) {
  const std::string weak =
      weak_near ? printfText("; %d weaker orders (below 1 %% of a throw's largest harmonic) lie within 10 %% of the "
                      "band, too weak to drive it", weak_near)
                : std::string();
  if (r.margin >= required) {
    r.verdict = "pass";
    r.reason = printfText("k*omega = %.4g rad/s is %.3g %% away from the crankshaft mode's band (>= 10 %%); the nearest "
                   "order that drives a throw", r.excitation, 100 * r.margin) + weak;
  } else {
    r.verdict = "FAIL";
    r.reason = printfText("k*omega = %.4g rad/s is only %.3g %% away from the crankshaft mode's band (< 10 %%): the "
                   "throws' torques drive the shaft's twist near resonance; move the mode (crankshaft."
                   "torsional_stiffness, the throws' spacing) or damp it (crankshaft.torsional_damping) and "
                   "read the run's shaft_torque_k columns",
                   r.excitation, 100 * r.margin);
  }
}

// A crankshaft mode's rows: the governing order (the nearest that drives a throw) and every
// driving order within the required margin.
void addChainModeRows(SeparationMargins& s, const std::string& name, const ChainModeBand& band,
                      const std::vector<double>& throw_shares) {
  const double w = s.omega;
  const int governing = governingOrder(band, throw_shares, w);
  const int weak_near = weakOrdersNear(band, throw_shares, w, s.required);
  for (size_t i = 0; i < throw_shares.size(); ++i) {
    const int k = int(i + 1);
    SeparationMargin r = chainMargin(name, k, w, band);
    const bool drives = throw_shares[i] >= kForcedOrderShare;
    if (!drives || !(k == governing || r.margin < s.required)) continue;
    judgeChainMargin(r, s.required, weak_near);
    s.rows.push_back(r);
  }
}

}  // namespace

void addChainSeparation(SeparationMargins& s, const CrankshaftChainModes& chain, bool elastic,
                        const SteadyMotion& steady, const std::vector<double>& throw_shares) {
  if (!chain.applies || !steady.found || throw_shares.empty()) return;
  if (!s.applicable) {
    if (elastic) return;  // the coupling mode's margins failed for a reason that holds for the chain too
    s.applicable = true;  // a rigid coupling: the chain's modes are the drive's torsional modes
    s.not_applicable.clear();
    s.omega = steady.omega_mean;
  }
  for (size_t m = elastic ? 1 : 0; m < chain.modes.size(); ++m) {
    const ChainModeBand& band = chain.modes[m];
    addChainModeRows(s, "crankshaft mode " + std::to_string(m + 1) + " (twists most: " + band.shape + ")", band,
                     throw_shares);
  }
}

}  // namespace rollerdyn::modes
