// The Python module rollerdyn._core: bindings of the same libraries the command line is built
// from (no second implementation of anything), imported by the package src/python/rollerdyn.
#include <pybind11/pybind11.h>

#include "python/Bindings.h"

PYBIND11_MODULE(_core, m) {
  m.doc() = "rollerdyn's libraries for Python; use the package rollerdyn, not this module";
  m.attr("version") = ROLLERDYN_VERSION;
  m.attr("git_commit") = ROLLERDYN_GIT_COMMIT;
  rollerdyn::python::bindScene(m);
  rollerdyn::python::bindRuns(m);
  rollerdyn::python::bindStudies(m);
  rollerdyn::python::bindSchema(m);
  rollerdyn::python::bindAnalysis(m);
  rollerdyn::python::bindSignOff(m);
}
