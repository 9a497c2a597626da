#include "cli/RunOutputs.h"

#include <iostream>

#include "analysis/RestDetector.h"
#include "cli/Commands.h"
#include "cli/Progress.h"
#include "compare/RunModel.h"

namespace rollerdyn::cli {

RunResult runWithProgress(const Scene& scene, const std::string& model) {
  Progress progress;
  RunControl control;
  control.interrupt = &g_interrupted;
  control.progress = [&progress](double t, double t_end) { progress(t, t_end); };
  return runModel(scene, model, control);
}

nlohmann::json writeRunOutputs(const Scene& scene, const RunResult& run, const std::string& scene_path,
                               const std::string& out_dir, const std::vector<std::string>& overrides,
                               const modes::RunModal* modal) {
  RunSummaryOptions options;
  options.scene_file = scene_path;
  options.overrides = overrides;
  options.modal = modal;
  RunMessages messages;
  const nlohmann::json summary = summarizeRun(scene, run, options, &messages);
  // The load's and the plausibility warnings, the first estimate's and the modal analysis'
  // resonance warnings, then the verdict that reconciles them.
  for (const std::string& w : messages.run_warnings) std::cerr << "rollerdyn: warning: " << w << '\n';
  for (const std::string& w : messages.resonance_warnings) std::cerr << "rollerdyn: warning: " << w << '\n';
  if (!messages.resonance_verdict.empty()) std::cerr << "rollerdyn: " << messages.resonance_verdict << '\n';
  writeRunFiles(out_dir, run, summary, modal);
  return summary;
}

int runExitCode(const RunResult& run, const nlohmann::json& summary) {
  const std::string motion = summary.value("motion", "");
  if (motion == "stalled" || motion == "rocking") return kExitDriveDoesNotTurn;
  // A machine without a motor that friction and loads brought to rest ended its run early by the
  // rest rule (RestDetector.h): a finished result, not a failed run.
  if (motion == "at_rest" && RestDetector::motionOfStatus(run.stats.status) == "at_rest") return 0;
  return run.stats.complete ? 0 : kExitRunFailed;
}

}  // namespace rollerdyn::cli
