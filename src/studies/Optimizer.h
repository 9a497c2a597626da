// Design optimization (`rollerdyn optimize`): the scene values (--param KEY --range a:b) that
// minimise a summary metric of the run, subject to bounds on other metrics, with NLopt's
// derivative-free methods (Johnson, The NLopt nonlinear-optimization package):
//   bobyqa    Powell (2009) BOBYQA: quadratic models within bounds; no constraints;
//   cobyla    Powell (1994) COBYLA: linear models, handles the metric constraints;
//   direct-l  Gablonsky and Kelley (2001) DIRECT-L: global, divides the box, for multimodal metrics;
//   crs2      Kaelo and Ali (2006) CRS2 with local mutation: global, random search.
//   multistart  the local method (bobyqa or cobyla) from the middle of the box and from a Latin
//             hypercube of further starts, one search per thread, side by side.
// "auto": the local method (bobyqa without constraints, cobyla with them) from the middle of the
// box, then a grid over the whole box (with the evenly spread crank offsets 360°·k/n), then the
// local method again from the best design when it lies in another basin (Optimizer.cpp);
// bobyqa and cobyla alone are local and say so.
// The global methods handle constraints and failed runs by a penalty, and the local method
// polishes their best design (see Optimizer.cpp).
//
// Each evaluation is one sweep point (Sweep.h runSweepPoint: the values applied as --set, so
// validated like a scene file) and its metrics are read through the sweep's metric lookup. A
// design that did not complete, did not reach steady state, stalled or rocks (the crank does not
// turn in one direction: omega_crank_min <= 0) is infeasible, never an optimum. NLopt asks for
// one point at a time, so within one search evaluations are sequential; multistart runs its
// searches in parallel on threads. Repeated designs are taken from a cache.
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "studies/Sweep.h"
#include "studies/SweepDesigns.h"

namespace rollerdyn {

struct OptimizeEvaluation;

// A quantity the caller computes from a usable run (the Python interface's objective and
// constraint functions), in place of a metric of the run.
using EvaluationFunction = std::function<double(const OptimizeEvaluation&)>;

// 'METRIC<=VALUE' or 'METRIC>=VALUE' (blanks allowed).
struct OptimizeConstraint {
  std::string metric;      // a sweepNumericMetrics() name, or the name of `value`
  bool upper = true;       // true: metric <= bound; false: metric >= bound
  double bound = 0;        // in the metric's unit
  std::string text;        // as given
  EvaluationFunction value;  // when set: the constrained quantity instead of the metric; called
                             // only for usable runs (complete, steady, turning)
};
// Throws std::invalid_argument naming the text and what was expected.
OptimizeConstraint parseConstraint(const std::string& text);

struct OptimizeEvaluation {
  std::vector<std::string> texts;   // parameter values as applied (--set)
  std::vector<double> x;            // the same as numbers (scene units)
  SweepPoint point;                 // the run and its metrics
  bool run_ok = false;              // completed, steady, turning: a usable design
  std::string reason;               // why not run_ok (empty when it is)
  double objective = 0;             // the minimised quantity (NaN when not available)
  std::vector<double> constraint_metrics; // per constraint: the constrained quantity (NaN when not available)
  std::vector<double> constraint_values;  // per constraint: metric minus bound, sign so <= 0 holds
  bool constraints_hold = false;    // every constraint_values <= 0 (false when !run_ok)
  bool feasible() const { return run_ok && constraints_hold; }
};

struct OptimizeOptions {
  std::string scene_path;
  std::shared_ptr<const SceneInput> scene_input;  // the scene in memory (Sweep.h SweepOptions)
  std::vector<std::string> base_overrides;       // --set applied to every evaluation
  std::vector<SampleRange> params;               // keys and their bounds
  std::string model = "multibody";               // multibody | reduced
  std::string minimize;                          // a metric, or one of the --param keys; with
                                                 // `objective`, the name of that function
  EvaluationFunction objective;                  // when set: the minimised quantity, computed by
                                                 // the caller from each usable run
  std::vector<OptimizeConstraint> constraints;
  std::string method = "auto";                   // auto | bobyqa | cobyla | direct-l | crs2 | multistart
  int threads = 2;                               // multistart: parallel local searches
  int max_evals = 100;                           // evaluations at most
  double x_tolerance = 1e-3;                     // stop when steps are below this fraction of each range [-]
  const std::atomic<bool>* interrupt = nullptr;  // stops the search (NLopt forced stop)
  std::function<void(const OptimizeEvaluation&, std::size_t number)> on_evaluation;  // after each new one
};


struct OptimizeResult {
  std::string method;                       // the method used (bobyqa, cobyla, ...)
  std::vector<OptimizeEvaluation> history;  // every distinct evaluation, in order
  std::size_t requests = 0;                 // evaluations NLopt asked for (cache hits included)
  bool found = false;                       // some evaluation is feasible
  std::size_t best = 0;                     // index into history of the feasible minimum
  std::string stop_reason;                  // NLopt's result, in words
  std::string scope;                        // local or global, in words (printed with the optimum)
  std::vector<double> values_handed;        // every objective value handed to NLopt, in order (finite)
};

// Throws std::invalid_argument for an unknown metric, key, method or model, a bad range or
// constraint; every failed run is an infeasible evaluation instead.
OptimizeResult runOptimize(const OptimizeOptions& options);

// history.csv as columns, one cell per evaluation in order: evaluation, the parameters, objective,
// the constrained quantities (named by the constraints' texts), usable_run, constraints_hold,
// best_so_far, every metric, status, reason, cpu_seconds.
std::vector<StudyColumn> optimizeHistoryTable(const OptimizeOptions& options, const OptimizeResult& result);

// optimize.json without its figures: scene, model, parameters, method, evaluations, stop reason,
// found, optimum (parameters, objective, metrics, constraints) or a note.
nlohmann::json optimizeJson(const OptimizeOptions& options, const OptimizeResult& result);

// optimize.json, history.csv, convergence figure (and, with one or two parameters, the evaluated
// designs with the optimum marked). Returns the files written.
// `plot_note` receives why figures are missing ("" when all were drawn).
std::vector<std::string> writeOptimizeOutputs(const OptimizeOptions& options, const OptimizeResult& result,
                                              const std::string& out_dir, std::string* plot_note = nullptr);

}  // namespace rollerdyn
