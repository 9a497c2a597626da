// The comparison of the two models' runs on one scene (ModelComparison.h): the common time grid,
// every quantity row by row, the steady-state answers and the shapes over a revolution; how it is
// written (comparison.json, the console text) is in ComparisonOutputs.cpp.
#include "compare/ModelComparison.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "analysis/Metrics.h"
#include "analysis/SteadyState.h"
#include "analysis/Summary.h"
#include "multibody/MultibodySimulation.h"
#include "reduced/ReducedModel.h"
#include "io/FieldFormat.h"

namespace rollerdyn {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool isReactionQuantity(const std::string& name) {
  return name.rfind("N_front_", 0) == 0 || name.rfind("N_rear_", 0) == 0 ||
         name.rfind("F_rod_", 0) == 0;
}

// Column `name` of the run's timeseries, or of its reactions table, with that table's times.
void columnWithTime(const RunResult& run, const std::string& name, std::vector<double>& t,
                    std::vector<double>& y) {
  const Table& tab = run.timeseries.has(name) ? run.timeseries : run.reactions;
  if (!tab.has(name) || !tab.has("t"))
    throw std::runtime_error("compare: the " + run.model + " run has no column '" + name + "'");
  t = tab.column("t");
  y = tab.column(name);
}


// `name` of the run's timeseries over its steady window folded onto one crank revolution: at 72
// crank angles 5° apart, interpolated linearly between the rows whose angles bracket them and
// averaged over the window's revolutions (NaN where the crank never passed an angle). Interpolating
// in φ, not averaging rows in bins, makes the result independent of where each run's rows fall.
std::vector<double> foldOnRevolution(const RunResult& run, const SteadyState& w, const std::string& name) {
  constexpr int kAngles = 72;
  std::vector<double> sum(kAngles, 0.0), count(kAngles, 0.0);
  const Table& ts = run.timeseries;
  if (!ts.has(name) || !ts.has("phi_crank")) return std::vector<double>(kAngles, kNaN);
  const int ip = ts.index("phi_crank"), iy = ts.index(name);
  const double step = 2.0 * M_PI / kAngles;
  for (std::size_t i = w.row_begin; i + 1 < w.row_end && i + 1 < ts.rows.size(); ++i) {
    const double a0 = ts.rows[i][ip], a1 = ts.rows[i + 1][ip];
    if (!(a1 != a0) || !std::isfinite(a0) || !std::isfinite(a1)) continue;
    const double lo = std::min(a0, a1), hi = std::max(a0, a1);
    // grid angles k·step (all turns) in (lo, hi]
    for (long g = long(std::floor(lo / step)) + 1; g * step <= hi; ++g) {
      const double f = (g * step - a0) / (a1 - a0);
      const double y = ts.rows[i][iy] + f * (ts.rows[i + 1][iy] - ts.rows[i][iy]);
      const int k = int(((g % kAngles) + kAngles) % kAngles);
      sum[k] += y;
      count[k] += 1;
    }
  }
  for (int k = 0; k < kAngles; ++k) sum[k] = count[k] > 0 ? sum[k] / count[k] : kNaN;
  return sum;
}


// The steady-state answers compared, each by its path in the run's summary (analysis/Summary.h).
struct SteadyItem {
  const char* name;
  const char* unit;
  const char* path;  // in the run's summary, dotted
};
const SteadyItem kSteadyItems[] = {
    {"omega_crank_mean", "rad/s", "omega_crank.mean"},
    {"delta", "-", "delta"},
    {"coupling_torque_swing", "N·m", "coupling_torque_swing"},
    {"coupling_torque_mean", "N·m", "sizing.coupling.mean"},
    {"coupling_torque_peak", "N·m", "sizing.coupling.peak"},
    {"motor_torque_rotor_rms", "N·m", "sizing.motor.torque_shaft.rms"},
    {"motor_torque_mean", "N·m", "sizing.motor.torque_shaft.mean"},
};

// The steady-state answers of both models, each from its own summary.
void compareSteadyMetrics(const Scene& scene, ModelComparison& c) {
  const nlohmann::json jm = makeSummary(scene, c.multibody), jr = makeSummary(scene, c.reduced);
  for (const SteadyItem& it : kSteadyItems) {
    SteadyMetricComparison m;
    m.name = it.name;
    m.unit = it.unit;
    m.multibody = jsonDouble(jsonAt(jm, it.path));
    m.reduced = jsonDouble(jsonAt(jr, it.path));
    m.rel_diff = (m.reduced - m.multibody) / std::abs(m.multibody);
    c.steady.push_back(m);
  }
  c.speed_difference = jsonDouble(jsonAt(jr, "omega_crank.mean")) - jsonDouble(jsonAt(jm, "omega_crank.mean"));
}

// One quantity's shape over a revolution: both steady windows folded onto the crank angle, the
// largest difference against the multibody swing.
ShapeComparison compareShape(const ModelComparison& c, const SteadyState& sm, const SteadyState& sr, const char* name) {
  const std::vector<double> a = foldOnRevolution(c.multibody, sm, name), b = foldOnRevolution(c.reduced, sr, name);
  ShapeComparison sh;
  sh.name = name;
  double lo = INFINITY, hi = -INFINITY;
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (!std::isfinite(a[k]) || !std::isfinite(b[k])) continue;
    sh.max_abs_diff = std::max(sh.max_abs_diff, std::abs(a[k] - b[k]));
    lo = std::min(lo, a[k]);
    hi = std::max(hi, a[k]);
  }
  sh.rel_diff = hi > lo ? sh.max_abs_diff / (hi - lo) : kNaN;
  return sh;
}

void compareSteady(const Scene& scene, ModelComparison& c) {
  const double wr = scene.simulation.steady_window_revolutions;
  const SteadyState sm = detectSteadyState(c.multibody, wr);
  const SteadyState sr = detectSteadyState(c.reduced, wr);
  compareSteadyMetrics(scene, c);
  for (const char* name : {"omega_crank", "coupling_torque"}) c.shapes.push_back(compareShape(c, sm, sr, name));
}

// RMS of the difference from ∫d² dt over the span; a single sample's |d| when the span is empty.
double rmsOverSpan(double integral, double span, double first_abs_diff) {
  return span > 0 ? std::sqrt(integral / span) : first_abs_diff;
}

// max|a - b| / max|a|; 0 for two zero signals, NaN when only the reference is zero.
double relativeToReference(double max_abs_diff, double max_abs_a) {
  if (max_abs_a > 0) return max_abs_diff / max_abs_a;
  return max_abs_diff == 0 ? 0.0 : kNaN;
}

// Statistics without a value: no samples, or a non-finite one.
DifferenceStats undefinedStats(DifferenceStats s) {
  s.max_abs_diff = s.rms_diff = s.max_rel_diff = s.max_abs_a = s.t_at_max = kNaN;
  return s;
}

}  // namespace

DifferenceStats differenceStats(const std::vector<double>& t, const std::vector<double>& a,
                                const std::vector<double>& b) {
  DifferenceStats s;
  const std::size_t n = std::min({t.size(), a.size(), b.size()});
  s.samples = n;
  if (n == 0) return undefinedStats(s);
  double integral = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double d = a[i] - b[i];
    if (!std::isfinite(d) || !std::isfinite(t[i])) return undefinedStats(s);
    if (i == 0 || std::abs(d) > s.max_abs_diff) {
      s.max_abs_diff = std::abs(d);
      s.t_at_max = t[i];
    }
    s.max_abs_a = std::max(s.max_abs_a, std::abs(a[i]));
    if (i > 0) {
      const double d0 = a[i - 1] - b[i - 1];
      integral += 0.5 * (d0 * d0 + d * d) * (t[i] - t[i - 1]);
    }
  }
  s.rms_diff = rmsOverSpan(integral, t[n - 1] - t[0], std::abs(a[0] - b[0]));
  s.max_rel_diff = relativeToReference(s.max_abs_diff, s.max_abs_a);
  return s;
}

std::vector<double> resampleLinear(const std::vector<double>& ts, const std::vector<double>& ys,
                                   const std::vector<double>& td) {
  std::vector<double> out(td.size(), kNaN);
  if (ts.empty() || ys.size() != ts.size()) return out;
  for (std::size_t i = 0; i < td.size(); ++i) {
    const double tq = td[i];
    if (!(tq >= ts.front() && tq <= ts.back())) continue;
    // First source time >= tq.
    const auto it = std::lower_bound(ts.begin(), ts.end(), tq);
    const std::size_t hi = std::size_t(it - ts.begin());
    if (ts[hi] == tq || hi == 0) {
      out[i] = ys[hi];
      continue;
    }
    const std::size_t lo = hi - 1;
    const double frac = (tq - ts[lo]) / (ts[hi] - ts[lo]);
    out[i] = ys[lo] + frac * (ys[hi] - ys[lo]);
  }
  return out;
}

const QuantityComparison* ModelComparison::find(const std::string& name) const {
  for (const auto& q : quantities)
    if (q.name == name) return &q;
  return nullptr;
}

const QuantityComparison* ModelComparison::findKinetostatic(const std::string& name) const {
  for (const auto& q : kinetostatic)
    if (q.name == name) return &q;
  return nullptr;
}

std::vector<std::string> comparedQuantities(int carts, bool reactions) {
  std::vector<std::string> q = {"omega_crank", "coupling_torque"};
  for (int j = 1; reactions && j <= carts; ++j)
    for (const char* n : {"N_front_", "N_rear_", "F_rod_"}) q.push_back(n + std::to_string(j));
  return q;
}

namespace {

// The grid both runs are compared on: the multibody rows within the span both runs reached. Sets
// its span, its size and how far its times lie from the reduced model's nearest row.
std::vector<double> comparisonGrid(const std::vector<double>& t_mb_all, const std::vector<double>& t_red,
                                   double t_common, ModelComparison& c) {
  std::vector<double> grid;
  for (double t : t_mb_all)
    if (t >= t_red.front() && t <= t_common + 1e-12) grid.push_back(t);
  if (grid.empty()) throw std::runtime_error("compare: the two runs share no time span");
  c.t_begin = grid.front();
  c.t_end = grid.back();
  c.rows = grid.size();
  for (double t : grid) {
    const auto it = std::lower_bound(t_red.begin(), t_red.end(), t);
    double off = std::numeric_limits<double>::infinity();
    if (it != t_red.end()) off = std::min(off, std::abs(*it - t));
    if (it != t_red.begin()) off = std::min(off, std::abs(*(it - 1) - t));
    c.grid_max_time_offset = std::max(c.grid_max_time_offset, off);
  }
  return grid;
}

// Kinetostatic reactions of the reduced model on its own rows: φ, φ̇, φ̈ from its timeseries.
// Three columns per cart (front and rear guide normals, rod force); none without reactions.
std::vector<std::vector<double>> reducedKinetostaticReactions(const Scene& scene, const RunResult& red,
                                                              const std::vector<double>& t_red) {
  const int n = scene.carts.count;
  const bool reactions = scene.simulation.reactions;
  std::vector<std::vector<double>> kin(reactions ? 3 * n : 0, std::vector<double>(t_red.size(), kNaN));
  if (reactions) {
    const ReducedModel model(scene);
    const std::vector<double> phi = red.timeseries.column("phi_crank");
    const std::vector<double> w = red.timeseries.column("omega_crank");
    const std::vector<double> e = red.timeseries.column("eps_crank");
    for (std::size_t i = 0; i < t_red.size(); ++i) {
      const std::vector<CartEvaluation> carts = model.cartReactions(phi[i], w[i], e[i], true);
      for (int j = 0; j < n; ++j) {
        kin[3 * j][i] = carts[j].statics.N_front;
        kin[3 * j + 1][i] = carts[j].statics.N_rear;
        kin[3 * j + 2][i] = carts[j].statics.F_rod;
      }
    }
  }
  return kin;
}

// A quantity of a run on the comparison grid.
std::vector<double> onGrid(const RunResult& run, const std::string& name, const std::vector<double>& grid) {
  std::vector<double> t, y;
  columnWithTime(run, name, t, y);
  return resampleLinear(t, y, grid);
}

// comparison.csv being filled: a name and a vector on the grid per column.
struct ComparisonColumns {
  Table& table;
  std::vector<std::vector<double>> cols;

  void add(const std::string& name, std::vector<double> values) {
    table.columns.push_back(name);
    cols.push_back(std::move(values));
  }
  void fillRows(std::size_t rows) {
    table.rows.assign(rows, std::vector<double>(cols.size()));
    for (std::size_t i = 0; i < rows; ++i)
      for (std::size_t k = 0; k < cols.size(); ++k) table.rows[i][k] = cols[k][i];
  }
};

// Every compared quantity on the grid: its statistics, its columns of both models, and for a
// reaction also the reduced model's kinetostatic reaction.
void compareQuantities(const Scene& scene, const RunResult& mb, const RunResult& red, const std::vector<double>& grid,
                       ModelComparison& c) {
  const std::vector<double> t_red = red.timeseries.column("t");
  const std::vector<std::vector<double>> kin = reducedKinetostaticReactions(scene, red, t_red);
  ComparisonColumns cols{c.table, {}};
  cols.add("t", grid);
  const std::vector<std::string> names = comparedQuantities(scene.carts.count, scene.simulation.reactions);
  for (std::size_t k = 0; k < names.size(); ++k) {
    const std::string& q = names[k];
    const std::vector<double> a = onGrid(mb, q, grid), b = onGrid(red, q, grid);
    c.quantities.push_back({q, differenceStats(grid, a, b)});
    cols.add(q + "_multibody", a);
    cols.add(q + "_reduced", b);
    if (isReactionQuantity(q)) {
      const std::size_t kin_index = k - 2;  // names: omega, torque, then 3 per cart
      const std::vector<double> bk = resampleLinear(t_red, kin[kin_index], grid);
      c.kinetostatic.push_back({q, differenceStats(grid, a, bk)});
      cols.add(q + "_reduced_kinetostatic", bk);
    }
  }
  cols.fillRows(grid.size());
}

// What the two models are asked to model alike, from the scene alone.
void describeModels(const Scene& scene, ModelComparison& c) {
  c.scene_name = scene.name;
  c.differences = modelDifferences(scene);
  c.identical = identicalPhysics(scene);
  c.motion_equivalent = motionEquivalent(scene);
  c.reduced_kinetostatic = scene.reduced.guide_normals == ReducedGuideNormals::Kinetostatic;
}

// Crank angle multibody minus reduced at the end of the compared span.
double phaseDrift(const ModelComparison& c, const std::vector<double>& t_mb_all, const std::vector<double>& t_red) {
  const std::vector<double> pa = resampleLinear(t_mb_all, c.multibody.timeseries.column("phi_crank"), {c.t_end});
  const std::vector<double> pb = resampleLinear(t_red, c.reduced.timeseries.column("phi_crank"), {c.t_end});
  return pa[0] - pb[0];
}

}  // namespace

ModelComparison compareRuns(const Scene& scene, RunResult mb, RunResult red) {
  ModelComparison c;
  describeModels(scene, c);
  if (!mb.timeseries.has("t") || mb.timeseries.rows.empty() || !red.timeseries.has("t") ||
      red.timeseries.rows.empty())
    throw std::runtime_error("compare: a model produced no output rows");
  const std::vector<double> t_mb_all = mb.timeseries.column("t");
  const std::vector<double> t_red = red.timeseries.column("t");
  const double t_common = std::min(t_mb_all.back(), t_red.back());
  const std::vector<double> grid = comparisonGrid(t_mb_all, t_red, t_common, c);
  compareQuantities(scene, mb, red, grid, c);
  c.multibody = std::move(mb);
  c.reduced = std::move(red);
  c.phase_drift = phaseDrift(c, t_mb_all, t_red);
  compareSteady(scene, c);
  return c;
}

ModelComparison runComparison(const Scene& scene, const CompareControl& control) {
  // The reduced model first: it is ~100x cheaper and rejects an impossible combination (e.g. the
  // Baranov scheme with an elastic coupling) before the long multibody run.
  RunControl rc;
  rc.interrupt = control.interrupt;
  RunResult red = runReducedModel(scene, rc);
  RunResult mb = runMultibodyModel(scene, rc);
  return compareRuns(scene, std::move(mb), std::move(red));
}

}  // namespace rollerdyn
