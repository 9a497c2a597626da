// The parts of the Python module `rollerdyn._core`, one per concept (Module.cpp calls them in
// order). The pure-Python package (src/python/rollerdyn/) wraps them into the public API.
#pragma once

#include <pybind11/pybind11.h>

namespace rollerdyn::python {

void bindScene(pybind11::module_& m);    // SceneBindings.cpp: Scene, SceneError
void bindRuns(pybind11::module_& m);     // RunBindings.cpp: simulate, compare
void bindStudies(pybind11::module_& m);  // StudyBindings.cpp: sweep, optimize
void bindSchema(pybind11::module_& m);   // SchemaBindings.cpp: the scene keys, column units
void bindAnalysis(pybind11::module_& m); // AnalysisBindings.cpp: modes, fit_motor
void bindSignOff(pybind11::module_& m);  // SignOffBindings.cpp: signoff

}  // namespace rollerdyn::python
