// `rollerdyn bench SCENE [--set k=v]... [--study integrators|carts|effects|reactions|all|motors] [--quick]
//  [--budget S] [--repeat N] [--out DIR]`: accuracy vs CPU time of every integrator of both
// models, cost vs number of carts, cost of each effect (src/bench/BenchStudies.h).
#include <iostream>
#include <stdexcept>

#include "bench/BenchStudies.h"
#include "cli/Commands.h"
#include "report/OutputDir.h"

namespace rollerdyn::cli {

int runBench(const SceneArgs& args, const BenchArgs& bench) {
  const bench::SceneSource source{args.scene_path, args.overrides};
  const Scene scene = source.load();  // validates the scene (and the overrides) up front
  const std::string out_dir = bench.out_dir.empty() ? defaultOutDir(scene.name) + "/bench" : bench.out_dir;
  prepareOutputDir(out_dir);  // before the runs: a bad --out fails now

  bench::BenchOptions opt;
  opt.quick = bench.quick;
  opt.budget = bench.budget > 0 ? bench.budget : (bench.quick ? 1.0 : 20.0);
  opt.repeats = bench.repeats;
  opt.interrupt = &g_interrupted;
  opt.log = [](const std::string& line) { std::cerr << line << '\n'; };

  const std::string& study = bench.study;
  if (study != "integrators" && study != "carts" && study != "effects" && study != "reactions" && study != "motors" &&
      study != "all")
    throw std::invalid_argument("--study: expected integrators, carts, effects, reactions, motors or all, got '" + study +
                                "'");
  std::vector<std::string> written;
  auto add = [&written](const std::vector<std::string>& w) { written.insert(written.end(), w.begin(), w.end()); };
  if (study == "integrators" || study == "all")
    add(bench::writeIntegratorStudy(out_dir, bench::benchScene(scene, opt), bench::runIntegratorStudy(source, opt), opt));
  if ((study == "carts" || study == "all") && !g_interrupted)
    add(bench::writeCartsStudy(out_dir, scene, bench::runCartsStudy(source, opt), opt));
  if ((study == "effects" || study == "all") && !g_interrupted)
    add(bench::writeEffectsStudy(out_dir, scene, bench::runEffectsStudy(source, opt), opt));
  if (study == "motors" && !g_interrupted)  // not part of all: its own table
    add(bench::writeMotorsStudy(out_dir, scene, bench::runMotorsStudy(source, opt), opt));
  if ((study == "reactions" || study == "all") && !g_interrupted)
    add(bench::writeReactionsStudy(out_dir, scene, bench::runReactionsStudy(source, opt), opt));

  for (const std::string& w : written) std::cout << w << '\n';
  if (g_interrupted) {
    std::cerr << "rollerdyn: bench interrupted; the files above hold the runs finished so far\n";
    return 3;
  }
  return 0;
}

}  // namespace rollerdyn::cli
