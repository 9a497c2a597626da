#include "modes/SeparationMargins.h"

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

std::string fmt(const char* format, double a, double b = 0, double c = 0) {
  char buf[600];  // the longest, a FAIL's advice, is about 400 characters
  std::snprintf(buf, sizeof buf, format, a, b, c);
  return buf;
}

}  // namespace

SeparationMargins separationMargins(bool elastic, const SteadyMotion& steady, const Band& frozen_natural,
                                    const Band& frozen_undamped, const Band& frozen_damping,
                                    const ExcitationOrders& orders,
                                    const CampbellDiagram& campbell) {
  SeparationMargins s;
  if (!elastic) {
    s.not_applicable = "rigid coupling (coupling.type: rigid): the drive has no torsional mode to keep away from the orders";
    return s;
  }
  if (!steady.found) {
    s.not_applicable = "no steady motion of the drive (" + steady.failure +
                       "): no operating speed to take the excitation orders at";
    return s;
  }
  const FloquetVerdict& v = steady.verdict;
  const bool floquet = v.has_torsional && v.torsional_resolved && std::isfinite(v.torsional_frequency);
  double p_lo = frozen_natural.min, p_hi = frozen_natural.max, zeta = frozen_damping.min;
  if (floquet) {
    zeta = v.torsional_damping_ratio;
    p_lo = p_hi = v.torsional_frequency / std::sqrt(std::max(1e-12, 1 - zeta * zeta));
  }
  if (!(std::isfinite(p_lo) && std::isfinite(p_hi))) {
    s.not_applicable = "the coupling mode has no natural frequency along the steady motion (frozen-angle modes failed)";
    return s;
  }
  s.applicable = true;
  s.omega = steady.omega_mean;
  // The orders that drive the coupling get a verdict; the layout's other orders up to 1.2 times the
  // mode's frequency are shown with their margin and why they have none (their harmonic is small).
  std::vector<int> shown = orders.forced;
  for (int k : orders.layout)
    if (k * s.omega <= 1.2 * p_hi && std::find(shown.begin(), shown.end(), k) == shown.end()) shown.push_back(k);
  std::sort(shown.begin(), shown.end());
  for (int k : shown) {
    const bool drives = std::find(orders.forced.begin(), orders.forced.end(), k) != orders.forced.end();
    SeparationMargin m;
    m.order = k;
    m.excitation = k * s.omega;
    m.exciting_torque = (k >= 1 && k <= int(orders.table.size())) ? orders.table[size_t(k - 1)].exciting_torque : NAN;
    m.p_low = p_lo;
    m.p_high = p_hi;
    m.undamped_low = frozen_undamped.min;
    m.undamped_high = frozen_undamped.max;
    m.frequency_source = floquet ? "Floquet multipliers" : "frozen-angle band";
    m.margin = distanceToBand(m.excitation, p_lo, p_hi) / m.excitation;
    m.damping_ratio = zeta;
    m.amplification = zeta > 0 ? 0.5 / zeta : INFINITY;
    if (!drives) {
      m.verdict = "n/a";
      m.reason = fmt("order %.0f's harmonic is %.2g %% of the largest (< 1 %%): it does not drive the coupling mode",
                     k, 100 * m.exciting_torque / orders.exciting_largest);
    } else if (m.margin >= s.required) {
      m.verdict = "pass";
      m.reason = fmt("k*omega = %.4g rad/s is %.3g %% away from the mode (>= 10 %%)", m.excitation, 100 * m.margin);
    } else {
      m.verdict = "FAIL";
      m.reason = fmt("k*omega = %.4g rad/s is only %.3g %% away from the mode (< 10 %%); accept it only where the "
                     "run's coupling torque over the steady window (its peak, swing and fatigue) is within the "
                     "coupling's ratings (a forced-response analysis, API 617), amplification factor 1/(2*zeta) = %.3g",
                     m.excitation, 100 * m.margin, m.amplification);
    }
    s.rows.push_back(m);
  }
  if (campbell.applicable)
    for (const CampbellCrossing& c : campbell.crossings)
      if (!c.parametric && c.omega < s.omega &&
          std::find(orders.forced.begin(), orders.forced.end(), c.order) != orders.forced.end())
        s.start_crossings.push_back({c.order, c.omega});
  return s;
}

}  // namespace rollerdyn::modes
