// `rollerdyn identify SCENE --data FILE --free KEY[,KEY...] [--bounds KEY=lo:hi]... [--noise COL=σ]...
//  [--model multibody|reduced] [--holdout F] [--global] [--set k=v]... [--out DIR]`: the scene values
// that reproduce measured signals, with their uncertainties (src/studies/Identify.h).
#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>

#include <CLI/CLI.hpp>

#include "cli/Commands.h"
#include "cli/SceneOptions.h"
#include "cli/UsageError.h"
#include "report/OutputDir.h"
#include "scene/SceneParser.h"
#include "scene/SceneSchema.h"
#include "studies/Identify.h"
#include "studies/IdentifyOutputs.h"

namespace rollerdyn::cli {

namespace {

struct IdentifyArgs {
  SceneArgs scene;
  std::string data, model = "multibody", out_dir;
  std::vector<std::string> free, bounds, noise, signals;
  double holdout = 0.3;
  double accuracy = 0;
  bool global = false;
  int max_iterations = 30;
  int threads = 2;
};

// "NAME=TEXT" split at the first '='; throws naming the option and what was expected.
std::pair<std::string, std::string> assignment(const std::string& option, const std::string& text,
                                               const std::string& expected) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
    throw std::invalid_argument("identify: " + option + ": expected " + expected + ", got '" + text + "'");
  return {text.substr(0, eq), text.substr(eq + 1)};
}

double number(const std::string& option, const std::string& text, const std::string& whole) {
  std::size_t used = 0;
  double v = NAN;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !std::isfinite(v))
    throw std::invalid_argument("identify: " + option + " '" + whole + "': expected a number, got '" + text + "'");
  return v;
}

// The items of comma-separated lists given once or more (--free a,b --free c).
std::vector<std::string> commaItems(const std::vector<std::string>& lists) {
  std::vector<std::string> items;
  for (const std::string& f : lists) {
    std::stringstream ss(f);
    for (std::string item; std::getline(ss, item, ',');)
      if (!item.empty()) items.push_back(item);
  }
  return items;
}

// --bounds KEY=LOWER:UPPER and --noise COLUMN=SIGMA.
void readBoundsAndNoise(const IdentifyArgs& a, IdentifyOptions& o) {
  for (const std::string& b : a.bounds) {
    const auto [key, spec] = assignment("--bounds", b, "KEY=LOWER:UPPER");
    const auto colon = spec.find(':');
    if (colon == std::string::npos)
      throw std::invalid_argument("identify: --bounds '" + b + "': expected KEY=LOWER:UPPER, got no ':'");
    o.bounds[key] = {number("--bounds", spec.substr(0, colon), b), number("--bounds", spec.substr(colon + 1), b)};
  }
  for (const std::string& n : a.noise) {
    const auto [column, sigma] = assignment("--noise", n, "COLUMN=SIGMA (in the column's unit)");
    o.noise[column] = number("--noise", sigma, n);
  }
}

IdentifyOptions identifyOptions(const IdentifyArgs& a) {
  IdentifyOptions o;
  o.scene_path = a.scene.scene_path;
  o.base_overrides = a.scene.overrides;
  o.free_keys = commaItems(a.free);
  o.signals = commaItems(a.signals);
  readBoundsAndNoise(a, o);
  o.model = a.model;
  o.holdout = a.holdout;
  o.global = a.global;
  o.max_iterations = a.max_iterations;
  o.threads = a.threads;
  o.accuracy = a.accuracy;
  o.interrupt = &g_interrupted;
  o.on_progress = [](const std::string& line) { std::cout << line << std::endl; };
  o.data = readMeasuredData(a.data);
  return o;
}

int runIdentifyCommand(const IdentifyArgs& a) {
  const IdentifyOptions o = identifyOptions(a);
  const Scene base = parseSceneFile(o.scene_path, o.base_overrides);  // a bad scene fails before any run
  const std::string out_dir = a.out_dir.empty() ? defaultOutDir(base.name) + "/identify" : a.out_dir;
  prepareOutputDir(out_dir);
  std::cout << "identify " << base.name << ": " << o.free_keys.size() << " keys from "
            << (o.signals.empty() ? o.data.signals.size() : o.signals.size()) << " signals of " << a.data << " (" << o.data.t.size() << " samples), " << o.model << " model\n";
  const IdentifyResult r = runIdentify(o);
  std::string plot_note;
  const auto files = writeIdentifyOutputs(o, r, out_dir, &plot_note);
  std::cout << "\n" << describeIdentify(r);
  if (!plot_note.empty()) std::cerr << "rollerdyn: figures: " << plot_note << "\n";
  std::cout << "outputs in " << out_dir << "/ (" << files.size() << " files)\n";
  return r.converged ? 0 : 4;
}

const char* const kIdentifyFooter =
      "The model runs from the scene's initial state (t = 0) to the last measured time and is interpolated "
      "linearly onto the measured times; record from rest. Weighted least squares by Levenberg-Marquardt; the "
      "uncertainties from the Jacobian at the estimate. Warnings: keys the data cannot tell apart (correlation above "
      "0.95), keys they do not determine (relative uncertainty above 50 %), estimates on a bound.\n"
      "Exit codes: 0 converged, 4 not converged (the reason is printed and in identify.json), 2 bad input.\n"
      "Example:\n"
      "  rollerdyn identify model/balanced-4cart.yaml --data start.csv --free coupling.stiffness,coupling.damping "
      "--bounds coupling.stiffness=5e4:1e6 --bounds coupling.damping=500:30000";

// How the values are fitted: the model, the holdout, the search, the runs' threads and accuracy.
void addFitOptions(CLI::App& cmd, IdentifyArgs& a) {
  cmd.add_option("--model", a.model, "multibody (default) or reduced")->check(oneOf({"multibody", "reduced"}));
  cmd.add_option("--holdout", a.holdout,
                  "fraction of the measured span at its end that is predicted, not fitted (default 0.3; 0: none)")
      ->check(CLI::Range(0.0, 0.9));
  cmd.add_flag("--global", a.global, "a global search (DIRECT-L, 30 runs per key) before the local fit");
  cmd.add_option("--max-iterations", a.max_iterations, "Levenberg-Marquardt iterations per fit (default 30)")
      ->check(CLI::Range(1, 1000));
  cmd.add_option("--threads", a.threads, "runs of one Jacobian side by side (default 2)")->check(CLI::Range(1, 64));
  cmd.add_option("--accuracy", a.accuracy,
                  "integrator accuracy of the runs (default: the scene's, at most 1e-8, so the finite differences "
                  "stay far above the integration's noise)")
      ->check(CLI::Range(1e-14, 1e-2));
}

// The measurements and what to fit to them: the data, its signals, the free keys, their bounds and
// the measurement noise.
void addMeasurementOptions(CLI::App& cmd, IdentifyArgs& args) {
  cmd.add_option("--data", args.data,
                 "measured CSV: a column t[s] and any output columns of simulate with their units, e.g. "
                 "omega_crank[rad/s], stator_current[A]")
      ->required()
      ->check(CLI::ExistingFile);
  cmd.add_option("--signals", args.signals,
                 "the measured columns to fit, COL[,COL...] (default: every column of --data but t)")
      ->allow_extra_args(false);
  cmd.add_option("--free", args.free, "scene keys to identify, KEY[,KEY...] (repeatable)")
      ->required()
      ->allow_extra_args(false);
  cmd.add_option("--bounds", args.bounds,
                 "search bounds KEY=LOWER:UPPER in the key's unit (repeatable); default: the key's range in the "
                 "scene schema where it is finite")
      ->allow_extra_args(false);
  cmd.add_option("--noise", args.noise,
                 "measurement noise COLUMN=SIGMA in the column's unit (repeatable); default: estimated from the "
                 "residuals of a first fit")
      ->allow_extra_args(false);
}

}  // namespace

Subcommand addIdentifyCommand(CLI::App& app) {
  auto args = std::make_shared<IdentifyArgs>();
  CLI::App* cmd = app.add_subcommand(
      "identify",
      "scene values (coupling stiffness and damping, friction, motor data) that reproduce measured signals, with "
      "their uncertainties; identify.json, figures");
  addSceneFile(*cmd, args->scene, "scene file (YAML)");
  addMeasurementOptions(*cmd, *args);
  addSceneOverrides(*cmd, args->scene, "override a scene value for every run, key.path=value (repeatable)");
  addFitOptions(*cmd, *args);
  cmd->add_option("--out", args->out_dir, "output folder (default out/<scene name>/identify)");
  cmd->footer(kIdentifyFooter);
  return {cmd, [args] { return runIdentifyCommand(*args); }};
}

}  // namespace rollerdyn::cli
