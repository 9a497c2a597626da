#include "studies/Sweep.h"

#include <time.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "analysis/Summary.h"
#include "io/AtomicFile.h"
#include "multibody/MultibodySimulation.h"
#include "reduced/ReducedModel.h"
#include "report/Gnuplot.h"
#include "scene/SceneParser.h"
#include "scene/SceneSchema.h"
#include "studies/ResonanceCheck.h"
#include "studies/SweepExecution.h"

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

// Value in a summary path ("omega_crank.mean"), NaN when absent or null.
double summaryNumber(const nlohmann::json& s, const std::string& path) {
  const nlohmann::json* node = &s;
  std::size_t start = 0;
  while (true) {
    const std::size_t dot = path.find('.', start);
    const std::string part = path.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    if (!node->is_object() || !node->contains(part)) return kNaN;
    node = &(*node)[part];
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  return node->is_number() ? node->get<double>() : kNaN;
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
  return m;
}

// Units for plot labels.
std::string metricLabel(const std::string& m) {
  if (m == "delta") return "delta [-] (Loveikin and Pochka (2007) eq. (12))";
  if (m == "H") return "H [-] (Loveikin and Pochka (2007) eq. (13))";
  if (m == "k_p") return "k_p [-] (Loveikin and Pochka (2007) eq. (14))";
  if (m.rfind("omega_crank", 0) == 0) return m + " [rad/s]";
  if (m == "coupling_torque_swing") return "coupling torque swing [N·m]";
  if (m == "twist_swing") return "twist swing [rad]";
  if (m == "twist_rate_swing") return "twist rate swing [rad/s]";
  if (m == "twist_accel_swing") return "twist acceleration swing [rad/s²]";
  if (m == "eps_crank_abs_max") return "max |eps_crank| [rad/s²]";
  if (m == "energy_residual_rel") return "energy residual (relative) [-]";
  return m;
}

// Gnuplot draws titles as enhanced text, where "_" starts a subscript: escape it (Gnuplot.h).
std::string gp(const std::string& text) {
  std::string out;
  for (char c : text) out += (c == '_') ? std::string("\\_") : std::string(1, c);
  return out;
}

std::string paramLabel(const std::string& key) {
  const KeySpec* spec = findSceneKey(key);
  if (spec && !spec->unit.empty() && spec->unit != "-") return key + " [" + spec->unit + "]";
  return key;
}

std::string csvNumber(double v) {
  if (!std::isfinite(v)) return "nan";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.12g", v);
  return buf;
}

std::string csvText(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += (c == '"') ? std::string("\"\"") : std::string(1, c == '\n' || c == '\r' ? ' ' : c);
  return q + "\"";
}

nlohmann::json jsonNumber(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

SweepPoint runPoint(const SweepOptions& o, const std::vector<std::string>& texts,
                    const std::vector<double>& values) {
  SweepPoint p;
  p.texts = texts;
  p.values = values;
  p.metrics.assign(sweepNumericMetrics().size(), kNaN);
  const double cpu0 = threadCpuSeconds();
  std::vector<std::string> overrides = o.base_overrides;
  for (std::size_t i = 0; i < o.params.size(); ++i) overrides.push_back(o.params[i].key + "=" + texts[i]);
  Scene scene;
  try {
    scene = parseSceneFile(o.scene_path, overrides);
  } catch (const std::exception& e) {
    p.status = std::string("invalid: ") + e.what();
    p.cpu_seconds = threadCpuSeconds() - cpu0;
    return p;
  }
  try {
    RunResult run;
    if (o.model == "multibody") {
      RunControl control;
      control.interrupt = o.interrupt;
      run = runMultibodyModel(scene, control);
    } else {
      run = runReducedModel(scene);
    }
    p.ran = true;
    nlohmann::json summary = makeSummary(scene, run);
    addResonanceWarnings(scene, summary);
    p.warnings = summary["warnings"];
    const auto& src = metricSources();
    for (std::size_t k = 0; k < src.size(); ++k) p.metrics[k] = summaryNumber(summary, src[k].second);
    p.complete = run.stats.complete;
    p.steady = summary["steady_state"].value("reached", false);
    p.status = summary.value("status", run.stats.status);
  } catch (const std::exception& e) {
    p.status = std::string("error: ") + e.what();
  }
  p.cpu_seconds = threadCpuSeconds() - cpu0;
  return p;
}

}  // namespace

SweepPoint runSweepPoint(const SweepOptions& o, const std::vector<std::string>& texts,
                         const std::vector<double>& values) {
  return runPoint(o, texts, values);
}

bool SweepParameter::numeric() const {
  for (double v : values)
    if (!std::isfinite(v)) return false;
  return !values.empty();
}

SweepParameter parseSweepValues(const std::string& key, const std::string& spec_in) {
  SweepParameter p;
  p.key = key;
  const std::string spec = trim(spec_in);
  if (spec.empty()) throw std::invalid_argument("--values for " + key + ": empty");
  if (spec.find(':') != std::string::npos) {
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

const std::vector<std::string>& sweepMetricColumns() {
  static const std::vector<std::string> c = {
      "delta", "H", "k_p", "omega_crank_mean", "coupling_torque_swing", "twist_swing",
      "eps_crank_abs_max", "energy_residual_rel", "steady_state_reached", "status", "cpu_seconds",
      "omega_crank_min", "omega_crank_max", "omega_crank_midrange", "twist_rate_swing",
      "twist_accel_swing", "resonance_warnings"};
  return c;
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

SweepOptimum findOptimum(const std::vector<SweepParameter>& params,
                         const std::vector<SweepPoint>& points, const std::string& metric) {
  SweepOptimum opt;
  opt.metric = metric;
  bool any_steady = false;
  for (const SweepPoint& p : points)
    any_steady = any_steady || (p.complete && p.steady && std::isfinite(p.metric(metric)));
  auto candidate = [&](const SweepPoint& p) {
    return p.complete && std::isfinite(p.metric(metric)) && (!any_steady || p.steady);
  };
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!candidate(points[i])) continue;
    if (!opt.found || points[i].metric(metric) < opt.value) {
      opt.found = true;
      opt.index = i;
      opt.value = points[i].metric(metric);
      opt.steady = points[i].steady;
    }
  }
  if (!opt.found) {
    opt.note = "no completed point has a finite " + metric;
    return opt;
  }
  opt.note = any_steady ? "minimum over the points that completed at steady state"
                        : "no point reached steady state: minimum over the completed points";
  if (params.size() == 1 && params[0].numeric() && opt.index > 0 && opt.index + 1 < points.size() &&
      candidate(points[opt.index - 1]) && candidate(points[opt.index + 1])) {
    const double x0 = points[opt.index - 1].values[0], x1 = points[opt.index].values[0],
                 x2 = points[opt.index + 1].values[0];
    const double y0 = points[opt.index - 1].metric(metric), y1 = opt.value,
                 y2 = points[opt.index + 1].metric(metric);
    const double den = (x0 - x1) * (x0 - x2) * (x1 - x2);
    if (den != 0.0) {
      const double A = (x2 * (y1 - y0) + x1 * (y0 - y2) + x0 * (y2 - y1)) / den;
      const double B = (x2 * x2 * (y0 - y1) + x1 * x1 * (y2 - y0) + x0 * x0 * (y1 - y2)) / den;
      const double C = (x1 * x2 * (x1 - x2) * y0 + x2 * x0 * (x2 - x0) * y1 + x0 * x1 * (x0 - x1) * y2) / den;
      if (A > 0.0) {
        opt.refined = true;
        opt.refined_parameter = -B / (2 * A);
        opt.refined_value = C - B * B / (4 * A);
      }
    }
  }
  return opt;
}

SweepResult runSweep(const SweepOptions& o) {
  if (o.params.empty()) throw std::invalid_argument("sweep: give at least one --param with --values");
  if (o.model != "multibody" && o.model != "reduced")
    throw std::invalid_argument("sweep: --model must be multibody or reduced, got '" + o.model + "'");
  if (!o.minimize.empty()) {
    bool known = false;
    for (const std::string& m : sweepNumericMetrics()) known = known || m == o.minimize;
    if (!known) {
      std::string list;
      for (const std::string& m : sweepNumericMetrics()) list += (list.empty() ? "" : ", ") + m;
      throw std::invalid_argument("sweep: --minimize: expected one of " + list + ", got '" + o.minimize + "'");
    }
  }
  for (const SweepParameter& p : o.params) {
    if (p.values.empty()) throw std::invalid_argument("sweep: --param " + p.key + " has no values");
    if (!findSceneKey(p.key))
      throw std::invalid_argument("sweep: --param " + p.key + " is not a scene key (see model/README.md)");
  }
  // Grid (last parameter fastest) or explicit designs; threads or MPI, saved rows, resume.
  SweepResult result;
  result.points = executeSweep(o, sweepDesigns(o), result);
  if (!result.output_rank) return result;
  // Designs from a file or a Latin hypercube are not ordered: no parabola through neighbours.
  if (!o.minimize.empty())
    result.optimum = findOptimum(o.designs.empty() ? o.params : std::vector<SweepParameter>{}, result.points, o.minimize);
  return result;
}

std::string describeOptimum(const SweepOptions& o, const SweepResult& r) {
  const SweepOptimum& opt = r.optimum;
  if (opt.metric.empty()) return "";
  if (!opt.found) return "minimum of " + opt.metric + ": none (" + opt.note + ")";
  std::ostringstream os;
  os.precision(6);
  os << "minimum of " << opt.metric << " = " << opt.value << " at";
  const SweepPoint& p = r.points[opt.index];
  for (std::size_t k = 0; k < o.params.size(); ++k) os << ' ' << o.params[k].key << '=' << p.texts[k];
  os << (opt.steady ? " (steady state reached)" : " (steady state NOT reached)");
  if (opt.refined)
    os << "; parabola through the neighbours: " << o.params[0].key << " = " << opt.refined_parameter
       << ", " << opt.metric << " = " << opt.refined_value;
  return os.str();
}

std::vector<std::string> writeSweepOutputs(const SweepOptions& o, const SweepResult& r,
                                           const std::string& out_dir) {
  std::vector<std::string> files;
  const auto& metrics = sweepNumericMetrics();
  // --- sweep.csv ---
  std::ostringstream csv;
  for (const SweepParameter& p : o.params) csv << csvText(p.key) << ',';
  const auto& cols = sweepMetricColumns();
  for (std::size_t c = 0; c < cols.size(); ++c) csv << cols[c] << (c + 1 < cols.size() ? "," : "\n");
  for (const SweepPoint& p : r.points) {
    for (const std::string& t : p.texts) csv << csvText(t) << ',';
    for (std::size_t c = 0; c < cols.size(); ++c) {
      const std::string& name = cols[c];
      if (name == "steady_state_reached") csv << (p.steady ? 1 : 0);
      else if (name == "status") csv << csvText(p.status);
      else if (name == "cpu_seconds") csv << csvNumber(p.cpu_seconds);
      else if (name == "resonance_warnings") csv << p.warnings.size();
      else csv << csvNumber(p.metric(name));
      csv << (c + 1 < cols.size() ? "," : "\n");
    }
  }
  writeFileAtomic(out_dir + "/sweep.csv", csv.str());
  files.push_back(out_dir + "/sweep.csv");

  // --- plots ---
  std::vector<std::string> plots;
  std::string plot_note;
  const bool all_numeric = [&] {
    for (const SweepParameter& p : o.params)
      if (!p.numeric()) return false;
    return true;
  }();
  auto worth_plotting = [&](const std::string& m) {
    bool finite = false, nonzero = false;
    for (const SweepPoint& p : r.points) {
      const double v = p.metric(m);
      finite = finite || std::isfinite(v);
      nonzero = nonzero || (std::isfinite(v) && v != 0.0);
    }
    return finite && nonzero;
  };
  if (o.params.size() > 2) {
    plot_note = "no plots: more than two parameters";
  } else if (!o.designs.empty()) {
    plot_note = "no plots: the designs (values file or Latin hypercube) are not a grid";
  } else if (!all_numeric) {
    plot_note = "no plots: a parameter has non-numeric values";
  } else if (!gnuplotAvailable()) {
    plot_note = "no plots: gnuplot not found on PATH";
  } else {
    try {
      for (const std::string& m : metrics) {
        if (!worth_plotting(m)) continue;
        if (o.params.size() == 1) {
          PlotSpec spec;
          spec.title = gp(m + " vs " + o.params[0].key + " (" + o.model + " model)");
          spec.xlabel = gp(paramLabel(o.params[0].key));
          spec.ylabel = gp(metricLabel(m));
          PlotSeries s;
          s.title = gp(m);
          s.style = "linespoints";
          for (const SweepPoint& p : r.points) {
            s.x.push_back(p.values[0]);
            s.y.push_back(p.metric(m));
          }
          spec.series.push_back(s);
          renderPlot(spec, out_dir + "/plot_" + m);
          plots.push_back(out_dir + "/plot_" + m + ".png");
        } else {
          const SweepParameter &py = o.params[0], &px = o.params[1];
          std::vector<std::vector<double>> z(py.values.size(), std::vector<double>(px.values.size(), kNaN));
          for (std::size_t i = 0; i < r.points.size(); ++i)
            z[i / px.values.size()][i % px.values.size()] = r.points[i].metric(m);
          renderHeatMap(gp(m + " (" + o.model + " model)"), gp(paramLabel(px.key)), gp(paramLabel(py.key)),
                        gp(metricLabel(m)), px.values, py.values, z, out_dir + "/heatmap_" + m);
          plots.push_back(out_dir + "/heatmap_" + m + ".png");
        }
      }
    } catch (const std::exception& e) {
      plot_note = std::string("plotting failed: ") + e.what();
    }
  }
  for (const std::string& p : plots) files.push_back(p);

  // --- sweep.json ---
  nlohmann::json j;
  j["scene"] = o.scene_path;
  j["model"] = o.model;
  j["base_overrides"] = o.base_overrides;
  j["parameters"] = nlohmann::json::array();
  for (const SweepParameter& p : o.params) j["parameters"].push_back({{"key", p.key}, {"values", p.texts}});
  j["columns"] = cols;
  j["points"] = nlohmann::json::array();
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    const SweepPoint& p = r.points[i];
    nlohmann::json values = nlohmann::json::object(), m = nlohmann::json::object();
    for (std::size_t k = 0; k < o.params.size(); ++k)
      values[o.params[k].key] = std::isfinite(p.values[k]) ? nlohmann::json(p.values[k]) : nlohmann::json(p.texts[k]);
    for (const std::string& name : metrics) m[name] = jsonNumber(p.metric(name));
    j["points"].push_back({{"index", i},
                           {"values", values},
                           {"metrics", m},
                           {"steady_state_reached", p.steady},
                           {"complete", p.complete},
                           {"status", p.status},
                           {"cpu_seconds", jsonNumber(p.cpu_seconds)},
                           {"warnings", p.warnings}});
  }
  if (!r.optimum.metric.empty()) {
    const SweepOptimum& opt = r.optimum;
    nlohmann::json jo = {{"metric", opt.metric}, {"found", opt.found}, {"note", opt.note}};
    if (opt.found) {
      nlohmann::json at = nlohmann::json::object();
      for (std::size_t k = 0; k < o.params.size(); ++k)
        at[o.params[k].key] = std::isfinite(r.points[opt.index].values[k])
                                  ? nlohmann::json(r.points[opt.index].values[k])
                                  : nlohmann::json(r.points[opt.index].texts[k]);
      jo["index"] = opt.index;
      jo["at"] = at;
      jo["value"] = opt.value;
      jo["steady_state_reached"] = opt.steady;
      if (opt.refined)
        jo["parabola"] = {{"parameter", opt.refined_parameter}, {"value", opt.refined_value},
                          {"note", "vertex of the parabola through the best grid point and its two neighbours"}};
    }
    j["optimum"] = jo;
  } else {
    j["optimum"] = nullptr;
  }
  j["plots"] = plots;
  j["plot_note"] = plot_note;
  for (const auto& [key, value] : r.execution.items()) j[key] = value;  // ranks, points_per_rank, ...
  writeFileAtomic(out_dir + "/sweep.json", j.dump(2) + "\n");
  files.push_back(out_dir + "/sweep.json");
  return files;
}

}  // namespace rollerdyn
