// `rollerdyn bench SCENE [--set k=v]... [--study integrators|carts|effects|reactions|all|motors|setup|identify] [--quick]
//  [--budget S] [--repeat N] [--out DIR]`: accuracy vs CPU time of every integrator of both
// models, cost vs number of carts, cost of each effect (src/bench/BenchStudies.h).
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <thread>

#include <unistd.h>

#include "bench/BenchStudies.h"
#include "bench/SetupStudy.h"
#include "cli/Commands.h"
#include "cli/ReportCommand.h"
#include "cli/RunOutputs.h"
#include "multibody/MultibodySimulation.h"
#include "report/OutputDir.h"
#include "scene/SceneParser.h"
#include "studies/IdentifyBench.h"

namespace rollerdyn::cli {
namespace {

// The processors and the load while the study ran (its times depend on both).
std::string machineLine() {
  std::string model, load;
  std::ifstream cpu("/proc/cpuinfo");
  for (std::string line; model.empty() && std::getline(cpu, line);)
    if (line.rfind("model name", 0) == 0) model = line.substr(line.find(':') + 2);
  std::ifstream("/proc/loadavg") >> load;
  return std::to_string(std::thread::hardware_concurrency()) + " processors (" + (model.empty() ? "?" : model) +
         "), load average over the last minute " + (load.empty() ? "?" : load) + " when timed";
}

// The executable started anew.
bench::SetupSample timeProcessStart(const std::string& self) {
  PhaseClock clock;
  if (std::system(("'" + self + "' --version >/dev/null 2>&1").c_str()) != 0)
    throw std::runtime_error("bench --study setup: could not start rollerdyn --version");
  clock.mark("rollerdyn --version (exec, shared libraries, static initialisation)");
  return {"process start", clock.phases()};
}

// A short run as `simulate` makes it, without the console's progress line.
bench::SetupSample timeShortRun(const SceneArgs& args, const std::string& run_dir) {
  PhaseClock clock;
  std::vector<std::string> sets = args.overrides;
  std::ostringstream t_end;
  t_end << "simulation.t_end=" << bench::kSetupShortRunEnd;
  sets.push_back(t_end.str());
  const Scene scene = parseSceneFile(args.scene_path, sets);
  prepareOutputDir(run_dir, StaleOutputs::RunFiguresAndReport);
  clock.mark("scene file");
  const RunResult run = runMultibodyModel(scene);
  clock.mark("multibody model: set-up and integration");
  const nlohmann::json summary = writeRunOutputs(scene, run, args.scene_path, run_dir, sets);
  clock.mark("summary and files");
  std::vector<PhaseTime> phases = clock.phases();
  phases.insert(phases.begin() + 2, PhaseTime{"of which the integration (its own CPU time)", NAN,
                                              run.stats.cpu_seconds, 0.0});
  return {"short run", phases};
}

bench::SetupSample timeReport(const SceneArgs& args, const std::string& report_dir) {
  PhaseClock clock;
  runReport(args, report_dir, &clock, /*quiet=*/true);
  return {"report", clock.phases()};
}

// `rollerdyn bench --study setup`: each repetition times the process start, a short run and a
// report of the scene (bench/SetupStudy.h); their files go to a temporary folder, removed after.
std::vector<std::string> runSetupStudy(const SceneArgs& args, const std::string& out_dir, int repeats) {
  namespace fs = std::filesystem;
  std::vector<bench::SetupSample> samples;
  const fs::path tmp = fs::temp_directory_path() / ("rollerdyn-setup-" + std::to_string(::getpid()));
  fs::create_directories(tmp);
  const std::string self = fs::read_symlink("/proc/self/exe").string();  // this executable
  for (int k = 0; k < repeats && !g_interrupted; ++k) {
    samples.push_back(timeProcessStart(self));
    samples.push_back(timeShortRun(args, (tmp / "run").string()));
    samples.push_back(timeReport(args, (tmp / "report").string()));
    std::cerr << "[setup " << k + 1 << "/" << repeats << "] timed\n";
  }
  std::error_code ec;
  fs::remove_all(tmp, ec);
  const Scene scene = parseSceneFile(args.scene_path, args.overrides);
  return bench::writeSetupStudy(out_dir, scene.name, bench::setupRows(samples), machineLine());
}

bench::BenchOptions benchOptions(const BenchArgs& bench) {
  bench::BenchOptions opt;
  opt.quick = bench.quick;
  opt.budget = bench.budget > 0 ? bench.budget : (bench.quick ? 1.0 : 20.0);
  opt.repeats = bench.repeats;
  opt.interrupt = &g_interrupted;
  opt.log = [](const std::string& line) { std::cerr << line << '\n'; };
  return opt;
}

// The studies --study names, in the order they run; the files each wrote.
std::vector<std::string> runStudies(const SceneArgs& args, const BenchArgs& bench, const Scene& scene,
                                    const std::string& out_dir, const bench::BenchOptions& opt) {
  const bench::SceneSource source{args.scene_path, args.overrides};
  const std::string& study = bench.study;
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
  if (study == "setup")  // not part of all: timings of the whole program, not of the integrators
    add(runSetupStudy(args, out_dir, std::max(3, bench.repeats)));
  if (study == "identify")  // not part of all: the cost of a whole identification, many runs
    add(writeIdentifyBench(out_dir, scene.name,
                           runIdentifyBench(args.scene_path, args.overrides, std::max(1, bench.repeats), &g_interrupted, opt.log),
                           machineLine()));
  if ((study == "reactions" || study == "all") && !g_interrupted)
    add(bench::writeReactionsStudy(out_dir, scene, bench::runReactionsStudy(source, opt), opt));
  return written;
}

}  // namespace

int runBench(const SceneArgs& args, const BenchArgs& bench) {
  const bench::SceneSource source{args.scene_path, args.overrides};
  const Scene scene = source.load();  // validates the scene (and the overrides) up front
  const std::string out_dir = bench.out_dir.empty() ? defaultOutDir(scene.name) + "/bench" : bench.out_dir;
  prepareOutputDir(out_dir);  // before the runs: a bad --out fails now
  const bench::BenchOptions opt = benchOptions(bench);
  const std::string& study = bench.study;
  if (study != "integrators" && study != "carts" && study != "effects" && study != "reactions" && study != "motors" &&
      study != "all" && study != "setup" && study != "identify")
    throw std::invalid_argument(
        "--study: expected integrators, carts, effects, reactions, motors, setup, identify or all, got '" + study + "'");
  for (const std::string& w : runStudies(args, bench, scene, out_dir, opt)) std::cout << w << '\n';
  if (g_interrupted) {
    std::cerr << "rollerdyn: bench interrupted; the files above hold the runs finished so far\n";
    return 3;
  }
  return 0;
}

}  // namespace rollerdyn::cli
