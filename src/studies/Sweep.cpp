#include "studies/Sweep.h"

#include <algorithm>

#include <time.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "analysis/SizingSummary.h"
#include "analysis/Summary.h"
#include "io/AtomicFile.h"
#include "multibody/MultibodySimulation.h"
#include "reduced/ReducedModel.h"
#include "scene/SceneParser.h"
#include "scene/SceneSchema.h"
#include "scene/DidYouMean.h"
#include "studies/RunSummary.h"
#include "studies/SweepExecution.h"
#include "studies/SweepPointBudget.h"
#include "compare/RunModel.h"
#include "io/FieldFormat.h"

namespace rollerdyn {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// CPU time of the calling thread [s]: std::clock() counts the whole process, which with two
// workers would charge each point with its neighbour's time too.
double threadCpuSeconds() {
  timespec ts{};
  if (clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts) != 0) return kNaN;
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

double parseNumber(const std::string& text, bool* ok) {
  std::size_t used = 0;
  double v = kNaN;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  *ok = used > 0 && used == text.size() && std::isfinite(v);
  return *ok ? v : kNaN;
}

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t");
  if (a == std::string::npos) return "";
  const auto b = s.find_last_not_of(" \t");
  return s.substr(a, b - a + 1);
}


// sweepNumericMetrics() name -> summary.json path.
const std::vector<std::pair<std::string, std::string>>& metricSources() {
  static const std::vector<std::pair<std::string, std::string>> m = {
      {"delta", "delta"},
      {"H", "H"},
      {"k_p", "k_p"},
      {"omega_crank_mean", "omega_crank.mean"},
      {"coupling_torque_swing", "coupling_torque_swing"},
      {"twist_swing", "twist_swing"},
      {"eps_crank_abs_max", "eps_crank_abs_max"},
      {"energy_residual_rel", "energy_residual_rel"},
      {"omega_crank_min", "omega_crank.min"},
      {"omega_crank_max", "omega_crank.max"},
      {"omega_crank_midrange", "omega_crank.midrange"},
      {"twist_rate_swing", "twist_rate_swing"},
      {"twist_accel_swing", "twist_accel_swing"},
  };
  static const std::vector<std::pair<std::string, std::string>> all = [] {
    std::vector<std::pair<std::string, std::string>> v = m;
    for (const auto& p : sizingMetricPaths()) v.push_back(p);  // drive sizing (SizingSummary.h)
    return v;
  }();
  return all;
}

// A finished run's row: its motion, resonance warnings, metrics, steadiness and status, from the
// summary every run gets (stall cause, the resonance verdict): the resonance_warnings column counts
// the run's resonance warnings, the same as `simulate` prints.
void readRunInto(const Scene& scene, const RunResult& run, const std::vector<std::string>& overrides, SweepPoint& p) {
  RunSummaryOptions summary_options;
  summary_options.overrides = overrides;
  summary_options.flywheel_by_runs = false;  // a point's δ is its own answer
  RunMessages messages;
  const nlohmann::json summary = summarizeRun(scene, run, summary_options, &messages);
  p.motion = summary.value("motion", "unknown");
  p.warnings = messages.resonance_warnings;  // the load's warning is a metric column
  const auto& src = metricSources();
  for (std::size_t k = 0; k < src.size(); ++k) p.metrics[k] = jsonDouble(jsonAt(summary, src[k].second));
  p.complete = run.stats.complete;
  p.steady = summary["steady_state"].value("reached", false);
  p.status = summary.value("status", run.stats.status);
}

// Runs the point's scene into p; an exception of the run becomes its status ("error: …").
void runScene(const SweepOptions& o, const Scene& scene, const std::vector<std::string>& overrides, SweepPoint& p) {
  try {
    RunControl control;
    control.interrupt = o.interrupt;
    const RunResult run = runModel(scene, o.model, control);
    p.ran = true;
    readRunInto(scene, run, overrides, p);
  } catch (const std::exception& e) {
    p.status = std::string("error: ") + e.what();
  }
}

SweepPoint runPoint(const SweepOptions& o, const std::vector<std::string>& texts,
                    const std::vector<double>& values) {
  SweepPoint p = pointNotRun(texts, values);
  const double cpu0 = threadCpuSeconds();
  std::vector<std::string> overrides = o.base_overrides;
  for (std::size_t i = 0; i < o.params.size(); ++i) overrides.push_back(o.params[i].key + "=" + texts[i]);
  Scene scene;
  try {
    scene = o.scene_input ? parseSceneInput(*o.scene_input, overrides) : parseSceneFile(o.scene_path, overrides);
  } catch (const std::exception& e) {
    p.status = std::string("invalid: ") + e.what();
    p.cpu_seconds = threadCpuSeconds() - cpu0;
    return p;
  }
  runScene(o, scene, overrides, p);
  p.cpu_seconds = threadCpuSeconds() - cpu0;
  return p;
}

}  // namespace

SweepPoint runSweepPoint(const SweepOptions& o, const std::vector<std::string>& texts,
                         const std::vector<double>& values) {
  return o.run_point ? o.run_point(texts, values) : runPoint(o, texts, values);
}

SweepPoint pointNotRun(const std::vector<std::string>& texts, const std::vector<double>& values) {
  SweepPoint p;
  p.texts = texts;
  p.values = values;
  p.metrics.assign(sweepNumericMetrics().size(), kNaN);
  return p;
}

bool SweepParameter::numeric() const {
  for (double v : values)
    if (!std::isfinite(v)) return false;
  return !values.empty();
}

namespace {

// The numbers of --values a:b:step, in the key's unit.
struct ValueRange {
  double a, b, step;
};

// Reads --values a:b:step for key: three numbers, the step not zero and leading from a to b.
ValueRange parseRange(const std::string& key, const std::string& spec) {
  std::vector<std::string> parts;
  std::stringstream ss(spec);
  for (std::string item; std::getline(ss, item, ':');) parts.push_back(trim(item));
  bool ok[3] = {false, false, false};
  if (parts.size() != 3)
    throw std::invalid_argument("--values for " + key + ": expected a:b:step, got '" + spec + "'");
  const double a = parseNumber(parts[0], &ok[0]), b = parseNumber(parts[1], &ok[1]),
               step = parseNumber(parts[2], &ok[2]);
  if (!ok[0] || !ok[1] || !ok[2])
    throw std::invalid_argument("--values for " + key + ": a:b:step needs three numbers, got '" + spec + "'");
  if (step == 0.0 || (b - a) * step < 0.0)
    throw std::invalid_argument("--values for " + key + ": step must be non-zero and lead from " +
                                parts[0] + " to " + parts[1] + ", got '" + spec + "'");
  return {a, b, step};
}

// --values a:b:step: from a to b (inclusive, within 1e-9 of a step) in steps, at most 100000 points.
SweepParameter rangeValues(const std::string& key, const std::string& spec) {
  SweepParameter p;
  p.key = key;
  const auto [a, b, step] = parseRange(key, spec);
  const double n = std::floor((b - a) / step + 1e-9);
  if (n > 100000) throw std::invalid_argument("--values for " + key + ": more than 100000 points");
  for (long i = 0; i <= static_cast<long>(n); ++i) {
    // a + i·step rounded to 12 significant digits, so 0.1-steps print as 0.3, not 0.30000000000000004
    const double v = std::stod(formatNumber(a + i * step));
    p.values.push_back(v);
    p.texts.push_back(formatNumber(v));
  }
  return p;
}

// --values v1,v2,...: each as written (a text value stays text: its number is NaN).
SweepParameter listedValues(const std::string& key, const std::string& spec) {
  SweepParameter p;
  p.key = key;
  std::stringstream ss(spec);
  for (std::string item; std::getline(ss, item, ',');) {
    item = trim(item);
    if (item.empty()) throw std::invalid_argument("--values for " + key + ": empty entry in '" + spec + "'");
    bool ok = false;
    const double v = parseNumber(item, &ok);
    p.values.push_back(v);
    p.texts.push_back(item);
  }
  return p;
}

}  // namespace

SweepParameter parseSweepValues(const std::string& key, const std::string& spec_in) {
  const std::string spec = trim(spec_in);
  if (spec.empty()) throw std::invalid_argument("--values for " + key + ": empty");
  return spec.find(':') != std::string::npos ? rangeValues(key, spec) : listedValues(key, spec);
}

const std::vector<std::string>& sweepMetricColumns() {
  static const std::vector<std::string> c = {
      "delta", "H", "k_p", "omega_crank_mean", "coupling_torque_swing", "twist_swing",
      "eps_crank_abs_max", "energy_residual_rel", "steady_state_reached", "motion", "status", "cpu_seconds",
      "omega_crank_min", "omega_crank_max", "omega_crank_midrange", "twist_rate_swing",
      "twist_accel_swing", "resonance_warnings"};
  static const std::vector<std::string> all = [] {
    std::vector<std::string> v = c;
    for (const auto& [name, path] : sizingMetricPaths()) v.push_back(name);
    return v;
  }();
  return all;
}

const std::vector<std::string>& sweepNumericMetrics() {
  static const std::vector<std::string> m = [] {
    std::vector<std::string> v;
    for (const auto& [name, path] : metricSources()) v.push_back(name);
    return v;
  }();
  return m;
}

double SweepPoint::metric(const std::string& name) const {
  const auto& names = sweepNumericMetrics();
  for (std::size_t k = 0; k < names.size() && k < metrics.size(); ++k)
    if (names[k] == name) return metrics[k];
  return kNaN;
}

void requireSweepMetric(const std::string& what, const std::string& metric) {
  const std::vector<std::string>& names = sweepNumericMetrics();
  if (std::find(names.begin(), names.end(), metric) != names.end()) return;
  std::string list;
  for (const std::string& m : names) list += (list.empty() ? "" : ", ") + m;
  throw std::invalid_argument(what + ": unknown metric '" + metric + "'" + didYouMean(metric, names) +
                              "; expected one of " + list);
}

namespace {

// The parabola's vertex, run as a point of the grid is (same model, overrides and settings; under
// the same CPU budget; announced like a point, as the last one) and judged against its prediction.
void runVertex(const SweepOptions& o, SweepResult& r) {
  SweepVertex& v = r.optimum.vertex;
  if (!v.available) return;
  if (o.interrupt && o.interrupt->load()) {
    v.note = "not run (interrupted)";
    return;
  }
  const std::vector<std::string> texts = {v.text};
  const std::vector<double> values = {v.parameter};
  double accuracy = 1e-6;  // the schema's default, should the scene not parse at the vertex (the run says why)
  try {
    std::vector<std::string> overrides = o.base_overrides;
    overrides.push_back(o.params[0].key + "=" + v.text);
    accuracy = (o.scene_input ? parseSceneInput(*o.scene_input, overrides) : parseSceneFile(o.scene_path, overrides))
                   .simulation.accuracy;
  } catch (const std::exception&) {
  }
  const SweepPoint p = o.point_budget > 0 ? runSweepPointWithBudget(o, texts, values, o.point_budget)
                                          : runSweepPoint(o, texts, values);
  if (o.on_point) o.on_point(p, r.points.size() + 1, r.points.size());
  judgeVertexRun(r.optimum, r.points, p, accuracy);
}

}  // namespace

SweepResult runSweep(const SweepOptions& o) {
  if (o.params.empty()) throw std::invalid_argument("sweep: give at least one --param with --values");
  if (o.model != "multibody" && o.model != "reduced")
    throw std::invalid_argument("sweep: --model must be multibody or reduced, got '" + o.model + "'");
  if (!o.minimize.empty()) requireSweepMetric("sweep: --minimize", o.minimize);
  for (const SweepParameter& p : o.params) {
    if (p.values.empty()) throw std::invalid_argument("sweep: --param " + p.key + " has no values");
    if (!findSceneKey(p.key))
      throw std::invalid_argument("sweep: --param " + p.key + " is not a scene key (see docs/scene-reference.md)");
  }
  // Grid (last parameter fastest) or explicit designs; threads or MPI, saved rows, resume.
  SweepResult result;
  result.points = executeSweep(o, sweepDesigns(o), result);
  if (!result.output_rank) return result;
  // Designs from a file or a Latin hypercube are not ordered: no parabola through neighbours.
  if (!o.minimize.empty()) {
    result.optimum = findOptimum(o.designs.empty() ? o.params : std::vector<SweepParameter>{}, result.points, o.minimize);
    runVertex(o, result);
  }
  return result;
}

// findOptimum, judgeVertexRun, describeOptimum: SweepOptimum.cpp.
// writeSweepOutputs: SweepOutputs.cpp (files), SweepPlots.cpp (figures).

std::vector<std::string> firstPointOverrides(const SweepOptions& o) {
  std::vector<std::string> out = o.base_overrides;
  for (std::size_t k = 0; k < o.params.size(); ++k) {
    const std::string* text = nullptr;
    if (!o.designs.empty()) {
      if (k < o.designs.front().size()) text = &o.designs.front()[k];
    } else if (!o.params[k].texts.empty()) {
      text = &o.params[k].texts.front();
    }
    if (text) out.push_back(o.params[k].key + "=" + *text);
  }
  return out;
}

}  // namespace rollerdyn
