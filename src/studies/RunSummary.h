// What every caller of one run writes or returns about it, in one place, so that `simulate`,
// `report`, the sweep points and the Python interface give the same summary.json and files:
//   - the summary (analysis/Summary.h) with the load at the start that explains a stall
//     (StartLoad.h), the user's overrides (so that a command the console suggests repeats them),
//     the plausibility warnings of the scene (Plausibility.h), the guide friction's margins and
//     warnings (analysis/FrictionChecks.h: self-locking, dead centre, the quasi-static friction
//     work), the resonance and stability verdict (ResonanceCheck.h: the modal analysis at the run's
//     steady mean crank speed, the two-mass first estimate beside it), and the scene file's absolute
//     path, so `rollerdyn plot DIR` finds it from any folder; where the motor's fitted circuit
//     came from (motor_fit: fitted now or read from the fit cache; null without a fit);
//   - the run's files in an output folder: timeseries.csv, reactions.csv (when computed),
//     summary.json and, with a modal analysis, its files; each written to a temporary name and
//     renamed.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/RunResult.h"
#include "modes/RunModes.h"
#include "scene/Scene.h"

namespace rollerdyn {

struct RunSummaryOptions {
  // The scene file as given (made absolute and normalised in summary["scene_path"]), or "" for a
  // scene that is not a file (then scene_path is null).
  std::string scene_file;
  // The overrides applied to the file (--set key=value), in order: summary["overrides"].
  std::vector<std::string> overrides;
  // A full modal analysis made for this run (simulate --modes, report): the verdict rests on it,
  // and summary["modes"] and summary["order_spectrum"] hold it.
  const modes::RunModal* modal = nullptr;
  // With sizing.target_delta: find the flywheel that meets δ* by runs (FlywheelByRuns.h, up to five
  // more runs), summary["sizing"]["flywheel"]["by_runs"]. A sweep's points leave it out.
  bool flywheel_by_runs = true;
};

// What a terminal prints about the run once it is summarized: the warnings of summary["warnings"]
// in order, run_warnings then resonance_warnings, then the resonance verdict.
struct RunMessages {
  // The load's warnings (a load that does no net work), the scene's plausibility warnings and the
  // guide friction's warnings.
  std::vector<std::string> run_warnings;
  // The run's resonance warnings (studies/ResonanceCheck.h): the modal analysis' where it was made,
  // else a first-estimate hit labelled unchecked.
  std::vector<std::string> resonance_warnings;
  // "resonance verdict: ..." beside a first-estimate hit: the modal analysis refutes it (and why) or
  // could not check it; else "".
  std::string resonance_verdict;
  // What the two-mass first estimate said (one sentence per order it found near p0), whatever the
  // verdict made of it.
  std::vector<std::string> first_estimate;
};

// summary.json of `run` on `scene`.
nlohmann::json summarizeRun(const Scene& scene, const RunResult& run, const RunSummaryOptions& options,
                            RunMessages* messages = nullptr);

// Writes the run's tables, `summary` and, with `modal`, the modal analysis' files into `out_dir`
// (which must exist), atomically.
void writeRunFiles(const std::string& out_dir, const RunResult& run, const nlohmann::json& summary,
                   const modes::RunModal* modal = nullptr);

}  // namespace rollerdyn
