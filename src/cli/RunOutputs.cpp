#include "cli/RunOutputs.h"

#include <iostream>

#include "analysis/FrictionChecks.h"
#include "analysis/Summary.h"
#include "cli/Commands.h"
#include "cli/Progress.h"
#include "modes/RunModes.h"
#include "multibody/MultibodySimulation.h"
#include "report/OutputFolder.h"
#include "scene/Plausibility.h"
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

RunModal analyseRunModes(const Scene& scene, const RunResult& run, bool charts) {
  modes::ModesOptions o;
  o.charts = charts;
  o.chart_c = 12;
  o.chart_y = 8;
  RunModal m;
  m.report = modes::analyseModes(scene, o);
  m.spectrum = modes::runSpectrum(scene, run);
  return m;
}

nlohmann::json writeRunOutputs(const Scene& scene, const RunResult& run, const std::string& scene_path,
                               const std::string& out_dir, const std::vector<std::string>& overrides,
                               const RunModal* modal) {
  writeRunTables(out_dir, run);
  const StartLoad start_load = startLoadOf(scene);  // explains a stall
  nlohmann::json summary = makeSummary(scene, run, &start_load);
  summary["scene_path"] = absolutePath(scene_path);
  summary["overrides"] = overrides;
  for (const std::string& w : plausibilityWarnings(scene)) summary["warnings"].push_back(w);
  addFrictionWarnings(scene, run, summary);  // self-locking, dead centre, quasi-static friction work
  for (const auto& w : summary["warnings"])  // the load's and the plausibility warnings
    if (w.is_string()) std::cerr << "rollerdyn: warning: " << w.get<std::string>() << '\n';
  const std::vector<std::string> first_estimate = addResonanceWarnings(scene, summary);  // appends to summary["warnings"]
  // The resonance verdict rests on the modal analysis; the two-mass check is its first estimate.
  for (const std::string& line :
       modes::writeResonanceVerdict(scene, summary, first_estimate, modal ? &modal->report : nullptr))
    std::cerr << (line.rfind("resonance verdict:", 0) == 0 ? "rollerdyn: " : "rollerdyn: warning: ") << line << '\n';
  if (modal) modes::writeRunModes(out_dir, modal->report, modal->spectrum, summary);
  writeSummaryAtomic(out_dir + "/summary.json", summary);
  return summary;
}

int runExitCode(const RunResult& run, const nlohmann::json& summary) {
  const std::string motion = summary.value("motion", "");
  if (motion == "stalled" || motion == "rocking") return kExitDriveDoesNotTurn;
  return run.stats.complete ? 0 : kExitRunFailed;
}

}  // namespace rollerdyn::cli
