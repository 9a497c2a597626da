#include "cli/RunOutputs.h"

#include <iostream>

#include "cli/Commands.h"
#include "cli/Progress.h"
#include "multibody/MultibodySimulation.h"
#include "studies/RunSummary.h"

namespace rollerdyn::cli {

RunResult runMultibodyWithProgress(const Scene& scene) {
  Progress progress;
  RunControl control;
  control.interrupt = &g_interrupted;
  control.progress = [&progress](double t, double t_end) { progress(t, t_end); };
  return runMultibodyModel(scene, control);
}

nlohmann::json writeRunOutputs(const Scene& scene, const RunResult& run, const std::string& scene_path,
                               const std::string& out_dir) {
  std::vector<std::string> warnings;
  const nlohmann::json summary = summarizeRun(scene, run, scene_path, &warnings);
  for (const std::string& w : warnings) std::cerr << "rollerdyn: warning: " << w << '\n';
  writeRunFiles(out_dir, run, summary);
  return summary;
}

}  // namespace rollerdyn::cli
