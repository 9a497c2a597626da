// Validation item: a sweep's rows and an optimization's evaluations belong to their points. Each
// row is compared with a separate run of its point (the scene file with the point's --set
// values, parsed, run and summarised without the sweep or the optimizer), on points chosen so
// that their metrics differ: a row paired with another point's run, or the values of one point
// with the metrics of another, cannot pass. Tolerance 1e-12 relative: the same scene run twice
// gives the same numbers to the last bit (deterministic integrators, nothing shared between the
// runs), so anything above round-off is a mix-up.
#include "studies/StudyChecks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "analysis/Summary.h"
#include "reduced/ReducedModel.h"
#include "scene/SceneParser.h"
#include "studies/Optimizer.h"
#include "studies/Sweep.h"
#include "io/FieldFormat.h"

namespace rollerdyn::validation {
namespace {

constexpr double kSameRun = 1e-12;  // file comment

// The metrics compared: (the sweep's name, its path in summary.json).
const std::vector<std::pair<const char*, const char*>>& compared() {
  static const std::vector<std::pair<const char*, const char*>> m = {
      {"delta", "delta"},
      {"H", "H"},
      {"k_p", "k_p"},
      {"omega_crank_mean", "omega_crank.mean"},
      {"omega_crank_min", "omega_crank.min"},
      {"omega_crank_max", "omega_crank.max"},
      {"eps_crank_abs_max", "eps_crank_abs_max"},
      {"motor_torque_rotor_rms", "sizing.motor.torque_shaft.rms"},
  };
  return m;
}


// A row's metrics against its point run on its own: largest relative difference (NaN on both
// sides counts as equal, NaN on one side as a difference of 1).
double rowDifference(const SweepPoint& row, const nlohmann::json& own) {
  double worst = 0;
  for (const auto& [name, path] : compared()) {
    const double a = row.metric(name), b = jsonDouble(jsonAt(own, path));
    if (std::isnan(a) && std::isnan(b)) continue;
    const double d = std::isfinite(a) && std::isfinite(b) ? std::abs(a - b) / std::max(std::abs(b), 1e-300) : 1.0;
    worst = std::max(worst, d);
  }
  return worst;
}

// The check's scene, its base overrides and the key varied; each row's reference is its point run
// on its own.
struct RowCheckScene {
  const ItemContext& ctx;
  const std::string file = "recuperative-2cart.yaml", key = "crank.offset_deg";
  const std::vector<std::string> base = {"simulation.t_end=8"};

  nlohmann::json ownRun(const std::vector<std::string>& point) const {
    std::vector<std::string> sets = base;
    sets.insert(sets.end(), point.begin(), point.end());
    const Scene sc = parseSceneFile(ctx.path(file), sets);
    return makeSummary(sc, runReducedModel(sc));
  }
};

SweepResult runCheckSweep(const RowCheckScene& c) {
  SweepOptions o;
  o.scene_path = c.ctx.path(c.file);
  o.base_overrides = c.base;
  o.params = {parseSweepValues(c.key, "0,60,90,150")};
  o.model = "reduced";
  o.threads = 2;
  o.interrupt = c.ctx.interrupt;
  return runSweep(o);
}

void claimSweepRows(ValidationSection& s, const RowCheckScene& c) {
  const SweepResult r = runCheckSweep(c);
  double worst = 0, closest = INFINITY;
  std::string deltas;
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    const SweepPoint& row = r.points[i];
    worst = std::max(worst, rowDifference(row, c.ownRun({c.key + "=" + row.texts.at(0)})));
    deltas += (i ? ", " : "") + row.texts.at(0) + "° → " + significant(row.metric("delta"), 4);
    for (std::size_t k = 0; k < i; ++k)  // how different the points are: smallest relative δ difference
      closest = std::min(closest, std::abs(row.metric("delta") / r.points[k].metric("delta") - 1.0));
  }
  s.claim(r.points.size() == 4 && worst <= kSameRun && closest > 100 * kSameRun,
          "Sweep: " + std::to_string(r.points.size()) + " rows, δ by offset " + deltas +
              " (the points' δ differ by at least " + significant(100 * closest, 2) + " %); largest relative difference of a "
              "row from its own point's run " + significant(worst, 2) + " (at most " + significant(kSameRun) + ").");
}

OptimizeResult runCheckOptimization(const RowCheckScene& c) {
  OptimizeOptions p;
  p.scene_path = c.ctx.path(c.file);
  p.base_overrides = c.base;
  p.params = {{c.key, 60.0, 120.0}};
  p.model = "reduced";
  p.minimize = "delta";
  p.method = "bobyqa";
  p.max_evals = 8;
  p.threads = 1;
  p.interrupt = c.ctx.interrupt;
  return runOptimize(p);
}

void claimOptimizationEvaluations(ValidationSection& s, const RowCheckScene& c) {
  const OptimizeResult q = runCheckOptimization(c);
  double worst_q = 0, objective = 0;
  std::size_t distinct = 0;
  std::vector<double> seen;
  for (const OptimizeEvaluation& e : q.history) {
    const nlohmann::json j = c.ownRun({c.key + "=" + e.texts.at(0)});
    worst_q = std::max(worst_q, rowDifference(e.point, j));
    const double d = jsonDouble(jsonMember(j, "delta"));
    objective = std::max(objective, std::isfinite(e.objective) && std::isfinite(d) ? std::abs(e.objective - d) / d : 1.0);
    bool fresh = true;
    for (double v : seen) fresh = fresh && std::abs(v / d - 1.0) > 100 * kSameRun;
    if (fresh) ++distinct;
    seen.push_back(d);
  }
  s.claim(q.history.size() >= 3 && distinct >= 3 && worst_q <= kSameRun && objective <= kSameRun,
          "Optimization: " + std::to_string(q.history.size()) + " evaluations (" + std::to_string(distinct) +
              " with distinct δ); largest relative difference of an evaluation's metrics from its own point's run " +
              significant(worst_q, 2) + ", of its objective from that run's δ " + significant(objective, 2) + " (at most " + significant(kSameRun) + ").");
}

}  // namespace

ValidationSection sweepRowChecks(const ItemContext& ctx) {
  ValidationSection s("studies", "Sweep rows and optimization evaluations against separate runs of their points");
  const RowCheckScene c{ctx};
  s.text() << "`" << ctx.command("sweep", c.file, c.base) << " --param " << c.key
           << " --values 0,60,90,150 --model reduced` and `rollerdyn optimize` of the same scene (reduced model, Δφ in "
              "60 … 120°, minimising δ, at most 8 evaluations). Each row's metrics (δ, H, k_p, mean, smallest and "
              "largest crank speed, largest |ε|, RMS motor torque) against the summary of its point run on its own. "
              "Tolerance 1e-12 relative: the same run twice gives the same numbers to the last bit.\n\n";
  claimSweepRows(s, c);
  claimOptimizationEvaluations(s, c);
  return s;
}

}  // namespace rollerdyn::validation
