// `rollerdyn signoff SCENE [--set k=v]... [--out DIR]`: simulate the scene (multibody) with its
// modal analysis, as `report` does, and write the sign-off sheet of every check: signoff.json,
// signoff.html and signoff.pdf (studies/SignOff.h), beside the run's own files (summary.json,
// modes.json, ...) in DIR (default out/<scene name>/signoff/).
// Exit codes: 0 the sheet was written, whatever its verdicts (the console says how many FAIL);
// 2 bad input; 3 the run failed (the sheet is written and says so); 5 the sheet was written as
// JSON and HTML but no PDF (Chromium missing or failing: the console says which).
#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>

#include "cli/Commands.h"
#include "cli/SceneOptions.h"
#include "cli/RunOutputs.h"
#include "report/OutputDir.h"
#include "scene/SceneParser.h"
#include "studies/SignOff.h"

namespace rollerdyn::cli {
namespace {

struct SignoffArgs {
  SceneArgs scene;
  std::string out_dir;
};

int runSignoff(const SignoffArgs& a) {
  const Scene scene = parseSceneFile(a.scene.scene_path, a.scene.overrides);
  const std::string out = a.out_dir.empty() ? defaultOutDir(scene.name) + "/signoff" : a.out_dir;
  prepareOutputDir(out);  // before the run: a bad --out fails now
  const RunResult run = runWithProgress(scene, "multibody");
  const RunModal modal = analyseRunModes(scene, run, /*charts=*/false);
  const nlohmann::json summary = writeRunOutputs(scene, run, a.scene.scene_path, out, a.scene.overrides, &modal);
  const SignOffSheet sheet = signOffSheetOf(summary, scene.name, a.scene.scene_path, a.scene.overrides);
  const SignOffFiles files = writeSignOffFiles(sheet, out);
  std::cout << signOffSheetText(sheet) << "written: " << files.json << ", " << files.html;
  if (!files.pdf.empty()) std::cout << ", " << files.pdf;
  std::cout << '\n';
  // A drive that stalls or rocks is a finished sheet (its checks FAIL); a run that failed is an error.
  if (runExitCode(run, summary) == kExitRunFailed) {
    std::cerr << "rollerdyn: " << run.stats.status << '\n';
    return kExitRunFailed;
  }
  if (!files.pdf_not_written.empty()) {
    std::cerr << "rollerdyn: signoff.pdf not written: " << files.pdf_not_written << " (exit code "
              << kExitSignOffWithoutPdf << ")\n";
    return kExitSignOffWithoutPdf;
  }
  return 0;
}

}  // namespace

Subcommand addSignoffCommand(CLI::App& app) {
  auto a = std::make_shared<SignoffArgs>();
  CLI::App* cmd = app.add_subcommand(
      "signoff", "the sign-off sheet of a drive: every check with value, limit, method and verdict; writes "
                 "signoff.json, signoff.html, signoff.pdf");
  addSceneFile(*cmd, a->scene);
  addSceneOverrides(*cmd, a->scene);
  cmd->add_option("--out", a->out_dir, "output folder (default out/<scene name>/signoff/)");
  cmd->footer(
      "Simulates the scene (multibody) with its modal analysis and writes the run's files and the sheet: the scene\n"
      "file with the SHA-256 of its text, the overrides, the tool's version and the date; every check (drive sizing,\n"
      "coupling after DIN 740-2, fatigue, separation margins after API 617/684) with value, limit, method, window,\n"
      "verdict and what it rests on; pass / FAIL / n/a counts; empty fields for the reviewer's name, date, signature.\n"
      "The PDF is printed by headless Chromium (Debian package chromium).\n"
      "Exit codes: 0 written (also with FAILs), 2 bad input, 3 the run failed (sheet written, marked), 5 written\n"
      "without the PDF (Chromium missing or failing).\n"
      "Examples:\n  rollerdyn signoff model/balanced-4cart.yaml\n"
      "  rollerdyn signoff model/recuperative-2cart.yaml --set crank.offset_deg=60 --out out/dphi60-signoff");
  return {cmd, [a] { return runSignoff(*a); }};
}

}  // namespace rollerdyn::cli
