// rollerdyn: drive dynamics of roller forming installations (see README.md).
#include <csignal>
#include <iostream>

#include <CLI/CLI.hpp>

#include "cli/Commands.h"
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
  cmd->add_option("scene", args.scene_path, "scene file (YAML), e.g. model/balanced-4cart.yaml")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--set", args.overrides,
                  "override a scene value, key.path=value (repeatable), e.g. --set crank.offset_deg=60")
      ->allow_extra_args(false);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace rollerdyn::cli;
  CLI::App app{"rollerdyn: drive dynamics of roller forming installations (multibody and reduced models)"};
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

  SceneArgs check_args;
  auto* check = app.add_subcommand("check", "validate a scene and list the bodies, constraints and effects it builds");
  addSceneArgs(check, check_args);
  check->footer("Example:\n  rollerdyn check model/balanced-4cart.yaml --set coupling.type=rigid");

  SceneArgs sim_args;
  std::string out_dir, model = "multibody";
  auto* simulate = app.add_subcommand("simulate", "simulate a scene; writes timeseries.csv, reactions.csv, crank_speed_extrema.csv, summary.json");
  addSceneArgs(simulate, sim_args);
  simulate->add_option("--out", out_dir, "output folder (default out/<scene name>/)");
  simulate->add_option("--model", model, "multibody (Simbody, default) or reduced (the papers' reduced-mass model)")
      ->check(oneOf({"multibody", "reduced"}));
  bool sim_plot = false;  // PlotCommand.cpp
  simulate->add_flag("--plot", sim_plot, "also draw the figures of `rollerdyn plot` into <out>/figures/");
  bool sim_modes = false;
  simulate->add_flag("--modes", sim_modes,
                     "also the torsional modes, Floquet stability and Campbell diagram of `rollerdyn modes` (no "
                     "stability charts) and the run's order spectrum: modes.json, spectrum.csv, summary.json 'modes'");
  simulate->footer(
      "Examples:\n  rollerdyn simulate model/balanced-4cart.yaml\n"
      "  rollerdyn simulate model/recuperative-2cart.yaml --set crank.offset_deg=60 --out out/dphi60\n"
      "  rollerdyn simulate model/balanced-4cart.yaml --model reduced\n"
      "  rollerdyn simulate model/balanced-4cart.yaml --plot          # + PNG/SVG figures in out/balanced-4cart/figures/");

  // plot and report (src/cli/PlotCommand.cpp, ReportCommand.cpp, src/report/)
  std::string plot_dir, plot_scene;
  std::vector<std::string> plot_overrides;
  auto* plot = app.add_subcommand("plot", "draw the figures of an output folder (simulate or compare) as PNG and SVG into DIR/figures/");
  plot->add_option("dir", plot_dir, "output folder of simulate (timeseries.csv, reactions.csv, summary.json) or compare (comparison.csv)")
      ->required()
      ->check(CLI::ExistingDirectory);
  plot->add_option("--scene", plot_scene, "scene file for the motor's Kloss curve (default: scene_path in summary.json)")
      ->check(CLI::ExistingFile);
  plot->add_option("--set", plot_overrides, "the --set overrides the run was made with, key.path=value (repeatable)")
      ->allow_extra_args(false);
  plot->footer(
      "Figures: crank speed and acceleration against crank angle (steady window) and time, coupling torque,\n"
      "motor operating point on its Kloss curve, guide reactions and rod forces per cart, twist phase\n"
      "portraits, and multibody-vs-reduced overlays when comparison.csv is there.\n"
      "Examples:\n  rollerdyn plot out/balanced-4cart\n"
      "  rollerdyn plot out/dphi60 --scene model/balanced-4cart.yaml --set motor.breakdown_torque=600\n"
      "  rollerdyn plot out/balanced-4cart/compare");
  SceneArgs report_args;
  std::string report_out;
  auto* report = app.add_subcommand("report", "simulate a scene (multibody) and write one self-contained HTML page, DIR/report.html");
  addSceneArgs(report, report_args);
  report->add_option("--out", report_out, "output folder (default out/<scene name>/)");
  report->footer(
      "Writes the outputs of simulate, figures/ and report.html: scene and source, effects, parameters,\n"
      "summary metrics, joint reactions (min/max over the steady window) and the figures embedded;\n"
      "the page needs no network. Check it renders: bash scripts/check-report.sh DIR\n"
      "Examples:\n  rollerdyn report model/balanced-4cart.yaml\n"
      "  rollerdyn report model/recuperative-2cart.yaml --set crank.offset_deg=60 --out out/dphi60");

  // compare and validate (src/cli/CompareCommand.cpp, ValidateCommand.cpp)
  SceneArgs cmp_args;
  std::string cmp_out;
  auto* compare = app.add_subcommand("compare", "run both models on a scene; writes comparison.csv and comparison.json");
  addSceneArgs(compare, cmp_args);
  compare->add_option("--out", cmp_out, "output folder (default out/<scene name>/compare/)");
  compare->footer("Example:\n  rollerdyn compare model/balanced-4cart.yaml --set rods.model=split "
                  "--set loads.guide_friction.coefficient=0 --set simulation.accuracy=1e-9");
  bool val_quick = false;
  std::string val_out = "validation";
  auto* validate = app.add_subcommand("validate", "validation suite: model equivalence, papers, analytic checks, drive sizing by hand; writes <out>/report.md; exits 1 when a claim FAILED");
  validate->add_flag("--quick", val_quick, "coarser sweeps and shorter runs (about a minute)");
  validate->add_option("--out", val_out, "output folder (default validation/)");
  bool val_modes_only = false;
  validate->add_flag("--modes-only", val_modes_only,
                     "only the checks of the torsional modes and Floquet stability (seconds); writes <out>/modes/");
  std::string val_studies;
  validate->add_option("--studies", val_studies,
                       "only write the markdown pages of a studies folder (validation/studies) from the tables "
                       "validation/studies/run.sh left there; runs no simulation");
  validate->footer("Exit status: 0 when every claim holds or is an explained gap (a published table the papers' own\n"
                   "inputs cannot reproduce, with its numbers and reason) and every equivalence case passes; 1 otherwise.\n"
                   "Examples:\n  rollerdyn validate --quick                # about a minute\n"
                   "  rollerdyn validate --out out/validation");

  // bench (src/cli/BenchCommand.cpp)
  SceneArgs bench_args;
  BenchArgs bench_opts;
  auto* bench = app.add_subcommand("bench", "accuracy vs CPU time of every integrator, cost vs carts, cost of each effect and motor model");
  addSceneArgs(bench, bench_args);
  bench->add_option("--study", bench_opts.study,
                    "integrators (default), carts, effects, reactions (with vs without joint reactions), all (these "
                    "four), motors, setup (where the time of a report and of a short run goes, median of at least 3) "
                    "or identify (the time of one identification of the coupling's c and k from a measured start)")
      ->check(oneOf({"integrators", "carts", "effects", "reactions", "all", "motors", "setup", "identify"}));
  bench->add_flag("--quick", bench_opts.quick, "fewer accuracies, 1 s runs, 1 s budget per run (integrators: under a minute)");
  bench->add_option("--budget", bench_opts.budget, "CPU seconds per run before it is recorded as a timeout");
  bench->add_option("--repeat", bench_opts.repeats, "timed repetitions per run (median reported)")->check(CLI::Range(1, 1000));
  bench->add_option("--out", bench_opts.out_dir, "output folder (default out/<scene name>/bench/)");
  bench->footer("Examples:\n  rollerdyn bench model/balanced-4cart.yaml --quick\n"
                "  rollerdyn bench model/recuperative-2cart.yaml --study all --repeat 3");

  // sweep, cam-profile, chain: the studies of the papers (src/cli/SweepCommand.cpp, ...)
  const Subcommand studies[] = {addSweepCommand(app), addCamProfileCommand(app), addChainCommand(app),
                               addOptimizeCommand(app), addMotorCommand(app), addModesCommand(app),
                               addSchemaCommand(app), addSignoffCommand(app),
                               addIdentifyCommand(app)};

  // Usage errors: exit code 2 and one line (src/cli/UsageError.h); help and version: exit 0.
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
  std::signal(SIGINT, onInterrupt);
  try {
    if (*check) return runCheck(check_args);
    for (const Subcommand& c : studies)
      if (*c.cmd) return c.run();
    if (*simulate) return runSimulate(sim_args, out_dir, model, sim_plot, sim_modes);
    if (*plot) return runPlot(plot_dir, plot_scene, plot_overrides);
    if (*report) return runReport(report_args, report_out);
    if (*bench) return runBench(bench_args, bench_opts);
    if (*compare) return runCompare(cmp_args, cmp_out);
    if (*validate) return val_studies.empty() ? runValidate(val_quick, val_out, val_modes_only) : runValidateStudies(val_studies);
  } catch (const std::exception& e) {
    std::cerr << "rollerdyn: " << e.what() << '\n';
    return kExitBadInput;
  }
  return 1;
}
