// The subcommands of the `rollerdyn` command line. Each returns the process exit code and
// throws for bad input (main() turns any exception into a one-line reason and exit code 2).
#pragma once

#include <atomic>
#include <functional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace rollerdyn::cli {

// Options shared by the commands that read a scene.
struct SceneArgs {
  std::string scene_path;              // scene file (YAML)
  std::vector<std::string> overrides;  // --set key.path=value, in order
};

// Set by the SIGINT handler; long runs stop at the next output row and keep what they have.
extern std::atomic<bool> g_interrupted;

int runCheck(const SceneArgs& args);
int runSimulate(const SceneArgs& args, const std::string& out_dir, const std::string& model,
                bool plot = false,         // plot: also draw the figures (as `rollerdyn plot`)
                bool with_modes = false);  // with_modes: the torsional modes of `rollerdyn modes` too
int runCompare(const SceneArgs& args, const std::string& out_dir);  // CompareCommand.cpp
int runValidate(bool quick, const std::string& out_dir, bool modes_only = false);  // ValidateCommand.cpp
int runValidateStudies(const std::string& dir);                    // ValidateCommand.cpp

// `rollerdyn bench` options (BenchCommand.cpp, src/bench/BenchStudies.h).
struct BenchArgs {
  std::string study = "integrators";  // integrators | carts | effects | all
  bool quick = false;                 // fewer accuracies, shorter runs (about a minute)
  double budget = 0;                  // CPU seconds per run; 0: 20 (quick: 1)
  int repeats = 1;                    // timed repetitions per run, median reported
  std::string out_dir;                // default out/<scene name>/bench/
};
int runBench(const SceneArgs& args, const BenchArgs& bench);  // BenchCommand.cpp

// `rollerdyn plot DIR` (PlotCommand.cpp): figures of an output folder into DIR/figures/; the
// Kloss curve's motor data from --scene FILE (+ --set) or summary.json's scene_path.
int runPlot(const std::string& dir, const std::string& scene_path, const std::vector<std::string>& overrides);
// `rollerdyn report SCENE` (ReportCommand.cpp): simulate, figures and DIR/report.html.
int runReport(const SceneArgs& args, const std::string& out_dir);

// Subcommands that register themselves (studies): the parsed subcommand, and what to
// run when it was given. Their options live in the closure.
struct Subcommand {
  CLI::App* cmd;
  std::function<int()> run;
};
Subcommand addSweepCommand(CLI::App& app);       // SweepCommand.cpp: `rollerdyn sweep`
Subcommand addCamProfileCommand(CLI::App& app);  // CamProfileCommand.cpp: `rollerdyn cam-profile`
Subcommand addChainCommand(CLI::App& app);       // ChainCommand.cpp: `rollerdyn chain`
Subcommand addOptimizeCommand(CLI::App& app);    // OptimizeCommand.cpp: `rollerdyn optimize`
Subcommand addMotorCommand(CLI::App& app);       // MotorCommand.cpp: `rollerdyn motor`
Subcommand addModesCommand(CLI::App& app);       // ModesCommand.cpp: `rollerdyn modes`
Subcommand addSchemaCommand(CLI::App& app);      // SchemaCommand.cpp: `rollerdyn schema`
Subcommand addSignoffCommand(CLI::App& app);     // SignoffCommand.cpp: `rollerdyn signoff`
Subcommand addIdentifyCommand(CLI::App& app);    // IdentifyCommand.cpp: `rollerdyn identify`

// out/<scene name>/ unless the user named a folder.
std::string defaultOutDir(const std::string& scene_name);
// `path` made absolute and normalised (summary.json's scene_path, readable from any folder).
std::string absolutePath(const std::string& path);

}  // namespace rollerdyn::cli
