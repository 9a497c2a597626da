// The shared measures of the papers' findings (PaperFindings.cpp, PaperFindingsLoveikin2018.cpp):
// a finding as a claim or a measurement, gaps to the published tables and their ranges, the
// sensitivity rows, the gap put first as one verdict. Not a public header.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "compare/ValidationSuite.h"
#include "io/FieldFormat.h"

namespace rollerdyn::validation::findings_detail {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
using V = Finding::Verdict;

inline std::string g(double v, int prec = 3) { return significantOr(v, prec, "n/a"); }
inline std::string pctText(double v) { return std::isfinite(v) ? g(100.0 * v, std::abs(v) >= 1 ? 3 : 2) + " %" : "n/a"; }
inline Finding measurement(std::string text) { return {V::Measurement, std::move(text)}; }
inline Finding claim(bool holds, std::string text) { return {holds ? V::Holds : V::Fails, std::move(text)}; }

// Widens [lo, hi] (NaN: empty) to hold v.
inline void widen(double& lo, double& hi, double v) {
  lo = std::isfinite(lo) ? std::min(lo, v) : v;
  hi = std::isfinite(hi) ? std::max(hi, v) : v;
}

inline double published(const SweepPoint& p, const std::string& col) {
  const auto it = p.published.find(col);
  return (p.has_published && it != p.published.end()) ? it->second : kNaN;
}

// Largest |other/ours - 1| of a metric (other: the variant or the multibody run) over the points
// where both rotate; NaN when there is no such point.
inline double maxRelative(const std::vector<SweepPoint>& pts, double RunMetrics::*f, bool multibody) {
  double m = kNaN;
  for (const auto& s : pts) {
    const RunMetrics& other = multibody ? s.multibody : s.variant;
    if ((multibody ? s.has_multibody : s.has_variant) && s.reduced.rotating && other.rotating) {
      const double d = std::abs(other.*f / (s.reduced.*f) - 1.0);
      m = std::isfinite(m) ? std::max(m, d) : d;
    }
  }
  return m;
}

// Relative gap (ours - published)/published of a metric at one point; NaN where the crank does
// not rotate or nothing is published.
inline double gap(const SweepPoint& s, double RunMetrics::*f, const std::string& col) {
  const double pub = published(s, col);
  return s.reduced.rotating && std::isfinite(pub) && pub != 0 ? s.reduced.*f / pub - 1.0 : kNaN;
}

// x of the smallest value of a metric (ours: reduced, rotating points; or the published column).
inline double argminOurs(const std::vector<SweepPoint>& pts, double RunMetrics::*f, double k = 0) {
  double best = kNaN, x = kNaN;
  for (const auto& s : pts)
    if (s.k == k && s.reduced.rotating && !(s.reduced.*f >= best)) {
      best = s.reduced.*f;
      x = s.x;
    }
  return x;
}
inline double argminPublished(const std::vector<SweepPoint>& pts, const std::string& col, double k = 0) {
  double best = kNaN, x = kNaN;
  for (const auto& s : pts)
    if (s.k == k && std::isfinite(published(s, col)) && !(published(s, col) >= best)) {
      best = published(s, col);
      x = s.x;
    }
  return x;
}
inline const SweepPoint* at(const std::vector<SweepPoint>& pts, double x, double k = 0) {
  for (const auto& s : pts)
    if (std::abs(s.x - x) < 1e-9 && std::abs(s.k - k) < 1e-9) return &s;
  return nullptr;
}

// Largest |changed/baseline - 1| over the sensitivity rows of one paper whose metric is `metric`.
inline double largestSensitivity(const std::vector<SensitivityRow>& rows, const std::string& paper,
                          const std::string& metric, std::string* which) {
  double m = kNaN;
  for (const auto& r : rows)
    if (r.paper == paper && r.metric == metric && std::isfinite(r.changed) && r.baseline != 0) {
      const double d = std::abs(r.changed / r.baseline - 1.0);
      if (!(d <= m)) {
        m = d;
        if (which) *which = r.change;
      }
    }
  return m;
}
inline const SensitivityRow* sensitivityRow(const std::vector<SensitivityRow>& rows, const std::string& paper,
                                     const std::string& change_prefix) {
  for (const auto& r : rows)
    if (r.paper == paper && r.change.rfind(change_prefix, 0) == 0) return &r;
  return nullptr;
}

// The multibody finding shared by the two rigid-drive papers.
inline void multibodyFinding(std::vector<Finding>& c, const PaperSweep& p, double gap_scale, const std::string& where) {
  const double mb = maxRelative(p.points, &RunMetrics::delta, true);
  if (!std::isfinite(mb)) return;
  c.push_back(claim(mb < 0.1 * std::abs(gap_scale),
                    "Multibody model: δ within " + pctText(mb) + " of the reduced model at every multibody point "
                    "(distributed rods, no guide friction: identical physics), less than a tenth of the gap " +
                        where + " (" + pctText(gap_scale) + "): the gap lies between our inputs and the paper's, "
                        "not between our two models."));
}

// Range of the relative gap of a metric over the points where ours rotates and a value is
// published: [lo, hi] and the point of the largest |gap|.
struct GapRange {
  double lo = kNaN, hi = kNaN, x_worst = kNaN, k_worst = 0;
  int points = 0;
};
inline GapRange gapRange(const std::vector<SweepPoint>& pts, double RunMetrics::*f, const std::string& col) {
  GapRange r;
  for (const auto& s : pts) {
    const double gp = gap(s, f, col);
    if (!std::isfinite(gp)) continue;
    ++r.points;
    if (!(std::abs(gp) <= std::max(std::abs(r.lo), std::abs(r.hi)))) r.x_worst = s.x, r.k_worst = s.k;
    widen(r.lo, r.hi, gp);
  }
  return r;
}

// The table's gap as one verdict, put first: its numbers, and the reason it is there. Explained
// when the causes' claims (the findings after it) were all computed and all hold; a reason whose
// own checks fail is no explanation, and the verdict is then FAILED.
inline void putGapFirst(std::vector<Finding>& c, const std::string& numbers, const std::string& reason) {
  int claims = 0;
  bool all_hold = true;
  for (const auto& f : c) {
    if (f.verdict == V::Measurement) continue;
    ++claims;
    all_hold = all_hold && f.verdict == V::Holds;
  }
  const bool explained = claims > 0 && all_hold;
  c.insert(c.begin(), Finding{explained ? V::GapExplained : V::Fails,
                              "Gap: " + numbers + (explained ? " Why: " : " Not explained (a claim below FAILED): ") + reason});
}


}  // namespace rollerdyn::validation::findings_detail
