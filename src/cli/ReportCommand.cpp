// `rollerdyn report SCENE [--set k=v]... [--out DIR]`: simulate the scene with the multibody
// model, write the outputs of `simulate` plus figures/ and ONE self-contained page
// DIR/report.html (src/report/HtmlReport.h).
#include <filesystem>
#include <future>
#include <iostream>

#include "analysis/Summary.h"
#include "cli/Commands.h"
#include "cli/ReportCommand.h"
#include "cli/RunOutputs.h"
#include "io/AtomicFile.h"
#include "modes/ModesFigures.h"
#include "modes/ModesHtml.h"
#include "report/HtmlReport.h"
#include "report/OutputDir.h"
#include "report/OutputFolder.h"
#include "report/RunFigures.h"
#include "report/SceneTable.h"
#include "scene/SceneParser.h"

namespace rollerdyn::cli {

int runReport(const SceneArgs& args, const std::string& out_dir_arg) { return runReport(args, out_dir_arg, nullptr, false); }

namespace {

// The torsional modes' and the order spectrum's figures, drawn on a thread of their own while the
// run's are (both wait mostly for gnuplot processes).
std::future<FigureSet> drawModalFigures(const RunModal& modal, const std::string& fig_dir) {
  return std::async(std::launch::async, [&modal, fig_dir] {
    FigureSet m = modes::drawModesFigures(modal.report, fig_dir);
    const FigureSet sp = modes::drawSpectrumFigures(modal.spectrum, fig_dir);
    m.figures.insert(m.figures.end(), sp.figures.begin(), sp.figures.end());
    return m;
  });
}

// What the page shows of the scene: its name, source, the command that wrote the page, its
// effects and the parameter tables.
void describeScene(const Scene& scene, const SceneArgs& args, const std::string& out_dir,
                   std::vector<SceneParameterRow> parameters, ReportContent& content) {
  content.scene_name = scene.name;
  content.scene_source = scene.source;
  content.scene_path = args.scene_path;
  content.overrides = args.overrides;
  content.effects = scene.effects();
  content.parameters = std::move(parameters);
  content.derived = derivedParameterRows(scene);
  content.command = "rollerdyn report " + args.scene_path;
  for (const std::string& o : args.overrides) content.command += " --set " + o;
  content.command += " --out " + out_dir;
}

// What the page shows of the run: its summary, figures and notes, the torsional modes and the
// run's order spectrum (a section of their own), the mechanism in motion and the time plots.
void describeRun(const Scene& scene, const RunResult& run, const nlohmann::json& summary, const RunModal& modal,
                 const FigureSet& figures, const FigureSet& modal_figures, ReportContent& content) {
  content.summary = summary;
  content.reaction_columns = run.reactions.columns;
  content.figures = figures.figures;
  content.notes = figures.notes;
  content.extra_sections_html.push_back(modes::modesHtmlSection(modal.report, modal_figures, &modal.spectrum, summary));
  for (const std::string& n : modal_figures.notes) content.notes.push_back(n);
  content.animation = mechanismFrames(scene, run.timeseries, run.reactions);
  content.time_plots = mainTimePlots(run.timeseries, run.reactions);
}

// The run's summary, the figures of both sets (so the count printed is the folder's: the trial
// read "16 figures" beside 23) and the page.
void printReport(const nlohmann::json& summary, const FigureSet& figures, const FigureSet& modal_figures,
                 const std::string& fig_dir, const std::string& page) {
  FigureSet all = figures;
  all.figures.insert(all.figures.end(), modal_figures.figures.begin(), modal_figures.figures.end());
  std::cout << summaryText(summary) << figureSetText(all, fig_dir) << "report: " << page << '\n';
}

// The run's and the modes' figures (drawn side by side), the page that shows them, and the
// console's account of both.
void writeReportPage(const Scene& scene, const RunResult& run, const nlohmann::json& summary, const RunModal& modal,
                     const std::string& out_dir, ReportContent& content, PhaseClock* clock, bool quiet) {
  namespace fs = std::filesystem;
  const std::string fig_dir = (fs::path(out_dir) / "figures").string();
  std::future<FigureSet> modes_figures = drawModalFigures(modal, fig_dir);
  const FigureSet figures = drawRunFigures(outputFolderOf(out_dir, run, summary), &scene, fig_dir);
  const FigureSet mf = modes_figures.get();
  markPhase(clock, "figures (gnuplot)");
  describeRun(scene, run, summary, modal, figures, mf, content);
  const std::string page = (fs::path(out_dir) / "report.html").string();
  writeFileAtomic(page, renderReportHtml(content));
  markPhase(clock, "animation, time plots and page");

  if (!quiet) printReport(summary, figures, mf, fig_dir, page);
}

}  // namespace

int runReport(const SceneArgs& args, const std::string& out_dir_arg, PhaseClock* clock, bool quiet) {
  const Scene scene = parseSceneFile(args.scene_path, args.overrides);
  const std::string out_dir = out_dir_arg.empty() ? defaultOutDir(scene.name) : out_dir_arg;
  prepareOutputDir(out_dir, StaleOutputs::RunFiguresAndReport);  // before the run: a bad --out fails now
  // Parameter table first: a scene that parses always gives one, and nothing is simulated for
  // nothing if it did not.
  ReportContent content;
  describeScene(scene, args, out_dir, sceneParameterRows(args.scene_path, args.overrides), content);
  markPhase(clock, "scene file and parameter table");
  const RunResult run = runWithProgress(scene, "multibody");
  markPhase(clock, "run (multibody model)");
  const RunModal modal = analyseRunModes(scene, run, /*charts=*/true, clock);  // coarse charts (12 x 8)
  const nlohmann::json summary = writeRunOutputs(scene, run, args.scene_path, out_dir, args.overrides, &modal);
  markPhase(clock, "summary and files");

  writeReportPage(scene, run, summary, modal, out_dir, content, clock, quiet);
  if (!run.stats.complete) std::cerr << "rollerdyn: " << run.stats.status << '\n';
  return runExitCode(run, summary);
}

}  // namespace rollerdyn::cli
