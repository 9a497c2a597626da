// The scene's drive and motor on their own, for Python: `rollerdyn modes` (torsional modes,
// Floquet stability, Campbell diagram, stability charts; modes/ModalAnalysis.h) and `rollerdyn
// motor` (the equivalent circuit fitted to the catalogue, the model at every catalogue point,
// the steady torque-slip curves; studies/MotorStudy.h), by the same functions, without the GIL.
#include <memory>
#include <optional>

#include <pybind11/stl.h>

#include "modes/ModalAnalysis.h"
#include "modes/ModesFigures.h"
#include "python/Bindings.h"
#include "python/PyConvert.h"
#include "python/PyScene.h"
#include "report/OutputDir.h"
#include "report/RunFigures.h"
#include "studies/MotorStudy.h"

namespace rollerdyn::python {

namespace {

struct ModesData {
  PyScene scene;
  std::shared_ptr<const modes::ModesReport> report;
};

struct MotorData {
  PyScene scene;
  std::shared_ptr<const MotorStudy> study;
};

// ModesData.write: what `rollerdyn modes --out DIR` writes, by the same functions.
std::string writeModes(const ModesData& d, const std::string& out_dir, bool figures) {
  prepareOutputDir(out_dir, StaleOutputs::Keep, "out_dir");
  modes::writeModesFiles(out_dir, *d.report);
  if (!figures) return std::string();
  py::gil_scoped_release release;  // gnuplot runs in child processes
  return figureSetText(modes::drawModesFigures(*d.report, out_dir + "/figures"), out_dir + "/figures");
}

// modes(): the options of `rollerdyn modes`, checked as the command line checks them; the
// analysis runs without the GIL.
ModesData analyseSceneModes(const PyScene& scene, const std::vector<double>& dampings,
                            const std::vector<double>& marked, int grid_c, int grid_y, int speeds,
                            std::optional<std::pair<double, double>> stiffness, bool charts, bool multibody) {
  modes::ModesOptions o;
  o.multibody = multibody;
  o.charts = charts;
  o.speeds = speeds;
  o.chart_dampings = dampings;
  o.marked_dampings = marked;
  if (grid_c < 2 || grid_y < 2 || grid_c > 400 || grid_y > 400)
    throw std::invalid_argument("modes: grid: expected (C, Y) with 2 ... 400 points each, e.g. (16, 10)");
  if (speeds < 2 || speeds > 1000) throw std::invalid_argument("modes: speeds: expected 2 ... 1000");
  o.chart_c = grid_c;
  o.chart_y = grid_y;
  if (stiffness) modes::setChartStiffness(o, scene.scene(), stiffness->first, stiffness->second, "modes: stiffness");
  std::shared_ptr<const modes::ModesReport> report;
  {
    py::gil_scoped_release release;
    report = std::make_shared<const modes::ModesReport>(modes::analyseModes(scene.scene(), o));
  }
  return ModesData{scene, report};
}

// ModesData and modes().
void bindModes(py::module_& m) {
  py::class_<ModesData>(m, "ModesData")
      .def("json", [](const ModesData& d) { return toPython(modes::modesJson(*d.report)); })
      .def("frozen", [](const ModesData& d) { return tableToPython(modes::frozenTable(*d.report)); })
      .def("campbell", [](const ModesData& d) { return tableToPython(modes::campbellTable(*d.report)); })
      .def("stability", [](const ModesData& d) { return tableToPython(modes::stabilityTable(*d.report)); })
      .def_property_readonly("warnings", [](const ModesData& d) { return d.report->warnings; })
      .def("text", [](const ModesData& d) { return modes::modesText(*d.report); })
      .def("write", &writeModes, py::arg("out_dir"), py::arg("figures") = true);

  m.def("modes", &analyseSceneModes, py::arg("scene"), py::arg("dampings"), py::arg("mark_dampings"),
        py::arg("grid_c"), py::arg("grid_y"), py::arg("speeds"), py::arg("stiffness"), py::arg("charts"),
        py::arg("multibody"));
}

// MotorData.write: what `rollerdyn motor --out DIR` writes, by the same function.
std::string writeMotor(const MotorData& d, const std::string& out_dir) {
  prepareOutputDir(out_dir, StaleOutputs::Keep, "out_dir");
  py::gil_scoped_release release;  // gnuplot runs in child processes
  return writeMotorStudy(out_dir, d.scene.scene(), *d.study);
}

// fit_motor(): the motor study, without the GIL.
MotorData fitSceneMotor(const PyScene& scene) {
  std::shared_ptr<const MotorStudy> study;
  {
    py::gil_scoped_release release;
    study = std::make_shared<const MotorStudy>(studyMotor(scene.scene(), scene.file(), scene.overrides()));
  }
  return MotorData{scene, study};
}

// MotorData and fit_motor().
void bindMotor(py::module_& m) {
  py::class_<MotorData>(m, "MotorData")
      .def("json", [](const MotorData& d) { return toPython(d.study->json); })
      .def("curves", [](const MotorData& d) { return tableToPython(d.study->curves); })
      .def("text", [](const MotorData& d) { return d.study->text; })
      .def("write", &writeMotor, py::arg("out_dir"));

  m.def("fit_motor", &fitSceneMotor, py::arg("scene"));
}

}  // namespace

void bindAnalysis(py::module_& m) {
  bindModes(m);
  bindMotor(m);
}

}  // namespace rollerdyn::python
