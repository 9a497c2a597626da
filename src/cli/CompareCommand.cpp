// `rollerdyn compare SCENE [--set k=v]... [--out DIR]`: run the multibody and the reduced model
// on one scene and write comparison.csv and comparison.json (src/compare/ModelComparison.h).
#include <iostream>

#include "cli/Commands.h"
#include "compare/ModelComparison.h"
#include "io/AtomicFile.h"
#include "report/OutputDir.h"
#include "scene/SceneParser.h"

namespace rollerdyn::cli {

int runCompare(const SceneArgs& args, const std::string& out_dir_arg) {
  const Scene scene = parseSceneFile(args.scene_path, args.overrides);
  const std::string out_dir = out_dir_arg.empty() ? defaultOutDir(scene.name) + "/compare" : out_dir_arg;
  prepareOutputDir(out_dir, StaleOutputs::RunFigures);  // before the runs: a bad --out fails now
  CompareControl control;
  control.interrupt = &g_interrupted;
  const ModelComparison c = runComparison(scene, control);
  writeCsvAtomic(out_dir + "/comparison.csv", c.table);
  writeFileAtomic(out_dir + "/comparison.json", comparisonJson(c).dump(2) + "\n");
  std::cout << comparisonText(c) << "outputs in " << out_dir << "/\n";
  const bool complete = c.multibody.stats.complete && c.reduced.stats.complete;
  if (!c.multibody.stats.complete) std::cerr << "rollerdyn: multibody: " << c.multibody.stats.status << '\n';
  if (!c.reduced.stats.complete) std::cerr << "rollerdyn: reduced: " << c.reduced.stats.status << '\n';
  return complete ? 0 : 3;
}

}  // namespace rollerdyn::cli
