// `rollerdyn simulate SCENE [--set k=v]... [--out DIR] [--model multibody|reduced] [--plot]`: run
// one model on one scene and write timeseries.csv, reactions.csv and summary.json to DIR (and
// with --plot the figures of `rollerdyn plot` to DIR/figures/).
#include <filesystem>
#include <iostream>
#include <stdexcept>

#include "analysis/SizingSummary.h"
#include "analysis/StartUpSummary.h"
#include "analysis/Summary.h"
#include "cli/Commands.h"
#include "cli/RunOutputs.h"
#include "reduced/ReducedModel.h"
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

int runSimulate(const SceneArgs& args, const std::string& out_dir_arg, const std::string& model, bool plot) {
  const Scene scene = parseSceneFile(args.scene_path, args.overrides);
  const std::string out_dir = out_dir_arg.empty() ? defaultOutDir(scene.name) : out_dir_arg;
  prepareOutputDir(out_dir, StaleOutputs::RunFiguresAndReport);  // before the run: a bad --out fails now
  RunResult run;
  if (model == "multibody") {
    run = runMultibodyWithProgress(scene);
  } else if (model == "reduced") {
    run = runReducedModel(scene);
  } else {
    throw std::invalid_argument("--model: expected multibody or reduced, got '" + model + "'");
  }
  const nlohmann::json summary = writeRunOutputs(scene, run, args.scene_path, out_dir);
  std::cout << summaryText(summary) << startUpText(summary) << sizingText(summary) << "outputs in " << out_dir << "/\n";
  if (plot)  // figures from the tables in memory and the scene with its overrides
    std::cout << figureSetText(drawRunFigures(outputFolderOf(out_dir, run, summary), &scene, out_dir + "/figures"),
                               out_dir + "/figures");
  if (!run.stats.complete) std::cerr << "rollerdyn: " << run.stats.status << '\n';
  return run.stats.complete ? 0 : 3;
}

}  // namespace rollerdyn::cli
