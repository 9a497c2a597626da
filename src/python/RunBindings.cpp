// simulate and compare for Python: the command line's runs (the same functions `rollerdyn
// simulate` and `rollerdyn compare` call), without the GIL, stoppable by Ctrl-C.
#include <atomic>
#include <memory>
#include <limits>

#include <pybind11/stl.h>

#include "analysis/SizingSummary.h"
#include "analysis/StartUpSummary.h"
#include "analysis/Summary.h"
#include "compare/ModelComparison.h"
#include "multibody/MultibodySimulation.h"
#include "python/Bindings.h"
#include "python/Interruptible.h"
#include "python/PyConvert.h"
#include "python/PyScene.h"
#include "reduced/ReducedModel.h"
#include "report/HtmlReport.h"
#include "report/OutputDir.h"
#include "report/OutputFolder.h"
#include "report/RunFigures.h"
#include "report/SizingSection.h"
#include "report/StartUpSection.h"
#include "scene/DidYouMean.h"
#include "modes/ModalAnalysis.h"
#include "modes/ModesFigures.h"
#include "modes/OrderSpectrum.h"
#include "modes/RunModes.h"
#include "studies/RunSummary.h"
#include "compare/RunModel.h"

namespace rollerdyn::python {

namespace {

// One finished (or interrupted) run with its summary, as `simulate` would write it.
struct RunData {
  PyScene scene;
  RunResult run;
  nlohmann::json summary;
  RunMessages messages;                             // what the CLI prints on stderr
  std::shared_ptr<const modes::RunModal> modal;     // simulate(modes=True), as `simulate --modes`
};

void checkModel(const std::string& model) {
  const std::vector<std::string> models = {"multibody", "reduced"};
  if (model != "multibody" && model != "reduced")
    throw std::invalid_argument("model: expected one of multibody, reduced, got '" + model + "'" +
                                didYouMean(model, models));
}

// The summary `simulate` writes (studies/RunSummary.h), with the modal analysis beside the run
// when `with_modes` (`simulate --modes`: no stability charts).
RunData summarized(const PyScene& scene, RunResult run, bool with_modes = false) {
  RunData d{scene, std::move(run), nullptr, {}, nullptr};
  if (with_modes) d.modal = std::make_shared<const modes::RunModal>(modes::analyseRunModes(scene.scene(), d.run, false));
  RunSummaryOptions options;
  options.scene_file = scene.file();
  options.overrides = scene.overrides();
  options.modal = d.modal.get();
  d.summary = summarizeRun(scene.scene(), d.run, options, &d.messages);
  return d;
}

struct CompareData {
  PyScene scene;
  ModelComparison comparison;
  RunData multibody, reduced;
};

// What `rollerdyn simulate --out DIR [--modes] [--plot]` writes, by the same functions; returns
// the account of the figures drawn (empty without figures).
std::string writeRun(const RunData& d, const std::string& out_dir, bool figures) {
  prepareOutputDir(out_dir, StaleOutputs::RunFiguresAndReport, "out_dir");
  writeRunFiles(out_dir, d.run, d.summary, d.modal.get());
  std::string text;
  if (figures) {
    py::gil_scoped_release release;  // gnuplot runs in child processes
    const std::string dir = out_dir + "/figures";
    text = figureSetText(drawRunFigures(outputFolderOf(out_dir, d.run, d.summary), &d.scene.scene(), dir), dir);
    if (d.modal) {
      FigureSet f = modes::drawModesFigures(d.modal->report, dir);
      const FigureSet sp = modes::drawSpectrumFigures(d.modal->spectrum, dir);
      f.figures.insert(f.figures.end(), sp.figures.begin(), sp.figures.end());
      text += figureSetText(f, dir);
    }
  }
  return text;
}

// The run's modal analysis as text ("" without one).
std::string runModesText(const RunData& d) {
  return d.modal ? modes::modesText(d.modal->report, modes::runStabilityNotApplicable(d.summary)) : std::string();
}

// The run's status and warnings.
void bindRunStatus(py::class_<RunData>& c) {
  c.def_property_readonly("scene", [](const RunData& d) { return d.scene; })
      .def_property_readonly("model", [](const RunData& d) { return d.run.model; })
      .def_property_readonly("complete", [](const RunData& d) { return d.run.stats.complete; })
      .def_property_readonly("status", [](const RunData& d) { return d.run.stats.status; })
      .def_property_readonly("run_warnings", [](const RunData& d) { return d.messages.run_warnings; })
      .def_property_readonly("resonance_warnings", [](const RunData& d) { return d.messages.resonance_warnings; })
      .def_property_readonly("resonance_verdict", [](const RunData& d) { return d.messages.resonance_verdict; });
}

// The run's modal analysis (simulate(modes=True)): its text and tables, None without one.
void bindRunModes(py::class_<RunData>& c) {
  c.def_property_readonly("has_modes", [](const RunData& d) { return d.modal != nullptr; })
      .def("modes_text", &runModesText)
      .def("frozen",
           [](const RunData& d) {
             return d.modal ? py::object(tableToPython(modes::frozenTable(d.modal->report))) : py::object(py::none());
           })
      .def("campbell",
           [](const RunData& d) {
             return d.modal && d.modal->report.campbell.applicable
                        ? py::object(tableToPython(modes::campbellTable(d.modal->report)))
                        : py::object(py::none());
           })
      .def("spectrum",
           [](const RunData& d) {
             return d.modal && d.modal->spectrum.ok ? py::object(tableToPython(modes::spectrumTable(d.modal->spectrum)))
                                                     : py::object(py::none());
           });
}

// The run's tables, summary, text and page, and its files.
void bindRunOutputs(py::class_<RunData>& c) {
  c.def("timeseries", [](const RunData& d) { return tableToPython(d.run.timeseries); })
      .def("reactions",
           [](const RunData& d) { return d.run.reactions.columns.empty() ? py::object(py::none()) : py::object(tableToPython(d.run.reactions)); })
      .def("crank_speed_extrema",
           [](const RunData& d) { return tableToPython(crankSpeedExtremaTable(d.run.crank_speed_extrema)); })
      .def("summary", [](const RunData& d) { return toPython(d.summary); })
      .def("text",
           [](const RunData& d) {
             return summaryText(d.summary) + startUpText(d.summary) + sizingText(d.summary) + runModesText(d);
           })
      .def("html",
           [](const RunData& d) {
             return runStatusHtml(d.summary) + summaryMetricsHtml(d.summary) + sizingSectionHtml(d.summary) +
                    startUpSectionHtml(d.summary) + reactionsTableHtml(d.summary, d.run.reactions.columns) +
                    (d.modal ? "<pre>" + htmlEscape(runModesText(d)) + "</pre>" : std::string());
           })
      .def("write", &writeRun, py::arg("out_dir"), py::arg("figures") = false);
}

// The run as Python sees it: its status, tables, summary, text and page, and its files.
void bindRunData(py::module_& m) {
  py::class_<RunData> c(m, "RunData");
  bindRunStatus(c);
  bindRunModes(c);
  bindRunOutputs(c);
}

// simulate: one run of a scene in memory, interruptible by Ctrl-C.
void bindSimulate(py::module_& m) {
  m.def(
      "simulate",
      [](const PyScene& scene, const std::string& model, bool with_modes) {
        checkModel(model);
        std::atomic<bool> stop{false};
        bool interrupted = false;
        RunData d = runInterruptible(
            [&scene, &model, &stop, with_modes] {
              RunControl control;
              control.interrupt = &stop;
              RunResult run = runModel(scene.scene(), model, control);
              // An interrupted run skips the modal analysis (seconds): the user asked to stop.
              return summarized(scene, std::move(run), with_modes && !stop);
            },
            stop, &interrupted);
        return py::make_tuple(std::move(d), interrupted);
      },
      py::arg("scene"), py::arg("model"), py::arg("modes") = false);
}

// compare(): both models on the same scene and their comparison, interruptible by Ctrl-C.
py::tuple compareScene(const PyScene& scene) {
  std::atomic<bool> stop{false};
  bool interrupted = false;
  CompareData c = runInterruptible(
      [&scene, &stop] {
        CompareControl control;
        control.interrupt = &stop;
        ModelComparison mc = runComparison(scene.scene(), control);
        RunData mb = summarized(scene, mc.multibody), red = summarized(scene, mc.reduced);
        return CompareData{scene, std::move(mc), std::move(mb), std::move(red)};
      },
      stop, &interrupted);
  return py::make_tuple(std::move(c), interrupted);
}

// compare: both models on the same scene, and their comparison.
void bindComparison(py::module_& m) {
  py::class_<CompareData>(m, "CompareData")
      .def_property_readonly("multibody", [](const CompareData& c) { return c.multibody; })
      .def_property_readonly("reduced", [](const CompareData& c) { return c.reduced; })
      .def("table", [](const CompareData& c) { return tableToPython(c.comparison.table); })
      .def("json", [](const CompareData& c) { return toPython(comparisonJson(c.comparison)); })
      .def("text", [](const CompareData& c) { return comparisonText(c.comparison); });

  m.def("compare", &compareScene, py::arg("scene"));
}

}  // namespace

void bindRuns(py::module_& m) {
  bindRunData(m);
  bindSimulate(m);
  bindComparison(m);
}

}  // namespace rollerdyn::python
