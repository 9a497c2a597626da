// sweep, optimize and identify for Python: the studies of `rollerdyn sweep`, `rollerdyn optimize`
// and `rollerdyn identify` (studies/Sweep.h, Optimizer.h, Identify.h) on a scene kept in memory,
// with the objective or constraints optionally computed by Python functions from each usable run.
#include <atomic>
#include <cmath>
#include <exception>
#include <map>
#include <limits>
#include <memory>
#include <mutex>

#include <pybind11/stl.h>

#include "python/Bindings.h"
#include "python/Interruptible.h"
#include "python/PyConvert.h"
#include "python/PyScene.h"
#include "scene/SceneSchema.h"
#include "studies/Identify.h"
#include "studies/IdentifyOutputs.h"
#include "studies/Optimizer.h"
#include "studies/Sweep.h"
#include "studies/SweepDesigns.h"

namespace rollerdyn::python {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double numberOf(py::handle v) {
  if (py::isinstance<py::bool_>(v) || py::isinstance<py::str>(v)) return kNaN;
  try {
    const double x = py::float_(py::reinterpret_borrow<py::object>(v)).cast<double>();
    return std::isfinite(x) ? x : kNaN;
  } catch (const py::error_already_set&) {
    return kNaN;
  }
}

// A sweep parameter from Python: a spec as the command line's --values ("0:180:10", "2000,8000")
// or a sequence of values (each written as a --set value).
SweepParameter sweepParameter(const std::string& key, py::handle values) {
  requireSceneKey("sweep: parameter " + key, key);
  if (py::isinstance<py::str>(values)) return parseSweepValues(key, values.cast<std::string>());
  SweepParameter p;
  p.key = key;
  for (auto v : values) {
    p.texts.push_back(yamlValueText(v));
    p.values.push_back(numberOf(v));
  }
  if (p.texts.empty()) throw std::invalid_argument("sweep: parameter " + key + " has no values");
  return p;
}

// Where the study's scene comes from: the scene in memory, named by its file (or its name).
template <class Options>
void setScene(Options& o, const PyScene& scene) {
  o.scene_path = scene.file().empty() ? scene.scene().name : scene.file();
  o.scene_input = scene.sharedInput();
  o.base_overrides = scene.overrides();
}

// The first Python exception raised by one of the caller's functions; the study is stopped
// (as by Ctrl-C) and the exception raised again once it has.
struct CallbackError {
  std::mutex mu;
  std::exception_ptr error;
};

// One evaluation as the Python functions see it: every parameter by key, every metric of the
// sweep table by name, motion, status, steady_state_reached, complete, cpu_seconds.
py::dict evaluationRow(const OptimizeOptions& o, const OptimizeEvaluation& e) {
  py::dict row;
  for (std::size_t k = 0; k < o.params.size(); ++k) row[py::str(o.params[k].key)] = e.x[k];
  const auto& names = sweepNumericMetrics();
  for (std::size_t m = 0; m < names.size(); ++m) row[py::str(names[m])] = e.point.metric(names[m]);
  row["motion"] = e.point.motion;
  row["status"] = e.point.status;
  row["steady_state_reached"] = e.point.steady;
  row["complete"] = e.point.complete;
  row["cpu_seconds"] = e.point.cpu_seconds;
  return row;
}

// A Python function of an evaluation as the optimizer calls it, from its worker threads: the GIL
// is taken for the call only. `fn` is borrowed: the Python caller keeps it alive during the run.
EvaluationFunction pythonFunction(PyObject* fn, const std::string& what, const OptimizeOptions* o,
                                  std::shared_ptr<CallbackError> failure, std::atomic<bool>* stop) {
  return [fn, what, o, failure, stop](const OptimizeEvaluation& e) -> double {
    py::gil_scoped_acquire gil;
    try {
      py::object r = py::reinterpret_borrow<py::object>(fn)(evaluationRow(*o, e));
      try {
        return r.cast<double>();
      } catch (const py::cast_error&) {
        throw py::type_error(what + " must return a number, got " +
                             py::str(py::type::handle_of(r).attr("__name__")).cast<std::string>());
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(failure->mu);
      if (!failure->error) failure->error = std::current_exception();
      *stop = true;
      return kNaN;
    }
  };
}

std::string functionName(py::handle fn, const std::string& fallback) {
  const std::string name = py::str(py::getattr(fn, "__name__", py::str(fallback))).cast<std::string>();
  return name == "<lambda>" ? fallback : name;
}

// The sweep's parameters: designs given row by row (design_keys), else a grid of (key, values) pairs.
void setSweepParameters(SweepOptions& o, const py::list& params, const std::vector<std::string>& design_keys,
                        const py::list& design_rows) {
  if (design_keys.empty()) {
    for (auto item : params) {
      const py::tuple kv = item.cast<py::tuple>();
      o.params.push_back(sweepParameter(kv[0].cast<std::string>(), kv[1]));
    }
    return;
  }
  for (const std::string& k : design_keys) requireSceneKey("sweep: parameter " + k, k);
  for (auto row : design_rows) {
    std::vector<std::string> texts;
    for (auto v : row) texts.push_back(yamlValueText(v));
    o.designs.push_back(texts);
  }
  o.params = designParameters(design_keys, o.designs);
}

// The study of `rollerdyn sweep`: a grid of --values per parameter, or designs given row by row.
py::tuple sweepStudy(const PyScene& scene, const py::list& params, const std::vector<std::string>& design_keys,
                     const py::list& design_rows, const std::string& model, const std::string& minimize, int threads) {
  SweepOptions o;
  setScene(o, scene);
  setSweepParameters(o, params, design_keys, design_rows);
  o.model = model;
  o.minimize = minimize;
  o.threads = threads;
  std::atomic<bool> stop{false};
  o.interrupt = &stop;
  bool interrupted = false;
  const SweepResult r = runInterruptible([&o] { return runSweep(o); }, stop, &interrupted);
  return py::make_tuple(studyTableToPython(sweepTable(o, r)), toPython(sweepOptimumJson(o, r)),
                        toPython(r.execution), interrupted);
}

// A constraint given as a Python function of the run's row: it holds where the function is <= 0.
OptimizeConstraint functionConstraint(const py::handle& c, OptimizeOptions& o, const std::shared_ptr<CallbackError>& failure,
                                      std::atomic<bool>* stop) {
  OptimizeConstraint k;
  k.metric = functionName(c, "constraint " + std::to_string(o.constraints.size() + 1));
  k.upper = true;
  k.bound = 0;
  k.text = k.metric + "(row)<=0";
  k.value = pythonFunction(c.ptr(), "the constraint " + k.metric, &o, failure, stop);
  return k;
}

// The optimizer's objective and constraints: metric names and bounds as on the command line, or
// Python functions of the run's row (a constraint function holds where it is <= 0).
void setObjectiveAndConstraints(OptimizeOptions& o, const py::object& minimize, const py::list& constraints,
                                const std::shared_ptr<CallbackError>& failure, std::atomic<bool>* stop) {
  if (py::isinstance<py::str>(minimize)) {
    o.minimize = minimize.cast<std::string>();
  } else {
    if (!PyCallable_Check(minimize.ptr()))
      throw py::type_error("optimize: minimize is a metric name or a function of the run's row");
    o.minimize = functionName(minimize, "objective");
    o.objective = pythonFunction(minimize.ptr(), "the objective " + o.minimize, &o, failure, stop);
  }
  for (auto c : constraints) {
    if (py::isinstance<py::str>(c)) {
      o.constraints.push_back(parseConstraint(c.cast<std::string>()));
    } else if (PyCallable_Check(c.ptr())) {
      o.constraints.push_back(functionConstraint(c, o, failure, stop));
    } else {
      throw py::type_error("optimize: each constraint is 'METRIC<=VALUE', 'METRIC>=VALUE' or a function of "
                           "the run's row that is <= 0 where the constraint holds");
    }
  }
}

// The study of `rollerdyn optimize` over ranges of scene keys.
py::tuple optimizeStudy(const PyScene& scene, const std::vector<std::tuple<std::string, double, double>>& ranges,
                        const py::object& minimize, const py::list& constraints, const std::string& model,
                        const std::string& method, int max_evals, int threads) {
  auto o = std::make_unique<OptimizeOptions>();
  setScene(*o, scene);
  for (const auto& [key, lower, upper] : ranges) {
    requireSceneKey("optimize: parameter " + key, key);
    o->params.push_back({key, lower, upper});
  }
  std::atomic<bool> stop{false};
  auto failure = std::make_shared<CallbackError>();
  setObjectiveAndConstraints(*o, minimize, constraints, failure, &stop);
  o->model = model;
  o->method = method;
  o->max_evals = max_evals;
  o->threads = threads;
  o->interrupt = &stop;
  bool interrupted = false;
  const OptimizeOptions& opts = *o;
  const OptimizeResult r = runInterruptible([&opts] { return runOptimize(opts); }, stop, &interrupted);
  if (failure->error) std::rethrow_exception(failure->error);  // the function's own exception
  return py::make_tuple(studyTableToPython(optimizeHistoryTable(opts, r)), toPython(optimizeJson(opts, r)),
                        interrupted);
}

// Per signal: measured and model on the measured times (empty lists without them).
py::dict signalCurves(const IdentifyResult& r) {
  py::dict curves;
  for (std::size_t s = 0; s < r.signals.size(); ++s)
    curves[py::str(r.signals[s].name)] =
        py::make_tuple(r.data_values.empty() ? std::vector<double>{} : r.data_values[s],
                       r.model_values.empty() ? std::vector<double>{} : r.model_values[s]);
  return curves;
}

// The study of `rollerdyn identify`: scene keys fitted to measured signals.
py::tuple identifyStudy(const PyScene& scene, const std::string& data_path, const std::string& data_text,
                        const std::vector<std::string>& signals, const std::vector<std::string>& free,
                        const std::vector<std::tuple<std::string, double, double>>& bounds,
                        const std::map<std::string, double>& noise, const std::string& model, double holdout,
                        bool global, int max_iterations, int threads) {
  IdentifyOptions o;
  setScene(o, scene);
  // A file is read as the command line reads it; a table from Python comes as CSV text.
  o.data = data_text.empty() ? readMeasuredData(data_path) : parseMeasuredData(data_text, data_path);
  o.signals = signals;
  o.free_keys = free;
  for (const auto& [key, lower, upper] : bounds) o.bounds[key] = {lower, upper};
  o.noise = noise;
  o.model = model;
  o.holdout = holdout;
  o.global = global;
  o.max_iterations = max_iterations;
  o.threads = threads;
  std::atomic<bool> stop{false};
  o.interrupt = &stop;
  bool interrupted = false;
  const IdentifyResult r = runInterruptible([&o] { return runIdentify(o); }, stop, &interrupted);
  return py::make_tuple(toPython(identifyJson(o, r)), r.t, signalCurves(r), describeIdentify(r), interrupted);
}

}  // namespace

void bindStudies(py::module_& m) {
  m.def("sweep", &sweepStudy, py::arg("scene"), py::arg("params"), py::arg("design_keys"), py::arg("design_rows"),
        py::arg("model"), py::arg("minimize"), py::arg("threads"));
  m.def("optimize", &optimizeStudy, py::arg("scene"), py::arg("ranges"), py::arg("minimize"),
        py::arg("constraints"), py::arg("model"), py::arg("method"), py::arg("max_evals"), py::arg("threads"));
  m.def("identify", &identifyStudy, py::arg("scene"), py::arg("data_path"), py::arg("data_text"),
        py::arg("signals"), py::arg("free"), py::arg("bounds"), py::arg("noise"), py::arg("model"),
        py::arg("holdout"), py::arg("global_"), py::arg("max_iterations"), py::arg("threads"));
}

}  // namespace rollerdyn::python
