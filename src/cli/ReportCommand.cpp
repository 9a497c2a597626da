// `rollerdyn report SCENE [--set k=v]... [--out DIR]`: simulate the scene with the multibody
// model, write the outputs of `simulate` plus figures/ and ONE self-contained page
// DIR/report.html (src/report/HtmlReport.h).
#include <filesystem>
#include <iostream>

#include "analysis/Summary.h"
#include "cli/Commands.h"
#include "cli/RunOutputs.h"
#include "io/AtomicFile.h"
#include "modes/ModesFigures.h"
#include "report/HtmlReport.h"
#include "report/OutputDir.h"
#include "report/OutputFolder.h"
#include "report/RunFigures.h"
#include "report/SceneTable.h"
#include "scene/SceneParser.h"

namespace rollerdyn::cli {

int runReport(const SceneArgs& args, const std::string& out_dir_arg) {
  namespace fs = std::filesystem;
  const Scene scene = parseSceneFile(args.scene_path, args.overrides);
  const std::string out_dir = out_dir_arg.empty() ? defaultOutDir(scene.name) : out_dir_arg;
  prepareOutputDir(out_dir, StaleOutputs::RunFiguresAndReport);  // before the run: a bad --out fails now
  // Parameter table first: a scene that parses always gives one, and nothing is simulated for
  // nothing if it did not.
  const std::vector<SceneParameterRow> parameters = sceneParameterRows(args.scene_path, args.overrides);

  const RunResult run = runMultibodyWithProgress(scene);
  const RunModal modal = analyseRunModes(scene, run, /*charts=*/true);  // coarse charts (12 x 8)
  const nlohmann::json summary = writeRunOutputs(scene, run, args.scene_path, out_dir, args.overrides, &modal);

  const OutputFolder folder = outputFolderOf(out_dir, run, summary);
  const FigureSet figures = drawRunFigures(folder, &scene, (fs::path(out_dir) / "figures").string());

  ReportContent content;
  content.scene_name = scene.name;
  content.scene_source = scene.source;
  content.scene_path = args.scene_path;
  content.overrides = args.overrides;
  content.effects = scene.effects();
  content.parameters = parameters;
  content.derived = derivedParameterRows(scene);
  content.summary = summary;
  content.reaction_columns = run.reactions.columns;
  content.figures = figures.figures;
  content.notes = figures.notes;
  content.command = "rollerdyn report " + args.scene_path;
  for (const std::string& o : args.overrides) content.command += " --set " + o;
  content.command += " --out " + out_dir;
  FigureSet mf;
  {  // torsional modes and the run's order spectrum: figures and a section of their own
    mf = modes::drawModesFigures(modal.report, (fs::path(out_dir) / "figures").string());
    const FigureSet sp = modes::drawSpectrumFigures(modal.spectrum, (fs::path(out_dir) / "figures").string());
    mf.figures.insert(mf.figures.end(), sp.figures.begin(), sp.figures.end());
    content.extra_sections_html.push_back(modes::modesHtmlSection(modal.report, mf, &modal.spectrum, summary));
    for (const std::string& n : mf.notes) content.notes.push_back(n);
  }
  content.animation = mechanismFrames(scene, run.timeseries, run.reactions);
  content.time_plots = mainTimePlots(run.timeseries, run.reactions);
  const std::string page = (fs::path(out_dir) / "report.html").string();
  writeFileAtomic(page, renderReportHtml(content));

  // Both sets, so the count printed is the folder's (the trial read "16 figures" beside 23).
  FigureSet all = figures;
  all.figures.insert(all.figures.end(), mf.figures.begin(), mf.figures.end());
  std::cout << summaryText(summary) << figureSetText(all, (fs::path(out_dir) / "figures").string())
            << "report: " << page << '\n';
  if (!run.stats.complete) std::cerr << "rollerdyn: " << run.stats.status << '\n';
  return runExitCode(run, summary);
}

}  // namespace rollerdyn::cli
