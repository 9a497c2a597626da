// `rollerdyn optimize SCENE --param KEY --range a:b [--param ...] --minimize METRIC
//  [--constraint 'METRIC<=VALUE']... [--model reduced|multibody] [--method ...] [--max-evals N]
//  [--set k=v]... [--out DIR]`: design optimization with NLopt (src/studies/Optimizer.h).
#include <cmath>
#include <iostream>
#include <sstream>
#include <memory>
#include <stdexcept>

#include <CLI/CLI.hpp>

#include "cli/Commands.h"
#include "cli/SceneOptions.h"
#include "report/OutputDir.h"
#include "scene/SceneParser.h"
#include "scene/SceneSchema.h"
#include "studies/Optimizer.h"

namespace rollerdyn::cli {

namespace {

struct OptimizeArgs {
  SceneArgs scene;
  std::vector<std::string> params, ranges, constraints;
  std::string model = "multibody", minimize, method = "auto", out_dir;
  int max_evals = 100;
  int threads = 2;
};

// The study's options from the command line; each --param with its --range.
OptimizeOptions optimizeOptions(const OptimizeArgs& a) {
  if (a.params.size() != a.ranges.size())
    throw std::invalid_argument("optimize: give one --range a:b after each --param (" + std::to_string(a.params.size()) +
                                " --param, " + std::to_string(a.ranges.size()) + " --range)");
  OptimizeOptions o;
  o.scene_path = a.scene.scene_path;
  o.base_overrides = a.scene.overrides;
  for (std::size_t i = 0; i < a.params.size(); ++i) o.params.push_back(parseSampleRange(a.params[i], a.ranges[i]));
  for (const std::string& c : a.constraints) o.constraints.push_back(parseConstraint(c));
  o.model = a.model;
  o.minimize = a.minimize;
  o.method = a.method;
  o.max_evals = a.max_evals;
  o.threads = a.threads;
  o.interrupt = &g_interrupted;
  return o;
}

// One evaluation's console line. A metric of a run that is not usable (no steady state, not
// turning) is no value: "n/a", as the sweep prints it (the trial read "delta 0.720692 infeasible"
// beside "delta nan"). A parameter minimised is a value whatever the run did.
void printEvaluation(const OptimizeOptions& o, const OptimizeEvaluation& e, std::size_t number) {
  std::cout << "[" << number << "]";
  for (std::size_t k = 0; k < o.params.size(); ++k) std::cout << ' ' << o.params[k].key << '=' << e.texts[k];
  bool minimise_parameter = false;
  for (const auto& p : o.params) minimise_parameter = minimise_parameter || p.key == o.minimize;
  auto value = [&e](double v, bool meaningful) {
    std::ostringstream s;
    if (meaningful && std::isfinite(v)) s << v; else s << "n/a";
    return s.str();
  };
  std::cout << "  " << o.minimize << ' ' << value(e.objective, e.run_ok || minimise_parameter);
  for (std::size_t j = 0; j < o.constraints.size(); ++j)
    std::cout << "  " << o.constraints[j].metric << ' ' << value(e.constraint_metrics[j], e.run_ok);
  std::cout << (e.feasible() ? "  feasible" : e.run_ok ? "  constraint violated" : "  infeasible: " + e.reason)
            << std::endl;
}

// The values of the run at exactly the printed parameters: a parameter minimised as it was
// applied (--set), a metric with 9 significant digits (below the integration's accuracy), so
// that `simulate --set KEY=VALUE` with the printed values gives the printed metric.
void printOptimum(const OptimizeOptions& o, const OptimizeEvaluation& b) {
  std::string objective;
  for (std::size_t k = 0; k < o.params.size(); ++k)
    if (o.params[k].key == o.minimize) objective = b.texts[k];
  if (objective.empty()) {
    std::ostringstream v;
    v.precision(9);
    v << b.objective;
    objective = v.str();
  }
  std::cout << "optimum: " << o.minimize << " = " << objective << " at";
  for (std::size_t k = 0; k < o.params.size(); ++k) std::cout << ' ' << o.params[k].key << '=' << b.texts[k];
  std::cout << (o.constraints.empty() ? "" : " (constraints hold)") << "\n";
}

int runOptimizeCommand(const OptimizeArgs& a) {
  OptimizeOptions o = optimizeOptions(a);
  // A bad scene fails before any run; checked with each parameter at its lower bound, so a key the
  // optimisation sets counts as given.
  std::vector<std::string> first_design = o.base_overrides;
  for (const SampleRange& p : o.params) first_design.push_back(p.key + "=" + formatNumber(p.lower));
  const Scene base = parseSceneFile(o.scene_path, first_design);
  std::string out_dir = a.out_dir.empty() ? defaultOutDir(base.name) + "/optimize_" + o.minimize : a.out_dir;
  o.on_evaluation = [&o](const OptimizeEvaluation& e, std::size_t number) { printEvaluation(o, e, number); };
  prepareOutputDir(out_dir);  // before the runs: a bad --out fails now
  std::cout << "optimize " << base.name << ": minimize " << o.minimize << ", " << o.model << " model\n";
  const OptimizeResult r = runOptimize(o);
  std::string plot_note;
  const auto files = writeOptimizeOutputs(o, r, out_dir, &plot_note);
  std::cout << r.method << ": " << r.history.size() << " evaluations (" << r.stop_reason << ")\n";
  if (!r.scope.empty()) std::cout << "search: " << r.scope << "\n";
  if (!plot_note.empty()) std::cerr << "rollerdyn: figures: " << plot_note << "\n";
  if (r.found) printOptimum(o, r.history[r.best]);
  else std::cout << "no usable design that keeps the constraints was found (see optimize.json)\n";
  std::cout << "outputs in " << out_dir << "/ (" << files.size() << " files)\n";
  return r.found ? 0 : 3;
}

const char* const kOptimizeFooter =
      "A design that does not complete, does not reach steady state, stalls or rocks is infeasible, never an "
      "optimum. NLopt asks for one design at a time, so bobyqa, cobyla, direct-l and crs2 evaluate one after "
      "another; multistart runs --threads searches side by side. Exit code 3 when no feasible design was found.\n"
      "Examples:\n"
      "  rollerdyn optimize model/recuperative-2cart.yaml --param crank.offset_deg --range 0:180 --minimize delta "
      "--model reduced\n"
      "  rollerdyn optimize model/energy-balanced-3cart.yaml --param flywheel.inertia --range 0:400 "
      "--minimize flywheel.inertia --constraint 'delta<=0.05' --model reduced";

// How the designs are searched: the model run, the method, its threads and budget, the output.
void addSearchOptions(CLI::App& cmd, OptimizeArgs& a) {
  cmd.add_option("--model", a.model, "multibody (default) or reduced")->check(CLI::IsMember({"multibody", "reduced"}));
  cmd.add_option("--method", a.method,
                  "auto (default: bobyqa without constraints or cobyla with them from the middle of the ranges, "
                  "then a grid over the whole ranges (19 values of one parameter, 7 of two, 5 of more; for "
                  "crank.offset_deg also the evenly spread offsets 360°·k/n), polished by the local method when "
                  "its best lies elsewhere), bobyqa or "
                  "cobyla alone (LOCAL: the minimum nearest to the middle of the ranges), direct-l or crs2 (global, "
                  "constraints by penalty; the local method polishes their best design), multistart (the local "
                  "method from --threads starts in parallel)");
  cmd.add_option("--threads", a.threads, "parallel local searches of --method multistart (default 2)")
      ->check(CLI::Range(1, 64));
  cmd.add_option("--max-evals", a.max_evals, "evaluations at most (default 100)")->check(CLI::PositiveNumber);
  cmd.add_option("--out", a.out_dir, "output folder (default out/<scene name>/optimize_<metric>)");
}

}  // namespace

Subcommand addOptimizeCommand(CLI::App& app) {
  auto args = std::make_shared<OptimizeArgs>();
  CLI::App* cmd = app.add_subcommand(
      "optimize", "scene values that minimise a metric subject to metric bounds (NLopt); optimize.json, history.csv, figures");
  addSceneFile(*cmd, args->scene, "scene file (YAML)");
  addSceneOverrides(*cmd, args->scene, "override a scene value for every evaluation, key.path=value (repeatable)");
  addStudyParams(*cmd, args->params);
  cmd->add_option("--range", args->ranges, "bounds a:b of the preceding --param (its scene unit)")
      ->required()
      ->allow_extra_args(false);
  cmd->add_option("--minimize", args->minimize,
                  "what to minimise: a sweep metric (delta, H, k_p, coupling_torque_swing, twist_swing, "
                  "eps_crank_abs_max, ...; see `rollerdyn sweep --help`) or one of the --param keys")
      ->required();
  cmd->add_option("--constraint", args->constraints, "'METRIC<=VALUE' or 'METRIC>=VALUE' (repeatable), e.g. 'delta<=0.05'")
      ->allow_extra_args(false);
  addSearchOptions(*cmd, *args);
  cmd->footer(kOptimizeFooter);
  return {cmd, [args] { return runOptimizeCommand(*args); }};
}

}  // namespace rollerdyn::cli
