// sweep.csv and sweep.json of a sweep (the figures: SweepPlots.cpp). Declared in Sweep.h.
#include <cmath>
#include <sstream>

#include "analysis/FrictionChecks.h"
#include "io/AtomicFile.h"
#include "io/FieldFormat.h"
#include "scene/SceneParser.h"
#include "scene/SceneSchema.h"
#include "studies/Sweep.h"
#include "studies/SweepPlots.h"

namespace rollerdyn {

namespace {

// A parameter column: its key path and the schema unit (ASCII), e.g. coupling.damping[N*m*s/rad].
std::string paramHeader(const std::string& key) {
  const KeySpec* spec = findSceneKey(key);
  if (!spec || spec->unit.empty()) return key;
  std::string u;
  for (std::size_t i = 0; i < spec->unit.size(); ++i) {
    if (spec->unit.compare(i, 2, "·") == 0) { u += '*'; ++i; continue; }
    if (spec->unit.compare(i, 2, "²") == 0) { u += "^2"; ++i; continue; }
    u += spec->unit[i];
  }
  return key + "[" + u + "]";
}

StudyColumn parameterColumn(const SweepOptions& o, const SweepResult& r, std::size_t k) {
  StudyColumn c;
  c.name = o.params[k].key;
  const std::string header = paramHeader(c.name);
  c.unit = header.size() > c.name.size() ? header.substr(c.name.size() + 1, header.size() - c.name.size() - 2) : "";
  c.parameter = true;
  c.is_text = !o.params[k].numeric();
  for (const SweepPoint& p : r.points) {
    c.texts.push_back(p.texts[k]);
    c.numbers.push_back(p.values[k]);
  }
  return c;
}

StudyColumn metricColumn(const SweepResult& r, const std::string& name) {
  StudyColumn c;
  c.name = name;
  c.unit = sweepMetricUnit(name);
  c.is_text = name == "status" || name == "motion";
  for (const SweepPoint& p : r.points) {
    if (name == "status") c.texts.push_back(p.status);
    else if (name == "motion") c.texts.push_back(p.motion);
    else if (name == "steady_state_reached") c.numbers.push_back(p.steady ? 1 : 0);
    else if (name == "cpu_seconds") c.numbers.push_back(p.cpu_seconds);
    else if (name == "resonance_warnings") c.numbers.push_back(double(p.warnings.size()));
    else c.numbers.push_back(p.metric(name));
  }
  return c;
}

// A point's parameter values by key: numbers where they are, else the text applied.
nlohmann::json pointValuesJson(const SweepOptions& o, const SweepPoint& p) {
  nlohmann::json values = nlohmann::json::object();
  for (std::size_t k = 0; k < o.params.size(); ++k)
    values[o.params[k].key] = std::isfinite(p.values[k]) ? nlohmann::json(p.values[k]) : nlohmann::json(p.texts[k]);
  return values;
}

// The parabola through the best grid point and its neighbours, its vertex and the run there.
nlohmann::json parabolaJson(const SweepVertex& v, bool is_optimum) {
  nlohmann::json run = nullptr;
  if (v.ran)
    run = {{"value", jsonNumber(v.value)},       {"usable", v.usable},
           {"status", v.point.status},           {"motion", v.point.motion},
           {"steady_state_reached", v.point.steady}, {"cpu_seconds", jsonNumber(v.point.cpu_seconds)}};
  return {{"parameter", v.parameter},
          {"predicted", v.predicted},
          {"run", run},
          {"holds", v.ran ? nlohmann::json(v.holds) : nlohmann::json(nullptr)},
          {"run_lower", v.ran ? nlohmann::json(v.lower) : nlohmann::json(nullptr)},
          {"tolerance", v.ran ? jsonNumber(v.tolerance) : nlohmann::json(nullptr)},
          {"is_optimum", is_optimum},
          {"refine", "--values " + formatNumber(v.refine_lower) + ":" + formatNumber(v.refine_upper) + ":" +
                         formatNumber(v.refine_step)},
          {"note", "vertex of the parabola through the best grid point and its two neighbours: " + v.note}};
}

}  // namespace

std::vector<StudyColumn> sweepTable(const SweepOptions& o, const SweepResult& r) {
  std::vector<StudyColumn> table;
  for (std::size_t k = 0; k < o.params.size(); ++k) table.push_back(parameterColumn(o, r, k));
  for (const std::string& name : sweepMetricColumns()) table.push_back(metricColumn(r, name));
  return table;
}

nlohmann::json sweepOptimumJson(const SweepOptions& o, const SweepResult& r) {
  if (r.optimum.metric.empty()) return nullptr;
  const SweepOptimum& opt = r.optimum;
  nlohmann::json jo = {{"metric", opt.metric}, {"found", opt.found}, {"note", opt.note}};
  if (!opt.found) return jo;
  const SweepVertex& v = opt.vertex;
  // The optimum is a run: the best grid point's, or the vertex's where that run is better.
  jo["at"] = opt.at_vertex ? nlohmann::json{{o.params[0].key, v.parameter}} : pointValuesJson(o, r.points[opt.index]);
  jo["value"] = opt.value;
  jo["steady_state_reached"] = opt.steady;
  jo["source"] = opt.at_vertex ? "run at the parabola's vertex" : "grid point";
  jo["index"] = opt.index;
  jo["grid_value"] = opt.grid_value;
  if (v.available) jo["parabola"] = parabolaJson(v, opt.at_vertex);
  return jo;
}

namespace {

// Headers as name[unit] (io/Table.h convention); text and count columns stay bare. Parameter
// values as they were applied (--set), metrics as numbers.
std::string sweepCsv(const std::vector<StudyColumn>& table, std::size_t points) {
  std::ostringstream csv;
  for (std::size_t c = 0; c < table.size(); ++c) {
    const StudyColumn& col = table[c];
    const std::string header = col.unit.empty() ? col.name : col.name + "[" + col.unit + "]";
    csv << (col.parameter ? csvText(header) : header) << (c + 1 < table.size() ? "," : "\n");
  }
  for (std::size_t i = 0; i < points; ++i)
    for (std::size_t c = 0; c < table.size(); ++c) {
      const StudyColumn& col = table[c];
      csv << (col.parameter || col.is_text ? csvText(col.texts[i]) : csvNumber(col.numbers[i]))
          << (c + 1 < table.size() ? "," : "\n");
    }
  return csv.str();
}

// The guide normal forces the points' friction (and the reduced model's reactions) use.
nlohmann::json guideNormalForcesJson(const SweepOptions& o) {
  try {
    const std::string g = guideNormalsDescription(parseSceneFile(o.scene_path, firstPointOverrides(o)), o.model == "reduced");
    return g.empty() ? nlohmann::json(nullptr) : nlohmann::json(g);
  } catch (const std::exception&) {
    return nullptr;  // the scene was checked before the sweep; nothing to add here
  }
}

nlohmann::json sweepPointJson(const SweepOptions& o, const SweepPoint& p, std::size_t index) {
  nlohmann::json m = nlohmann::json::object();
  for (const std::string& name : sweepNumericMetrics()) m[name] = jsonNumber(p.metric(name));
  return {{"index", index},
          {"values", pointValuesJson(o, p)},
          {"metrics", m},
          {"steady_state_reached", p.steady},
          {"complete", p.complete},
          {"motion", p.motion},
          {"status", p.status},
          {"cpu_seconds", jsonNumber(p.cpu_seconds)},
          {"warnings", p.warnings}};
}

nlohmann::json sweepJson(const SweepOptions& o, const SweepResult& r, const std::vector<std::string>& plots,
                         const std::string& plot_note) {
  nlohmann::json j;
  j["scene"] = o.scene_path;
  j["model"] = o.model;
  j["guide_normal_forces"] = guideNormalForcesJson(o);
  j["base_overrides"] = o.base_overrides;
  j["parameters"] = nlohmann::json::array();
  for (const SweepParameter& p : o.params) j["parameters"].push_back({{"key", p.key}, {"values", p.texts}});
  j["columns"] = sweepMetricColumns();
  j["points"] = nlohmann::json::array();
  for (std::size_t i = 0; i < r.points.size(); ++i) j["points"].push_back(sweepPointJson(o, r.points[i], i));
  j["optimum"] = sweepOptimumJson(o, r);
  j["plots"] = plots;
  j["plot_note"] = plot_note;
  for (const auto& [key, value] : r.execution.items()) j[key] = value;  // ranks, points_per_rank, ...
  return j;
}

}  // namespace

std::vector<std::string> writeSweepOutputs(const SweepOptions& o, const SweepResult& r,
                                           const std::string& out_dir, std::string* plot_note_out) {
  std::vector<std::string> files;
  writeFileAtomic(out_dir + "/sweep.csv", sweepCsv(sweepTable(o, r), r.points.size()));
  files.push_back(out_dir + "/sweep.csv");

  // --- plots (SweepPlots.h) ---
  std::string plot_note;
  std::vector<std::string> plots;
  try {
    plots = drawSweepPlots(o, r, out_dir, &plot_note);
  } catch (const std::exception& e) {
    plot_note = std::string("plotting failed: ") + e.what();
  }
  for (const std::string& p : plots) files.push_back(p);
  if (plot_note_out) *plot_note_out = plot_note;

  writeFileAtomic(out_dir + "/sweep.json", sweepJson(o, r, plots, plot_note).dump(2) + "\n");
  files.push_back(out_dir + "/sweep.json");
  return files;
}

}  // namespace rollerdyn
