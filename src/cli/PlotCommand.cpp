// `rollerdyn plot DIR [--scene FILE] [--set k=v]...`: the figures of an output folder of
// simulate (timeseries.csv, reactions.csv, summary.json) and/or compare (comparison.csv), as PNG
// and SVG in DIR/figures/ (src/report/RunFigures.h).
#include <filesystem>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <vector>

#include "cli/Commands.h"
#include "report/OutputDir.h"
#include "report/OutputFolder.h"
#include "report/RunFigures.h"
#include "scene/SceneParser.h"

namespace rollerdyn::cli {

namespace {

// The scene as the run had it: the file plus the run's own --set (recorded in summary.json), then
// the user's. Without them a run made with motor.enabled=false or another motor law was drawn
// against the file's motor curve ("was the run made with other motor data?"). Null, with a note,
// when the file no longer parses and the user gave no --set.
std::unique_ptr<Scene> sceneOfTheRun(const OutputFolder& folder, const std::string& scene_path,
                                     const std::vector<std::string>& overrides) {
  std::vector<std::string> all;
  if (folder.summary.contains("overrides") && folder.summary["overrides"].is_array())
    for (const auto& o : folder.summary["overrides"])
      if (o.is_string()) all.push_back(o.get<std::string>());
  all.insert(all.end(), overrides.begin(), overrides.end());
  try {
    return std::make_unique<Scene>(parseSceneFile(scene_path, all));
  } catch (const SceneError& e) {
    if (!overrides.empty()) throw;  // the user's --set is wrong
    std::cerr << "rollerdyn plot: note: scene '" << scene_path
              << "' named in summary.json no longer parses; pass --scene FILE (" << e.what() << ")\n";
  }
  return nullptr;
}

// The Kloss curve needs the motor data: --scene, else the scene_path summary.json records.
std::unique_ptr<Scene> plotScene(const OutputFolder& folder, const std::string& scene_arg,
                                 const std::vector<std::string>& overrides) {
  std::string scene_path = scene_arg;
  if (scene_path.empty() && folder.has_summary && folder.summary.contains("scene_path") &&
      folder.summary["scene_path"].is_string())
    scene_path = folder.summary["scene_path"].get<std::string>();
  if (!scene_arg.empty()) return std::make_unique<Scene>(parseSceneFile(scene_path, overrides));  // the user's to fix
  if (!scene_path.empty() && std::filesystem::exists(scene_path)) return sceneOfTheRun(folder, scene_path, overrides);
  if (!scene_path.empty())
    std::cerr << "rollerdyn plot: note: scene '" << scene_path
              << "' named in summary.json is not found from here; pass --scene FILE\n";
  return nullptr;
}

}  // namespace

int runPlot(const std::string& dir, const std::string& scene_arg, const std::vector<std::string>& overrides) {
  const OutputFolder folder = readOutputFolder(dir);
  const std::string fig_dir = (std::filesystem::path(dir) / "figures").string();
  prepareOutputDir(fig_dir, StaleOutputs::Keep, "figures folder");  // before drawing; drawing removes stale figures
  const std::unique_ptr<Scene> scene = plotScene(folder, scene_arg, overrides);
  if (!scene && !overrides.empty())
    throw std::invalid_argument("--set needs the scene file: pass --scene FILE");
  const FigureSet set = drawRunFigures(folder, scene.get(), fig_dir);
  std::cout << figureSetText(set, fig_dir);
  if (set.figures.empty()) {
    std::cerr << "rollerdyn plot: nothing to draw in '" << dir << "'\n";
    return 2;
  }
  return 0;
}

}  // namespace rollerdyn::cli
