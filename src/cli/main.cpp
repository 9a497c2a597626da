// rollerdyn: drive dynamics of roller forming installations (see README.md).
#include <csignal>
#include <iostream>

#include <CLI/CLI.hpp>

#include "cli/Commands.h"

namespace {

void onInterrupt(int) { rollerdyn::cli::g_interrupted = true; }

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

  SceneArgs check_args;
  auto* check = app.add_subcommand("check", "validate a scene and list the bodies, constraints and effects it builds");
  addSceneArgs(check, check_args);
  check->footer("Example:\n  rollerdyn check model/balanced-4cart.yaml --set coupling.type=rigid");

  SceneArgs sim_args;
  std::string out_dir, model = "multibody";
  auto* simulate = app.add_subcommand("simulate", "simulate a scene; writes timeseries.csv, reactions.csv, summary.json");
  addSceneArgs(simulate, sim_args);
  simulate->add_option("--out", out_dir, "output folder (default out/<scene name>/)");
  simulate->add_option("--model", model, "multibody (Simbody, default) or reduced (the papers' reduced-mass model)")
      ->check(CLI::IsMember({"multibody", "reduced"}));
  simulate->footer(
      "Examples:\n  rollerdyn simulate model/balanced-4cart.yaml\n"
      "  rollerdyn simulate model/recuperative-2cart.yaml --set crank.offset_deg=60 --out out/dphi60\n"
      "  rollerdyn simulate model/balanced-4cart.yaml --model reduced");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  std::signal(SIGINT, onInterrupt);
  try {
    if (*check) return runCheck(check_args);
    if (*simulate) return runSimulate(sim_args, out_dir, model);
  } catch (const std::exception& e) {
    std::cerr << "rollerdyn: " << e.what() << '\n';
    return 2;
  }
  return 1;
}
