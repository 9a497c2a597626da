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

void bindSignOff(py::module_& m) {
  m.def(
      "signoff",
      [](const PyScene& scene, const std::string& out_dir) {
        if (!out_dir.empty()) prepareOutputDir(out_dir, StaleOutputs::Keep, "out_dir");
        std::atomic<bool> stop{false};
        bool interrupted = false;
        struct Made {
          SignOffSheet sheet;
          SignOffFiles files;
        };
        const Made made = runInterruptible(
            [&scene, &stop, &out_dir] {
              RunControl control;
              control.interrupt = &stop;
              const RunResult run = runMultibodyModel(scene.scene(), control);
              const modes::RunModal modal = modes::analyseRunModes(scene.scene(), run, false);
              RunSummaryOptions options;
              options.scene_file = scene.file();
              options.overrides = scene.overrides();
              options.modal = &modal;
              const nlohmann::json summary = summarizeRun(scene.scene(), run, options);
              Made out{signOffSheetOf(summary, scene.scene().name, scene.file(), scene.overrides()), {}};
              if (!out_dir.empty()) {
                writeRunFiles(out_dir, run, summary, &modal);
                out.files = writeSignOffFiles(out.sheet, out_dir);
              }
              return out;
            },
            stop, &interrupted);
        if (interrupted) {  // a sheet of half a run signs nothing off
          PyErr_SetString(PyExc_KeyboardInterrupt, "signoff interrupted: no sheet made");
          throw py::error_already_set();
        }
        return py::make_tuple(toPython(signOffJson(made.sheet)), made.files.pdf, made.files.pdf_not_written);
      },
      py::arg("scene"), py::arg("out_dir") = "");
}

}  // namespace rollerdyn::python
