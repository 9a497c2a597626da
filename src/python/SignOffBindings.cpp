// signoff for Python: the sheet `rollerdyn signoff` writes (studies/SignOff.h), from the same run,
// modal analysis and summary, without the GIL and stoppable by Ctrl-C.
#include <atomic>

#include <pybind11/stl.h>

#include "multibody/MultibodySimulation.h"
#include "modes/RunModes.h"
#include "python/Bindings.h"
#include "python/Interruptible.h"
#include "python/PyConvert.h"
#include "python/PyScene.h"
#include "report/OutputDir.h"
#include "studies/RunSummary.h"
#include "studies/SignOff.h"

namespace rollerdyn::python {

namespace {

// The sheet and, with an output folder, the files written.
struct SignOffMade {
  SignOffSheet sheet;
  SignOffFiles files;
};

// The run, its modal analysis and summary as `rollerdyn signoff` makes them, and the sheet from them;
// with out_dir the run's files and the sheet's. `stop`: Ctrl-C.
SignOffMade makeSignOff(const PyScene& scene, const std::string& out_dir, std::atomic<bool>& stop) {
  RunControl control;
  control.interrupt = &stop;
  const RunResult run = runMultibodyModel(scene.scene(), control);
  const modes::RunModal modal = modes::analyseRunModes(scene.scene(), run, false);
  RunSummaryOptions options;
  options.scene_file = scene.file();
  options.overrides = scene.overrides();
  options.modal = &modal;
  const nlohmann::json summary = summarizeRun(scene.scene(), run, options);
  SignOffMade out{signOffSheetOf(summary, scene.scene().name, scene.file(), scene.overrides()), {}};
  if (!out_dir.empty()) {
    writeRunFiles(out_dir, run, summary, &modal);
    out.files = writeSignOffFiles(out.sheet, out_dir);
  }
  return out;
}

// signoff(): the sheet's json, the PDF's path and why it was not written, without the GIL.
py::tuple signOff(const PyScene& scene, const std::string& out_dir) {
  if (!out_dir.empty()) prepareOutputDir(out_dir, StaleOutputs::Keep, "out_dir");
  std::atomic<bool> stop{false};
  bool interrupted = false;
  const SignOffMade made =
      runInterruptible([&scene, &stop, &out_dir] { return makeSignOff(scene, out_dir, stop); }, stop, &interrupted);
  if (interrupted) {  // a sheet of half a run signs nothing off
    PyErr_SetString(PyExc_KeyboardInterrupt, "signoff interrupted: no sheet made");
    throw py::error_already_set();
  }
  return py::make_tuple(toPython(signOffJson(made.sheet)), made.files.pdf, made.files.pdf_not_written);
}

}  // namespace

void bindSignOff(py::module_& m) { m.def("signoff", &signOff, py::arg("scene"), py::arg("out_dir") = ""); }

}  // namespace rollerdyn::python
