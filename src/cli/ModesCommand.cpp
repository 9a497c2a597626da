// `rollerdyn modes SCENE [--set k=v]... [--out DIR] [--damping K]... [--mark-damping K]... [--grid CxY]
//  [--speeds N] [--stiffness LO:HI] [--no-charts] [--no-multibody]`: torsional natural frequencies,
// Floquet stability of the steady motion, Campbell diagram and stability charts of a drive
// (src/modes/ModalAnalysis.h). Writes modes.json, frozen.csv, campbell.csv, stability.csv and
// figures (PNG, SVG) into DIR (default out/<scene name>/modes/).
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>

#include <CLI/CLI.hpp>

#include "cli/Commands.h"
#include "cli/SceneOptions.h"
#include "modes/ModalAnalysis.h"
#include "modes/ModesFigures.h"
#include "report/OutputDir.h"
#include "scene/SceneParser.h"

namespace rollerdyn::cli {
namespace {

struct ModesArgs {
  SceneArgs scene;
  std::string out_dir;
  std::vector<double> dampings, marked;
  std::string grid = "16x10";
  int speeds = 21;
  std::string stiffness;  // "LO:HI" [N·m/rad]
  bool no_charts = false, no_multibody = false;
};

// The charts' grid --grid CxY and stiffness range --stiffness LO:HI.
void readChartGrid(const ModesArgs& a, const Scene& scene, modes::ModesOptions& o) {
  int nc = 0, ny = 0;
  char x = 0;
  std::istringstream gs(a.grid);
  if (!(gs >> nc >> x >> ny) || x != 'x' || nc < 2 || ny < 2 || nc > 400 || ny > 400)
    throw std::invalid_argument("--grid: expected CxY with 2 ... 400 points each, e.g. 16x10, got '" + a.grid + "'");
  o.chart_c = nc;
  o.chart_y = ny;
  if (a.stiffness.empty()) return;
  double lo = 0, hi = 0;
  char colon = 0;
  std::istringstream ss(a.stiffness);
  if (!(ss >> lo >> colon >> hi) || colon != ':' || !(lo > 0) || !(hi > lo))
    throw std::invalid_argument("--stiffness: expected LO:HI in N·m/rad with 0 < LO < HI, got '" + a.stiffness + "'");
  modes::setChartStiffness(o, scene, lo, hi, "--stiffness");
}

modes::ModesOptions modesOptions(const ModesArgs& a, const Scene& scene) {
  modes::ModesOptions o;
  o.multibody = !a.no_multibody;
  o.charts = !a.no_charts;
  o.speeds = a.speeds;
  o.chart_dampings = a.dampings;
  o.marked_dampings = a.marked;
  readChartGrid(a, scene, o);
  return o;
}

int runModes(const ModesArgs& a) {
  const Scene scene = parseSceneFile(a.scene.scene_path, a.scene.overrides);
  const std::string out = a.out_dir.empty() ? defaultOutDir(scene.name) + "/modes" : a.out_dir;
  prepareOutputDir(out);
  const modes::ModesReport r = modes::analyseModes(scene, modesOptions(a, scene));
  modes::writeModesFiles(out, r);
  const FigureSet figs = modes::drawModesFigures(r, out + "/figures");
  std::cout << modes::modesText(r);
  for (const std::string& w : r.warnings) std::cerr << "rollerdyn: warning: " << w << '\n';
  for (const std::string& n : figs.notes) std::cerr << "rollerdyn: " << n << '\n';
  std::cout << "outputs in " << out << "/ (modes.json, frozen.csv, campbell.csv, stability.csv, "
            << figs.figures.size() << " figures)\n";
  return 0;
}

const char* const kModesFooter =
      "Frozen-angle modes: the drive linearized with the crank angle held, along the steady motion (both models).\n"
      "Floquet: multipliers of the steady motion linearized over one crank revolution; |mu| > 1 is unstable.\n"
      "Crank speed in the Campbell diagram and charts is varied as a frequency converter does (motor curve shifted).\n"
      "Examples:\n  rollerdyn modes model/balanced-4cart.yaml\n"
      "  rollerdyn modes model/balanced-4cart.yaml --damping 2000 --damping 8000 --mark-damping 2000 --mark-damping 8000\n"
      "  rollerdyn modes model/balanced-4cart.yaml --set carts.count=1 --set coupling.damping=0 --grid 40x24";

// The Campbell diagram's speeds and the stability charts' dampings, grid and stiffness range.
void addChartOptions(CLI::App& cmd, ModesArgs& a) {
  cmd.add_option("--damping", a.dampings,
                  "coupling damping k [N·m·s/rad] of a stiffness × speed chart (repeatable; default the scene's)")
      ->allow_extra_args(false);
  cmd.add_option("--mark-damping", a.marked, "damping k [N·m·s/rad] to mark on the stiffness × damping chart (repeatable)")
      ->allow_extra_args(false);
  cmd.add_option("--grid", a.grid, "chart points, stiffness x (speed or damping), e.g. 40x24 (default 16x10)");
  cmd.add_option("--speeds", a.speeds, "crank speeds of the Campbell diagram (default 21)")->check(CLI::Range(2, 1000));
  cmd.add_option("--stiffness", a.stiffness,
                  "stiffness range of the charts LO:HI [N·m/rad] (default: 0.05 ... 5 times the scene's c)");
  cmd.add_flag("--no-charts", a.no_charts, "leave out the stability charts (the slow part)");
  cmd.add_flag("--no-multibody", a.no_multibody, "reduced model only (no frozen-angle modes or Floquet of the multibody model)");
}

}  // namespace

Subcommand addModesCommand(CLI::App& app) {
  auto a = std::make_shared<ModesArgs>();
  CLI::App* cmd = app.add_subcommand(
      "modes", "torsional natural frequencies, Floquet stability, Campbell diagram and stability charts of a drive");
  addSceneFile(*cmd, a->scene);
  addSceneOverrides(*cmd, a->scene);
  cmd->add_option("--out", a->out_dir, "output folder (default out/<scene name>/modes/)");
  addChartOptions(*cmd, *a);
  cmd->footer(kModesFooter);
  return {cmd, [a] { return runModes(*a); }};
}

}  // namespace rollerdyn::cli
