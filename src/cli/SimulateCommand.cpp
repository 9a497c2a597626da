// `rollerdyn simulate SCENE [--set k=v]... [--out DIR] [--model multibody|reduced]`: run one
// model on one scene and write timeseries.csv, reactions.csv and summary.json to DIR.
#include <unistd.h>

#include <cstdio>
#include <iostream>
#include <stdexcept>

#include "analysis/Summary.h"
#include "cli/Commands.h"
#include "io/AtomicFile.h"
#include "multibody/MultibodySimulation.h"
#include "reduced/ReducedModel.h"
#include "scene/SceneParser.h"

namespace rollerdyn::cli {

std::atomic<bool> g_interrupted{false};

std::string defaultOutDir(const std::string& scene_name) { return "out/" + scene_name; }

namespace {

// Progress on a terminal only: share done, speed as a multiple of real time. Silent otherwise,
// so logs and CI output stay clean.
class Progress {
 public:
  Progress() : enabled_(::isatty(STDERR_FILENO) == 1), cpu0_(std::clock()) {}
  void operator()(double t, double t_end) {
    if (!enabled_) return;
    const double cpu = double(std::clock() - cpu0_) / CLOCKS_PER_SEC;
    if (cpu - last_ < 0.2 && t < t_end) return;
    last_ = cpu;
    const double speed = cpu > 0 ? t / cpu : 0;
    const double left = speed > 0 ? (t_end - t) / speed : 0;
    std::fprintf(stderr, "\r  %5.1f %%  t = %.3f s  %.1fx real time  %.0f s left   ", 100.0 * t / t_end, t,
                 speed, left);
    if (t >= t_end) std::fprintf(stderr, "\n");
  }
  ~Progress() {
    if (enabled_ && last_ >= 0) std::fprintf(stderr, "\n");
  }

 private:
  bool enabled_;
  std::clock_t cpu0_;
  double last_ = -1;
};

}  // namespace

int runSimulate(const SceneArgs& args, const std::string& out_dir_arg, const std::string& model) {
  const Scene scene = parseSceneFile(args.scene_path, args.overrides);
  const std::string out_dir = out_dir_arg.empty() ? defaultOutDir(scene.name) : out_dir_arg;
  RunResult run;
  if (model == "multibody") {
    Progress progress;
    RunControl control;
    control.interrupt = &g_interrupted;
    control.progress = [&progress](double t, double t_end) { progress(t, t_end); };
    run = runMultibodyModel(scene, control);
  } else if (model == "reduced") {
    run = runReducedModel(scene);
  } else {
    throw std::invalid_argument("--model: expected multibody or reduced, got '" + model + "'");
  }
  writeCsvAtomic(out_dir + "/timeseries.csv", run.timeseries);
  writeCsvAtomic(out_dir + "/reactions.csv", run.reactions);
  const auto summary = makeSummary(scene, run);
  writeSummaryAtomic(out_dir + "/summary.json", summary);
  std::cout << summaryText(summary) << "outputs in " << out_dir << "/\n";
  if (!run.stats.complete) std::cerr << "rollerdyn: " << run.stats.status << '\n';
  return run.stats.complete ? 0 : 3;
}

}  // namespace rollerdyn::cli
