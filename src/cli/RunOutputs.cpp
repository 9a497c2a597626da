#include "cli/RunOutputs.h"

#include <iostream>

#include "analysis/FrictionChecks.h"
#include "analysis/Summary.h"
#include "cli/Commands.h"
#include "cli/Progress.h"
#include "multibody/MultibodySimulation.h"
#include "report/OutputFolder.h"
#include "studies/ResonanceCheck.h"
#include "studies/StartLoad.h"

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
  writeRunTables(out_dir, run);
  const StartLoad start_load = startLoadOf(scene);  // explains a stall
  nlohmann::json summary = makeSummary(scene, run, &start_load);
  summary["scene_path"] = absolutePath(scene_path);
  for (const std::string& w : addResonanceWarnings(scene, summary)) std::cerr << "rollerdyn: warning: " << w << '\n';
  for (const std::string& w : addFrictionWarnings(scene, run, summary)) std::cerr << "rollerdyn: warning: " << w << '\n';
  writeSummaryAtomic(out_dir + "/summary.json", summary);
  return summary;
}

}  // namespace rollerdyn::cli
