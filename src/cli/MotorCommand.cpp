// `rollerdyn motor SCENE [--set k=v]... [--out DIR]`: the scene's induction motor on its own.
// Fits the equivalent circuit to the catalogue data when the scene gives them (motor.catalogue.*),
// prints the circuit and the model's value at every catalogue point beside the catalogue's, and
// writes motor.json, motor_curves.csv, motor_catalogue.csv and the torque-slip and current-slip
// curves of every motor model against the catalogue points (PNG and SVG, gnuplot).
#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>

#include "cli/Commands.h"
#include "cli/SceneOptions.h"
#include "report/OutputDir.h"
#include "scene/SceneParser.h"
#include "studies/MotorStudy.h"

namespace rollerdyn::cli {

namespace {

struct MotorArgs {
  SceneArgs scene;
  std::string out_dir;
};

int runMotor(const MotorArgs& a) {
  const Scene scene = parseSceneFile(a.scene.scene_path, a.scene.overrides);
  const std::string out = a.out_dir.empty() ? defaultOutDir(scene.name) + "/motor" : a.out_dir;
  prepareOutputDir(out);  // before the fit: a bad --out fails now
  const MotorStudy study = studyMotor(scene, a.scene.scene_path, a.scene.overrides);
  std::cout << study.text;
  const std::string note = writeMotorStudy(out, scene, study);
  if (!note.empty()) std::cout << note << '\n';
  std::cout << "outputs in " << out << "/ (motor.json, motor_curves.csv"
            << (study.catalogue_csv.empty() ? "" : ", motor_catalogue.csv") << ", figures motor_torque_slip"
            << (study.has_machine ? ", motor_current_slip" : "") << ")\n";
  return 0;
}

}  // namespace

Subcommand addMotorCommand(CLI::App& app) {
  auto args = std::make_shared<MotorArgs>();
  CLI::App* cmd = app.add_subcommand(
      "motor",
      "the scene's induction motor: fit its equivalent circuit to the catalogue data, print the model at every "
      "catalogue point, plot the torque-slip and current-slip curves of every motor model");
  addSceneFile(*cmd, args->scene);
  addSceneOverrides(*cmd, args->scene);
  cmd->add_option("--out", args->out_dir, "output folder (default out/<scene name>/motor)");
  cmd->footer(
      "Models: Kloss formula (motor.breakdown_torque, critical slip), the dynamic Kloss characteristic (same static\n"
      "curve), the steady-state equivalent circuit and the space-phasor machine (motor.circuit.* or fitted to\n"
      "motor.catalogue.*). Circuit values are per phase of the equivalent star. See docs/motor.md.\n"
      "Examples:\n  rollerdyn motor model/balanced-4cart.yaml\n"
      "  rollerdyn motor model/energy-balanced-3cart.yaml --set motor.catalogue.cages=1 --out out/single-cage");
  return {cmd, [args] { return runMotor(*args); }};
}

}  // namespace rollerdyn::cli
