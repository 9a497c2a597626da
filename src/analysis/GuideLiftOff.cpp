#include "analysis/GuideLiftOff.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rollerdyn {

namespace {

// Share of [t0, t1] during which the piecewise-linear N(t) through the rows is negative, with the
// zero crossings interpolated (the output step is coarse against a short lift-off).
double negativeShare(const std::vector<double>& t, const std::vector<double>& N, double t0, double t1) {
  double neg = 0.0;
  for (std::size_t i = 1; i < t.size(); ++i) {
    const double a = std::max(t[i - 1], t0), b = std::min(t[i], t1);
    if (!(b > a) || !(t[i] > t[i - 1])) continue;
    const double s = t[i] - t[i - 1];
    const double Na = N[i - 1] + (N[i] - N[i - 1]) * (a - t[i - 1]) / s;
    const double Nb = N[i - 1] + (N[i] - N[i - 1]) * (b - t[i - 1]) / s;
    if (Na < 0 && Nb < 0) neg += b - a;
    else if (Na < 0 || Nb < 0) {
      const double tz = a + (b - a) * Na / (Na - Nb);  // the zero
      neg += Na < 0 ? tz - a : b - tz;
    }
  }
  return t1 > t0 ? neg / (t1 - t0) : 0.0;
}

// One guide's reaction N over the steady window: counted as checked when the window holds its
// rows, and entered as lifting when N takes both signs there.
void checkGuide(GuideLiftOff& g, const std::vector<double>& t, const std::vector<double>& N, const SteadyState& ss,
                int cart, const char* side) {
  double lo = INFINITY, hi = -INFINITY;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] >= ss.t_begin && t[i] <= ss.t_end && std::isfinite(N[i])) {
      lo = std::min(lo, N[i]);
      hi = std::max(hi, N[i]);
    }
  if (!std::isfinite(lo)) return;
  ++g.guides_checked;
  const double noise = 1e-6 * std::max(std::abs(lo), std::abs(hi));
  if (!(lo < -noise && hi > noise)) return;  // one side throughout
  const double share_negative = negativeShare(t, N, ss.t_begin, ss.t_end);
  GuideLiftOffEntry e;
  e.cart = cart;
  e.guide = side;
  e.presses_down = share_negative <= 0.5;
  e.time_fraction = e.presses_down ? share_negative : 1.0 - share_negative;
  e.worst_reaction = e.presses_down ? lo : hi;
  e.prevailing_extreme = e.presses_down ? hi : lo;
  g.lifting.push_back(e);
}

// One warning line for the run (a shipped scene's four carts give one line, not four), each
// lifting guide in it with its figures.
std::string liftOffWarning(const GuideLiftOff& g, const SteadyState& ss) {
  std::string list;
  for (const GuideLiftOffEntry& e : g.lifting) {
    char buf[256];
    std::snprintf(buf, sizeof buf, "%scart %d %s: %s (N %s 0, up to %.4g N), %s for %.3g %% of the time (N reaching %.4g N)",
                  list.empty() ? "" : "; ", e.cart, e.guide.c_str(), e.presses_down ? "downward" : "upward",
                  e.presses_down ? ">" : "<", e.prevailing_extreme, e.presses_down ? "upward" : "downward",
                  100.0 * e.time_fraction, e.worst_reaction);
    list += buf;
  }
  char head[160];
  std::snprintf(head, sizeof head, "guide reactions change sign in the steady window (t = %.4g ... %.4g s): ",
                ss.t_begin, ss.t_end);
  return std::string(head) + list +
         "; each of these rollers lifts off its guide while the reaction is on its other side, unless "
         "a counter-roller holds it, which the scene does not model (summary.json guide_lift_off)";
}

// Why the guides are not judged in this run: no guide reactions, or no steady window; "" when they are.
std::string notJudgedReason(const Table& rx, const SteadyState& ss, bool steady) {
  if (rx.columns.empty() || rx.rows.empty() || !rx.has("t") || !rx.has("N_front_1"))
    return "no guide reactions computed in this run (simulation.reactions: false); set simulation.reactions: true";
  if (!steady)
    return ss.not_reached.empty() ? std::string("the crank does not turn steadily in this run, so there is no steady "
                                                "window to judge the guide reactions in")
                                  : ss.not_reached;
  return "";
}

}  // namespace

GuideLiftOff computeGuideLiftOff(const RunResult& run, const SteadyState& ss, bool steady) {
  GuideLiftOff g;
  g.verdict = "not applicable";
  const Table& rx = run.reactions;
  g.reason = notJudgedReason(rx, ss, steady);
  if (!g.reason.empty()) return g;
  g.t_begin = ss.t_begin;
  g.t_end = ss.t_end;
  const std::vector<double> t = rx.column("t");
  for (int j = 1; rx.has("N_front_" + std::to_string(j)); ++j)
    for (const char* side : {"front", "rear"}) {
      const std::string col = std::string("N_") + side + "_" + std::to_string(j);
      if (rx.has(col)) checkGuide(g, t, rx.column(col), ss, j, side);
    }
  if (!g.lifting.empty()) g.warnings.push_back(liftOffWarning(g, ss));
  if (g.guides_checked == 0) {
    g.reason = "the steady window holds no rows of the reactions table";
    return g;
  }
  g.verdict = g.lifting.empty() ? "holds" : "lifts off";
  return g;
}

nlohmann::json guideLiftOffJson(const GuideLiftOff& g) {
  using nlohmann::json;
  json guides = json::array();
  for (const GuideLiftOffEntry& e : g.lifting)
    guides.push_back({{"cart", e.cart},
                      {"guide", e.guide},
                      {"prevailing", e.presses_down ? "downward" : "upward"},
                      {"time_fraction", e.time_fraction},
                      {"worst_reaction", e.worst_reaction},
                      {"prevailing_extreme", e.prevailing_extreme}});
  const bool judged = g.verdict != "not applicable";
  return {{"verdict", g.verdict},
          {"reason", g.reason.empty() ? json(nullptr) : json(g.reason)},
          {"t_begin", judged ? json(g.t_begin) : json(nullptr)},
          {"t_end", judged ? json(g.t_end) : json(nullptr)},
          {"guides_checked", g.guides_checked},
          {"lifting", guides}};
}

}  // namespace rollerdyn
