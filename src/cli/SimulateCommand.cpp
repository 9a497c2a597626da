// `rollerdyn simulate SCENE [--set k=v]... [--out DIR] [--model multibody|reduced] [--plot]`: run
// one model on one scene and write timeseries.csv, reactions.csv and summary.json to DIR (and
// with --plot the figures of `rollerdyn plot` to DIR/figures/).
#include <filesystem>
#include <iostream>
#include <memory>
#include <stdexcept>

#include "analysis/SizingSummary.h"
#include "analysis/StartUpSummary.h"
#include "analysis/Summary.h"
#include "cli/Commands.h"
#include "cli/RunOutputs.h"
#include "modes/ModesFigures.h"
#include "report/OutputDir.h"
#include "report/OutputFolder.h"
#include "report/RunFigures.h"
#include "scene/SceneParser.h"

namespace rollerdyn::cli {

std::atomic<bool> g_interrupted{false};

std::string defaultOutDir(const std::string& scene_name) { return "out/" + scene_name; }

std::string absolutePath(const std::string& path) {
  return std::filesystem::absolute(path).lexically_normal().string();
}

int runSimulate(const SceneArgs& args, const std::string& out_dir_arg, const std::string& model, bool plot,
                bool with_modes) {
  const Scene scene = parseSceneFile(args.scene_path, args.overrides);
  const std::string out_dir = out_dir_arg.empty() ? defaultOutDir(scene.name) : out_dir_arg;
  prepareOutputDir(out_dir, StaleOutputs::RunFiguresAndReport);  // before the run: a bad --out fails now
  const RunResult run = runWithProgress(scene, model);
  std::unique_ptr<RunModal> modal;
  if (with_modes) modal = std::make_unique<RunModal>(analyseRunModes(scene, run, /*charts=*/false));
  const nlohmann::json summary = writeRunOutputs(scene, run, args.scene_path, out_dir, args.overrides, modal.get());
  std::cout << summaryText(summary) << startUpText(summary) << sizingText(summary);
  if (modal) std::cout << modes::modesText(modal->report, modes::runStabilityNotApplicable(summary));
  std::cout << "outputs in " << out_dir << "/\n";
  if (plot) {  // figures from the tables in memory and the scene with its overrides
    std::cout << figureSetText(drawRunFigures(outputFolderOf(out_dir, run, summary), &scene, out_dir + "/figures"),
                               out_dir + "/figures");
    if (modal) {
      FigureSet f = modes::drawModesFigures(modal->report, out_dir + "/figures");
      const FigureSet sp = modes::drawSpectrumFigures(modal->spectrum, out_dir + "/figures");
      f.figures.insert(f.figures.end(), sp.figures.begin(), sp.figures.end());
      std::cout << figureSetText(f, out_dir + "/figures");
    }
  }
  if (!run.stats.complete) std::cerr << "rollerdyn: " << run.stats.status << '\n';
  return runExitCode(run, summary);
}

}  // namespace rollerdyn::cli
