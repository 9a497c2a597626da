// `rollerdyn sweep SCENE --param KEY --values a:b:step|v1,v2,... [--param KEY --values ...]
//  [--model multibody|reduced] [--minimize METRIC] [--set k=v]... [--out DIR] [--threads N]`:
// one simulation per grid point (src/studies/Sweep.h), sweep.csv + sweep.json + plots in DIR.
// Also designs from a file or a Latin hypercube (SweepDesigns.h), a CPU budget per point,
// saved rows and --resume (SweepProgress.h), and MPI ranks under mpirun/srun (SweepMpi.h).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <stdexcept>

#include <CLI/CLI.hpp>

#include "cli/Commands.h"
#include "cli/SceneOptions.h"
#include "cli/UsageError.h"
#include "report/OutputDir.h"
#include "scene/Plausibility.h"
#include "scene/SceneParser.h"
#include "scene/SceneSchema.h"
#include "studies/Sweep.h"
#include "studies/SweepDesigns.h"
#include "studies/SweepMpi.h"
#include "io/FieldFormat.h"

namespace rollerdyn::cli {

namespace {

struct SweepArgs {
  SceneArgs scene;
  std::vector<std::string> params, values;
  std::string model = "multibody", minimize, out_dir;
  int threads = 2;
  // Large and distributed sweeps
  std::string values_file;          // --values-file: one design per line
  std::size_t lhs = 0;              // --lhs N: Latin hypercube of N designs in the --range's
  std::uint64_t seed = 1;           // --seed of the Latin hypercube
  std::vector<std::string> ranges;  // --range a:b per --param (with --lhs)
  double point_budget = 0;          // --point-budget: CPU seconds per point [s]; 0: none
  bool resume = false;              // --resume: reuse the rows saved in the output folder
  bool dispatcher_only = false;     // --dispatcher-only: under MPI, rank 0 computes no points
};

// The Latin hypercube's designs of --lhs N, one --range after each --param.
std::vector<std::vector<std::string>> lhsDesigns(const SweepArgs& a) {
  if (a.params.size() != a.ranges.size())
    throw std::invalid_argument("sweep: --lhs needs one --range a:b after each --param (" +
                                std::to_string(a.params.size()) + " --param, " + std::to_string(a.ranges.size()) +
                                " --range)");
  std::vector<SampleRange> ranges;
  for (std::size_t i = 0; i < a.params.size(); ++i) ranges.push_back(parseSampleRange(a.params[i], a.ranges[i]));
  return latinHypercube(ranges, a.lhs, a.seed);
}

// The parameters (and explicit designs) from --values, --values-file or --lhs/--range.
void parseDesignOptions(const SweepArgs& a, SweepOptions& o) {
  const int sources = int(!a.values.empty()) + int(!a.values_file.empty()) + int(a.lhs > 0);
  if (sources != 1)
    throw std::invalid_argument("sweep: give the values one way: --values after each --param, or --values-file "
                                "FILE, or --lhs N with a --range after each --param");
  if (!a.ranges.empty() && a.lhs == 0)
    throw std::invalid_argument("sweep: --range goes with --lhs N (a Latin hypercube); for a grid use --values a:b:step");
  if (!a.values.empty()) {
    if (a.params.size() != a.values.size())
      throw std::invalid_argument("sweep: give one --values after each --param (" + std::to_string(a.params.size()) +
                                  " --param, " + std::to_string(a.values.size()) + " --values)");
    for (std::size_t i = 0; i < a.params.size(); ++i) o.params.push_back(parseSweepValues(a.params[i], a.values[i]));
    return;
  }
  o.designs = !a.values_file.empty() ? readValuesFile(a.values_file, a.params) : lhsDesigns(a);
  o.params = designParameters(a.params, o.designs);
}

std::string lineFor(const SweepOptions& o, const SweepPoint& p, std::size_t done, std::size_t total) {
  // After the grid: the run at the parabola's vertex (--minimize, one parameter), before any optimum.
  std::string s = done > total ? "[vertex of the parabola]" : "[" + std::to_string(done) + "/" + std::to_string(total) + "]";
  for (std::size_t k = 0; k < o.params.size(); ++k) s += " " + o.params[k].key + "=" + p.texts[k];
  char buf[256];
  // The motion first (stalled, rocking, turning), then whether a turning crank settled.
  const std::string state = !p.ran ? "FAILED"
                            : p.motion == "turning" ? (p.steady ? "turning, steady" : "turning, NOT steady")
                                                    : p.motion;
  // "n/a" where a metric has no meaning (a rocking or stalled crank).
  auto f = [](double v) { return significantOr(v, 4, "n/a"); };
  std::snprintf(buf, sizeof buf, "  δ %s  H %s  k_p %s  ΔM %s N·m  %s  %.2g s cpu", f(p.metric("delta")).c_str(),
                f(p.metric("H")).c_str(), f(p.metric("k_p")).c_str(),
                f(p.metric("coupling_torque_swing")).c_str(), state.c_str(), p.cpu_seconds);
  s += buf;
  if (!p.complete) s += "  (" + p.status + ")";
  if (!p.warnings.empty()) s += "  [first-estimate resonance warning]";
  return s;
}

// The values of parameter k the sweep runs: its grid values, or its column of the designs.
std::vector<std::string> sweptTexts(const SweepOptions& o, std::size_t k) {
  if (o.designs.empty()) return o.params[k].texts;
  std::vector<std::string> texts;
  for (const auto& d : o.designs)
    if (k < d.size()) texts.push_back(d[k]);
  return texts;
}

// The values of `key` whose base scene draws a plausibility warning on the key itself (at most
// 200: enough to say it); `first`: the first such warning.
std::vector<std::string> implausibleValues(const SweepOptions& o, const std::string& key,
                                           const std::vector<std::string>& texts, std::string& first) {
  std::vector<std::string> flagged;
  for (const std::string& text : texts) {
    if (flagged.size() >= 200) break;
    std::vector<std::string> overrides = o.base_overrides;
    overrides.push_back(key + "=" + text);
    try {
      for (const std::string& w : plausibilityWarnings(parseSceneFile(o.scene_path, overrides)))
        if (w.rfind(key, 0) == 0) {
          if (first.empty()) first = w;
          flagged.push_back(text);
          break;
        }
    } catch (const std::exception&) {
      // a value the scene rejects: the run of that point says so
    }
  }
  return flagged;
}

// The plausibility warnings of the swept values themselves (an offset swept in radians, a length
// in millimetres): each value of each parameter on the base scene, one line per parameter naming
// the values concerned. simulate warns of a single such value; a sweep ran them silently.
void warnImplausibleValues(const SweepOptions& o) {
  for (std::size_t k = 0; k < o.params.size(); ++k) {
    const std::string& key = o.params[k].key;
    std::string first;
    const std::vector<std::string> flagged = implausibleValues(o, key, sweptTexts(o, k), first);
    if (flagged.empty()) continue;
    std::string list;
    for (std::size_t i = 0; i < flagged.size() && i < 6; ++i) list += (i ? ", " : "") + flagged[i];
    if (flagged.size() > 6) list += ", ... (" + std::to_string(flagged.size()) + " values)";
    std::cerr << "rollerdyn: warning: --param " << key << " " << list << ": " << first << '\n';
  }
}

// This process among the MPI ranks (one rank without MPI).
struct SweepRanks {
  bool rank0 = true;
  int size = 1;
};

// Under mpirun/srun: share the points over the ranks; only rank 0 prints and writes.
SweepRanks joinRanks(SweepOptions& o) {
  const MpiLaunch launch = detectMpiLaunch();
  SweepRanks ranks;
  if (launch.launched && (mpiBuilt() || launch.world_size > 1)) {
    const MpiWorld world = startMpi();  // throws when built without MPI
    ranks.rank0 = world.rank == 0;
    ranks.size = world.size;
    o.mpi = world.size > 1;  // one rank (mpirun -n 1, a batch script's shell): the threads
  }
  return ranks;
}

// The points of the grid (one per combination of the parameters' values) or of the designs.
std::size_t pointCount(const SweepOptions& o) {
  std::size_t total = o.designs.size();
  if (o.designs.empty()) {
    total = 1;
    for (const SweepParameter& p : o.params) total *= p.values.size();
  }
  return total;
}

// What is swept, how, and the legend of the per-point lines.
void printSweepHeader(const SweepOptions& o, const std::string& scene_name, std::size_t total, int ranks) {
  std::cout << "sweep of " << scene_name << ": " << total << " points, " << o.model << " model, "
            << (o.mpi ? std::to_string(ranks) + " MPI ranks"
                      : std::to_string(std::min<std::size_t>(std::max(1, o.threads), total)) + " threads")
            << "\n"
            << "per point: δ coefficient of unevenness, H coefficient of dynamics, k_p generalised "
               "coefficient (Loveikin and Pochka (2007) eq. (12)-(14)), ΔM coupling torque swing, "
               "then the motion (turning, starting, rocking, stalled, coasting, at_rest)\n";
}

// The points' outcome after the outputs are written: how many did not settle, rock or stall, are
// near a resonance or failed; returns the exit code.
struct PointCounts {
  std::size_t failed = 0, unsteady = 0, warned = 0, not_turning = 0, rocking = 0, stalled = 0;
};

PointCounts countPoints(const SweepResult& r) {
  PointCounts n;
  for (const SweepPoint& p : r.points) {
    const bool drive_fails = p.motion == "stalled" || p.motion == "rocking";
    n.not_turning += drive_fails;
    n.failed += !p.complete && !drive_fails;
    n.unsteady += p.complete && !p.steady;
    n.warned += !p.warnings.empty();
    n.rocking += p.motion == "rocking";
    n.stalled += p.motion == "stalled";
  }
  return n;
}

int reportPoints(const SweepOptions& o, const SweepResult& r, const std::string& out_dir, std::size_t files) {
  const PointCounts n = countPoints(r);
  const std::size_t failed = n.failed, warned = n.warned;
  if (!o.minimize.empty()) std::cout << describeOptimum(o, r) << "\n";
  if (n.unsteady) std::cout << n.unsteady << " point(s) did not reach steady state (see steady_state_reached)\n";
  if (n.rocking || n.stalled)
    std::cout << n.rocking << " point(s) rocking, " << n.stalled << " stalled (motion column; their δ, H, k_p are n/a)\n";
  // A sweep runs no modal analysis: its warnings are the first estimate's (two constant inertias),
  // which simulate's modal verdict may overrule (six carts at 60°: heavily damped, no resonance).
  if (warned)
    std::cerr << "rollerdyn: warning: " << warned
              << " point(s) near a torsional resonance by the first estimate (two constant inertias, sweep.json); "
                 "the modal analysis of `simulate` on a point gives the verdict\n";
  std::cout << "outputs in " << out_dir << "/ (" << files << " files)\n";
  if (failed)
    std::cerr << "rollerdyn: " << failed << " of " << r.points.size()
              << " points failed to run (numerical failure, invalid values or interrupted: status column)\n";
  // 3: some point failed to run; 4: every point ran but some drive stalls or rocks; 0: all turn.
  return failed ? 3 : n.not_turning ? 4 : 0;
}

SweepOptions sweepOptions(const SweepArgs& a) {
  SweepOptions o;
  o.scene_path = a.scene.scene_path;
  o.base_overrides = a.scene.overrides;
  parseDesignOptions(a, o);
  for (const SweepParameter& p : o.params) requireSceneKey("sweep: --param " + p.key, p.key);  // with a did-you-mean
  o.model = a.model;
  o.minimize = a.minimize;
  if (!o.minimize.empty()) requireSweepMetric("sweep: --minimize", o.minimize);  // before any header or run
  o.threads = a.threads;
  o.interrupt = &g_interrupted;
  o.point_budget = a.point_budget;
  o.resume = a.resume;
  o.dispatcher_computes = !a.dispatcher_only;
  return o;
}

// --out, or out/<scene name>/sweep_<keys>.
std::string sweepOutDir(const SweepArgs& a, const Scene& base, const SweepOptions& o) {
  if (!a.out_dir.empty()) return a.out_dir;
  std::string out_dir = defaultOutDir(base.name) + "/sweep";
  for (const SweepParameter& p : o.params) out_dir += "_" + p.key;
  return out_dir;
}

// After the runs (rank 0): the resumed points, the files and the points' outcome.
int finishSweep(const SweepOptions& o, SweepResult& r, const std::string& out_dir) {
  if (r.execution.value("points_resumed", 0) > 0)
    std::cout << "resumed " << r.execution["points_resumed"] << " saved point(s), computed "
              << r.execution["points_computed"] << "\n";
  std::string plot_note;
  const auto files = writeSweepOutputs(o, r, out_dir, &plot_note);
  if (!plot_note.empty()) std::cout << "figures: " << plot_note << " (sweep.csv has every point)\n";
  return reportPoints(o, r, out_dir, files.size());
}

// Rank 0 before any point: the output folder (a bad --out fails now), the swept values'
// plausibility, a resume without saved rows, the header.
void prepareSweep(const SweepOptions& o, const Scene& base, const std::string& out_dir, int ranks) {
  prepareOutputDir(out_dir);
  warnImplausibleValues(o);
  const std::size_t total = pointCount(o);
  if (o.resume && !std::filesystem::exists(o.progress_path))
    std::cout << "--resume: no saved rows in " << o.progress_path << ", starting afresh\n";
  printSweepHeader(o, base.name, total, ranks);
}

int runSweepCommand(const SweepArgs& a) {
  SweepOptions o = sweepOptions(a);
  const SweepRanks ranks = joinRanks(o);
  const bool rank0 = ranks.rank0;
  // Validate the base scene once, so a typo in the file or a --set fails before any run (as the
  // first point sees it: a key the parameters set counts as given).
  const Scene base = parseSceneFile(o.scene_path, firstPointOverrides(o));
  const std::string out_dir = sweepOutDir(a, base, o);
  o.progress_path = out_dir + "/sweep.progress.jsonl";
  if (rank0) prepareSweep(o, base, out_dir, ranks.size);
  o.on_point = [&o](const SweepPoint& p, std::size_t done, std::size_t n) {
    std::cout << lineFor(o, p, done, n) << std::endl;
  };
  SweepResult r;
  try {
    r = runSweep(o);
  } catch (const std::exception&) {
    if (!rank0) return 2;  // every rank meets the same bad input: rank 0 alone says why
    throw;
  }
  if (!r.output_rank) return 0;  // an MPI worker: rank 0 writes the outputs
  return finishSweep(o, r, out_dir);
}

const char* const kSweepFooter =
      "Each value is applied as --set KEY=VALUE, so it is validated like a scene file; a point that fails "
      "is reported in its row (status) and the sweep goes on. Exit code 3 when any point failed to run (numerical "
      "failure, invalid values, interrupted), else 4 when a drive stalls or rocks at some point, else 0.\n"
      "Every finished point is appended to DIR/sweep.progress.jsonl at once, so a killed sweep loses only the "
      "points in flight: run the same command with --resume (without it the file is started afresh). The final "
      "files are written at the end, atomically.\n"
      "MPI: under mpirun or srun (built with MPI) the points are shared over the ranks, handed out one at a time "
      "by rank 0; the files are the same as with threads; sweep.json adds ranks and points_per_rank.\n"
      "Examples:\n"
      "  rollerdyn sweep model/recuperative-2cart.yaml --param crank.offset_deg --values 0:180:10 "
      "--model reduced --minimize delta\n"
      "  rollerdyn sweep model/balanced-4cart.yaml --param crank.offset_deg --values 0:90:10 "
      "--param coupling.damping --values 2000,8000 --model reduced\n"
      "  rollerdyn sweep model/energy-balanced-3cart.yaml --param flywheel.inertia --range 0:400 "
      "--param crank.offset_deg --range 90:150 --lhs 200 --seed 7 --model reduced\n"
      "  mpirun -n 64 rollerdyn sweep model/balanced-4cart.yaml --values-file designs.txt --param crank.offset_deg "
      "--param coupling.damping --point-budget 600 --resume --out out/big";

// The points: a grid of --values, designs of --values-file, or a Latin hypercube.
void addDesignOptions(CLI::App& cmd, SweepArgs& a) {
  cmd.add_option("--values", a.values, "values of the preceding --param: a:b:step or v1,v2,...")
      ->allow_extra_args(false);
  cmd.add_option("--values-file", a.values_file,
                  "designs instead of a grid: one per line, one value per --param in their order (commas or "
                  "blanks; '#' comments; an optional header line naming the keys)")
      ->check(CLI::ExistingFile);
  cmd.add_option("--lhs", a.lhs, "Latin hypercube of N designs instead of a grid (McKay et al. (1979)); "
                                      "needs a --range after each --param")
      ->check(CLI::PositiveNumber);
  cmd.add_option("--range", a.ranges, "range a:b of the preceding --param for --lhs")->allow_extra_args(false);
  cmd.add_option("--seed", a.seed, "seed of --lhs (default 1; the same seed gives the same designs)");
}

// How the points are run: a CPU budget per point, resuming, MPI's dispatcher.
void addExecutionOptions(CLI::App& cmd, SweepArgs& a) {
  cmd.add_option("--point-budget", a.point_budget,
                  "CPU seconds per point (rounded up to whole seconds); each point then runs in a child process "
                  "and one over budget becomes a 'timeout' row")
      ->check(CLI::PositiveNumber);
  cmd.add_flag("--resume", a.resume,
                "continue a killed sweep: reuse the rows saved in DIR/sweep.progress.jsonl (same command "
                "required; checked by a fingerprint) and compute only the missing points");
  cmd.add_flag("--dispatcher-only", a.dispatcher_only,
                "under MPI: rank 0 only hands out points and collects rows (default: it also computes)");
}

}  // namespace

Subcommand addSweepCommand(CLI::App& app) {
  auto args = std::make_shared<SweepArgs>();
  CLI::App* cmd = app.add_subcommand(
      "sweep", "one simulation per value of one or more scene keys; sweep.csv, sweep.json, plots, optimum");
  addSceneFile(*cmd, args->scene, "scene file (YAML)");
  addSceneOverrides(*cmd, args->scene, "override a scene value for every point, key.path=value (repeatable)");
  addStudyParams(*cmd, args->params);
  addDesignOptions(*cmd, *args);
  addExecutionOptions(*cmd, *args);
  cmd->add_option("--model", args->model, "multibody (default) or reduced")
      ->check(oneOf({"multibody", "reduced"}));
  cmd->add_option("--minimize", args->minimize,
                  "metric whose minimum to report: delta, H, k_p, omega_crank_mean, coupling_torque_swing, "
                  "twist_swing, eps_crank_abs_max, energy_residual_rel, omega_crank_min, omega_crank_max, "
                  "omega_crank_midrange, twist_rate_swing, twist_accel_swing, or a drive-sizing metric "
                  "(motor_torque_rotor_rms, motor_rms_over_nominal, motor_peak_over_breakdown, motor_power_mean, "
                  "energy_per_revolution, coupling_torque_peak, guide_roller_peak, rod_force_peak, "
                  "crank_pin_peak, main_bearing_peak, ..._equivalent_load: see sweep.csv); with one numeric "
                  "parameter the vertex of the parabola through the best point and its neighbours is run as one "
                  "more point, and the optimum is the better of the two runs");
  cmd->add_option("--threads", args->threads, "worker threads (default 2; under MPI one per rank)")->check(CLI::Range(1, 64));
  cmd->add_option("--out", args->out_dir, "output folder (default out/<scene name>/sweep_<keys>)");
  cmd->footer(kSweepFooter);
  return {cmd, [args] { return runSweepCommand(*args); }};
}

}  // namespace rollerdyn::cli
