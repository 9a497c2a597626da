// rollerdyn: drive dynamics of roller forming installations (see README.md).
#include <csignal>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/Commands.h"
#include "cli/SceneOptions.h"
#include "cli/UsageError.h"

namespace {

void onInterrupt(int) { rollerdyn::cli::g_interrupted = true; }

// "rollerdyn 0.1 (commit 08674ee1c2d3)": CMake's project(VERSION) and the git commit at
// configure time (CMakeLists.txt), when the sources were a git checkout.
std::string versionText() {
  std::string v = std::string("rollerdyn ") + ROLLERDYN_VERSION;
  if (std::string(ROLLERDYN_GIT_COMMIT).size()) v += std::string(" (commit ") + ROLLERDYN_GIT_COMMIT + ")";
  return v;
}

void addSceneArgs(CLI::App* cmd, rollerdyn::cli::SceneArgs& args) {
  rollerdyn::cli::addSceneFile(*cmd, args);
  rollerdyn::cli::addSceneOverrides(
      *cmd, args, "override a scene value, key.path=value (repeatable), e.g. --set crank.offset_deg=60");
}

using rollerdyn::cli::Subcommand;

// The command's description, its typical session and its exit codes (rollerdyn --help).
void describeApp(CLI::App& app) {
  app.require_subcommand(1);
  app.set_version_flag("--version", versionText(), "print the version (and git commit) and exit");
  app.footer(
      "A typical session (each command has --help with examples):\n"
      "  rollerdyn check model/balanced-4cart.yaml                    validate the scene\n"
      "  rollerdyn schema coupling                                    the scene keys under coupling\n"
      "  rollerdyn simulate model/balanced-4cart.yaml --plot          -> out/balanced-4cart/ (+ figures/)\n"
      "  rollerdyn plot out/balanced-4cart                            figures of an output folder\n"
      "  rollerdyn report model/balanced-4cart.yaml --set crank.offset_deg=60 --out out/dphi60\n"
      "                                                               -> out/dphi60/report.html\n"
      "Exit codes: 0 success, 2 bad input or set-up, 3 a run failed (numerical failure, interrupted; outputs still "
      "written), 4 the drive stalls or rocks instead of turning (outputs written; the sizing checks fail), 5 signoff "
      "wrote its sheet without the PDF (Chromium missing).\n"
      "Ctrl-C stops a run at the next output row and writes what it has.");
}

Subcommand addCheckCommand(CLI::App& app) {
  auto a = std::make_shared<rollerdyn::cli::SceneArgs>();
  auto* check = app.add_subcommand("check", "validate a scene and list the bodies, constraints and effects it builds");
  addSceneArgs(check, *a);
  check->footer("Example:\n  rollerdyn check model/balanced-4cart.yaml --set coupling.type=rigid");
  return {check, [a] { return rollerdyn::cli::runCheck(*a); }};
}

Subcommand addSimulateCommand(CLI::App& app) {
  struct Args {
    rollerdyn::cli::SceneArgs scene;
    std::string out_dir, model = "multibody";
    bool plot = false;  // PlotCommand.cpp
    bool modes = false;
  };
  auto a = std::make_shared<Args>();
  auto* simulate = app.add_subcommand("simulate", "simulate a scene; writes timeseries.csv, reactions.csv, crank_speed_extrema.csv, summary.json");
  addSceneArgs(simulate, a->scene);
  simulate->add_option("--out", a->out_dir, "output folder (default out/<scene name>/)");
  simulate->add_option("--model", a->model, "multibody (Simbody, default) or reduced (the papers' reduced-mass model)")
      ->check(rollerdyn::cli::oneOf({"multibody", "reduced"}));
  simulate->add_flag("--plot", a->plot, "also draw the figures of `rollerdyn plot` into <out>/figures/");
  simulate->add_flag("--modes", a->modes,
                     "also the torsional modes, Floquet stability and Campbell diagram of `rollerdyn modes` (no "
                     "stability charts) and the run's order spectrum: modes.json, spectrum.csv, summary.json 'modes'");
  simulate->footer(
      "Examples:\n  rollerdyn simulate model/balanced-4cart.yaml\n"
      "  rollerdyn simulate model/recuperative-2cart.yaml --set crank.offset_deg=60 --out out/dphi60\n"
      "  rollerdyn simulate model/balanced-4cart.yaml --model reduced\n"
      "  rollerdyn simulate model/balanced-4cart.yaml --plot          # + PNG/SVG figures in out/balanced-4cart/figures/");
  return {simulate, [a] { return rollerdyn::cli::runSimulate(a->scene, a->out_dir, a->model, a->plot, a->modes); }};
}

// plot and report (src/cli/PlotCommand.cpp, ReportCommand.cpp, src/report/)
Subcommand addPlotCommand(CLI::App& app) {
  struct Args {
    std::string dir, scene;
    std::vector<std::string> overrides;
  };
  auto a = std::make_shared<Args>();
  auto* plot = app.add_subcommand("plot", "draw the figures of an output folder (simulate or compare) as PNG and SVG into DIR/figures/");
  plot->add_option("dir", a->dir, "output folder of simulate (timeseries.csv, reactions.csv, summary.json) or compare (comparison.csv)")
      ->required()
      ->check(CLI::ExistingDirectory);
  plot->add_option("--scene", a->scene, "scene file for the motor's Kloss curve (default: scene_path in summary.json)")
      ->check(CLI::ExistingFile);
  plot->add_option("--set", a->overrides, "the --set overrides the run was made with, key.path=value (repeatable)")
      ->allow_extra_args(false);
  plot->footer(
      "Figures: crank speed and acceleration against crank angle (steady window) and time, coupling torque,\n"
      "motor operating point on its Kloss curve, guide reactions and rod forces per cart, twist phase\n"
      "portraits, and multibody-vs-reduced overlays when comparison.csv is there.\n"
      "Examples:\n  rollerdyn plot out/balanced-4cart\n"
      "  rollerdyn plot out/dphi60 --scene model/balanced-4cart.yaml --set motor.breakdown_torque=600\n"
      "  rollerdyn plot out/balanced-4cart/compare");
  return {plot, [a] { return rollerdyn::cli::runPlot(a->dir, a->scene, a->overrides); }};
}

Subcommand addReportCommand(CLI::App& app) {
  struct Args {
    rollerdyn::cli::SceneArgs scene;
    std::string out;
  };
  auto a = std::make_shared<Args>();
  auto* report = app.add_subcommand("report", "simulate a scene (multibody) and write one self-contained HTML page, DIR/report.html");
  addSceneArgs(report, a->scene);
  report->add_option("--out", a->out, "output folder (default out/<scene name>/)");
  report->footer(
      "Writes the outputs of simulate, figures/ and report.html: scene and source, effects, parameters,\n"
      "summary metrics, joint reactions (min/max over the steady window) and the figures embedded;\n"
      "the page needs no network. Check it renders: bash scripts/check-report.sh DIR\n"
      "Examples:\n  rollerdyn report model/balanced-4cart.yaml\n"
      "  rollerdyn report model/recuperative-2cart.yaml --set crank.offset_deg=60 --out out/dphi60");
  return {report, [a] { return rollerdyn::cli::runReport(a->scene, a->out); }};
}

// compare and validate (src/cli/CompareCommand.cpp, ValidateCommand.cpp)
Subcommand addCompareCommand(CLI::App& app) {
  struct Args {
    rollerdyn::cli::SceneArgs scene;
    std::string out;
  };
  auto a = std::make_shared<Args>();
  auto* compare = app.add_subcommand("compare", "run both models on a scene; writes comparison.csv and comparison.json");
  addSceneArgs(compare, a->scene);
  compare->add_option("--out", a->out, "output folder (default out/<scene name>/compare/)");
  compare->footer("Example:\n  rollerdyn compare model/balanced-4cart.yaml --set rods.model=split "
                  "--set loads.guide_friction.coefficient=0 --set simulation.accuracy=1e-9");
  return {compare, [a] { return rollerdyn::cli::runCompare(a->scene, a->out); }};
}

Subcommand addValidateCommand(CLI::App& app) {
  struct Args {
    bool quick = false;
    std::string out = "validation";
    bool modes_only = false;
    std::string studies;
  };
  auto a = std::make_shared<Args>();
  auto* validate = app.add_subcommand("validate", "validation suite: model equivalence, papers, analytic checks, drive sizing by hand; writes <out>/report.md; exits 1 when a claim FAILED");
  validate->add_flag("--quick", a->quick, "coarser sweeps and shorter runs (about a minute)");
  validate->add_option("--out", a->out, "output folder (default validation/)");
  validate->add_flag("--modes-only", a->modes_only,
                     "only the checks of the torsional modes and Floquet stability (seconds); writes <out>/modes/");
  validate->add_option("--studies", a->studies,
                       "only write the markdown pages of a studies folder (validation/studies) from the tables "
                       "validation/studies/run.sh left there; runs no simulation");
  validate->footer("Exit status: 0 when every claim holds or is an explained gap (a published table the papers' own\n"
                   "inputs cannot reproduce, with its numbers and reason) and every equivalence case passes; 1 otherwise.\n"
                   "Examples:\n  rollerdyn validate --quick                # about a minute\n"
                   "  rollerdyn validate --out out/validation");
  return {validate, [a] {
            return a->studies.empty() ? rollerdyn::cli::runValidate(a->quick, a->out, a->modes_only)
                                      : rollerdyn::cli::runValidateStudies(a->studies);
          }};
}

// bench (src/cli/BenchCommand.cpp)
Subcommand addBenchCommand(CLI::App& app) {
  struct Args {
    rollerdyn::cli::SceneArgs scene;
    rollerdyn::cli::BenchArgs opts;
  };
  auto a = std::make_shared<Args>();
  rollerdyn::cli::BenchArgs& o = a->opts;
  auto* bench = app.add_subcommand("bench", "accuracy vs CPU time of every integrator, cost vs carts, cost of each effect and motor model");
  addSceneArgs(bench, a->scene);
  bench->add_option("--study", o.study,
                    "integrators (default), carts, effects, reactions (with vs without joint reactions), all (these "
                    "four), motors, setup (where the time of a report and of a short run goes, median of at least 3) "
                    "or identify (the time of one identification of the coupling's c and k from a measured start)")
      ->check(rollerdyn::cli::oneOf({"integrators", "carts", "effects", "reactions", "all", "motors", "setup", "identify"}));
  bench->add_flag("--quick", o.quick, "fewer accuracies, 1 s runs, 1 s budget per run (integrators: under a minute)");
  bench->add_option("--budget", o.budget, "CPU seconds per run before it is recorded as a timeout");
  bench->add_option("--repeat", o.repeats, "timed repetitions per run (median reported)")->check(CLI::Range(1, 1000));
  bench->add_option("--out", o.out_dir, "output folder (default out/<scene name>/bench/)");
  bench->footer("Examples:\n  rollerdyn bench model/balanced-4cart.yaml --quick\n"
                "  rollerdyn bench model/recuperative-2cart.yaml --study all --repeat 3");
  return {bench, [a] { return rollerdyn::cli::runBench(a->scene, a->opts); }};
}

// The arguments parsed; an exit code where parsing ends the program (help, version: 0; a usage
// error: 2 and one line, src/cli/UsageError.h), -1 where a command is to run.
int parseArguments(CLI::App& app, int argc, char** argv) {
  using namespace rollerdyn::cli;
  if (const std::string bad = checkCommandWord(app, argc, argv); !bad.empty()) return usageError(bad);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    return usageError(usageMessage(app, e));
  }
  return -1;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace rollerdyn::cli;
  CLI::App app{"rollerdyn: drive dynamics of roller forming installations (multibody and reduced models)"};
  describeApp(app);
  // In the order --help lists them; sweep ... identify: the studies of the papers and the tools
  // around a scene (src/cli/SweepCommand.cpp, ...).
  const Subcommand commands[] = {addCheckCommand(app),    addSimulateCommand(app), addPlotCommand(app),
                                 addReportCommand(app),   addCompareCommand(app),  addValidateCommand(app),
                                 addBenchCommand(app),    addSweepCommand(app),    addCamProfileCommand(app),
                                 addChainCommand(app),    addOptimizeCommand(app), addMotorCommand(app),
                                 addModesCommand(app),    addSchemaCommand(app),   addSignoffCommand(app),
                                 addIdentifyCommand(app)};
  if (const int exit_code = parseArguments(app, argc, argv); exit_code >= 0) return exit_code;
  std::signal(SIGINT, onInterrupt);
  try {
    for (const Subcommand& c : commands)
      if (*c.cmd) return c.run();
  } catch (const std::exception& e) {
    std::cerr << "rollerdyn: " << e.what() << '\n';
    return kExitBadInput;
  }
  return 1;
}
