// Output files of `rollerdyn optimize` (Optimizer.h): optimize.json, history.csv and figures.
#include <cmath>
#include <sstream>

#include "io/AtomicFile.h"
#include "io/FieldFormat.h"
#include "report/Gnuplot.h"
#include "studies/Optimizer.h"
#include "studies/SweepPlots.h"

namespace rollerdyn {

namespace {

nlohmann::json evaluationJson(const OptimizeOptions& o, const OptimizeEvaluation& e) {
  nlohmann::json at = nlohmann::json::object(), metrics = nlohmann::json::object(), cons = nlohmann::json::array();
  for (std::size_t k = 0; k < o.params.size(); ++k) at[o.params[k].key] = e.x[k];
  for (const std::string& m : sweepNumericMetrics()) metrics[m] = jsonNumber(e.point.metric(m));
  for (std::size_t j = 0; j < o.constraints.size(); ++j)
    cons.push_back({{"constraint", o.constraints[j].text},
                    {"value", jsonNumber(e.constraint_metrics[j])},
                    {"holds", e.run_ok && e.constraint_values[j] <= 0.0}});
  return {{"parameters", at},        {"objective", jsonNumber(e.objective)}, {"metrics", metrics},
          {"constraints", cons},     {"constraints_hold", e.constraints_hold}, {"usable_run", e.run_ok},
          {"reason", e.reason},      {"status", e.point.status},
          {"steady_state_reached", e.point.steady}, {"cpu_seconds", jsonNumber(e.point.cpu_seconds)}};
}

// What was asked: the scene, model, overrides, the quantity minimised, constraints and ranges.
nlohmann::json optimizeQuestionJson(const OptimizeOptions& o) {
  nlohmann::json j;
  j["scene"] = o.scene_path;
  j["model"] = o.model;
  j["base_overrides"] = o.base_overrides;
  j["minimize"] = o.minimize;
  j["constraints"] = nlohmann::json::array();
  for (const OptimizeConstraint& c : o.constraints) j["constraints"].push_back(c.text);
  j["parameters"] = nlohmann::json::array();
  for (const SampleRange& p : o.params) j["parameters"].push_back({{"key", p.key}, {"lower", p.lower}, {"upper", p.upper}});
  return j;
}

}  // namespace

nlohmann::json optimizeJson(const OptimizeOptions& o, const OptimizeResult& r) {
  nlohmann::json j = optimizeQuestionJson(o);
  j["method"] = r.method;
  j["scope"] = r.scope;
  j["evaluations"] = r.history.size();
  j["evaluations_requested"] = r.requests;
  j["max_evals"] = o.max_evals;
  j["stop_reason"] = r.stop_reason;
  j["parallel"] = r.method.rfind("multistart", 0) == 0
                      ? "multistart: one local search per thread, side by side"
                      : "sequential: NLopt asks for one design at a time; each evaluation is one run on one thread";
  j["found"] = r.found;
  j["constraints_hold"] = r.found;
  j["optimum"] = r.found ? evaluationJson(o, r.history[r.best]) : nlohmann::json(nullptr);
  if (!r.found)
    j["note"] = "no evaluated design is usable (complete, steady, turning) and keeps every constraint: widen the "
                "ranges, raise --max-evals, or try --method direct-l";
  return j;
}

namespace {

// Where each column family of the history table starts.
struct HistoryColumns {
  std::size_t evaluation, params, objective, constraints, usable, hold, best, metrics, status, reason, cpu;
  std::size_t param_count, constraint_count;
};

std::size_t addColumn(std::vector<StudyColumn>& t, const std::string& name, bool is_text = false) {
  StudyColumn c;
  c.name = name;
  c.is_text = is_text;
  t.push_back(c);
  return t.size() - 1;
}

HistoryColumns historyColumns(const OptimizeOptions& o, std::vector<StudyColumn>& t) {
  HistoryColumns c;
  c.evaluation = addColumn(t, "evaluation");
  c.params = t.size();
  for (const SampleRange& p : o.params) t[addColumn(t, p.key)].parameter = true;
  c.objective = addColumn(t, "objective");
  c.constraints = t.size();
  for (const OptimizeConstraint& k : o.constraints) addColumn(t, k.text);
  c.usable = addColumn(t, "usable_run");
  c.hold = addColumn(t, "constraints_hold");
  c.best = addColumn(t, "best_so_far");
  c.metrics = t.size();
  for (const std::string& m : sweepNumericMetrics()) addColumn(t, m);
  c.status = addColumn(t, "status", true);
  c.reason = addColumn(t, "reason", true);
  c.cpu = addColumn(t, "cpu_seconds");
  c.param_count = o.params.size();
  c.constraint_count = o.constraints.size();
  return c;
}

// Evaluation i (0-based) as the table's next row; `best`: the best feasible objective so far.
void appendEvaluation(std::vector<StudyColumn>& t, const HistoryColumns& c, const OptimizeEvaluation& e,
                      std::size_t i, double best) {
  t[c.evaluation].numbers.push_back(double(i + 1));
  for (std::size_t k = 0; k < c.param_count; ++k) {
    t[c.params + k].texts.push_back(e.texts[k]);
    t[c.params + k].numbers.push_back(e.x[k]);
  }
  t[c.objective].numbers.push_back(e.objective);
  for (std::size_t j = 0; j < c.constraint_count; ++j)
    t[c.constraints + j].numbers.push_back(e.constraint_metrics[j]);
  t[c.usable].numbers.push_back(e.run_ok ? 1 : 0);
  t[c.hold].numbers.push_back(e.constraints_hold ? 1 : 0);
  t[c.best].numbers.push_back(best);
  const auto& names = sweepNumericMetrics();
  for (std::size_t m = 0; m < names.size(); ++m) t[c.metrics + m].numbers.push_back(e.point.metric(names[m]));
  t[c.status].texts.push_back(e.point.status);
  t[c.reason].texts.push_back(e.reason);
  t[c.cpu].numbers.push_back(e.point.cpu_seconds);
}

}  // namespace

std::vector<StudyColumn> optimizeHistoryTable(const OptimizeOptions& o, const OptimizeResult& r) {
  std::vector<StudyColumn> t;
  const HistoryColumns columns = historyColumns(o, t);
  double best = NAN;
  for (std::size_t i = 0; i < r.history.size(); ++i) {
    const OptimizeEvaluation& e = r.history[i];
    if (e.feasible() && !(e.objective >= best)) best = e.objective;
    appendEvaluation(t, columns, e, i, best);
  }
  return t;
}

namespace {

// history.csv: one row per distinct evaluation, in the order they were made. Also hands back the
// best-so-far column, the convergence figure's line.
std::string historyCsv(const OptimizeOptions& o, const OptimizeResult& r, std::vector<double>& best_curve) {
  const std::vector<StudyColumn> table = optimizeHistoryTable(o, r);
  std::ostringstream csv;
  csv << "evaluation";
  for (const SampleRange& p : o.params) csv << ',' << csvText(p.key);
  csv << ",objective";
  for (const OptimizeConstraint& c : o.constraints) csv << ',' << csvText(c.text);
  csv << ",usable_run,constraints_hold,best_so_far";
  for (const std::string& m : sweepNumericMetrics()) csv << ',' << m;
  csv << ",status,reason,cpu_seconds\n";
  for (std::size_t i = 0; i < r.history.size(); ++i)
    for (std::size_t c = 0; c < table.size(); ++c) {
      const StudyColumn& col = table[c];
      if (col.name == "best_so_far") best_curve.push_back(col.numbers[i]);
      if (col.name == "evaluation" || col.name == "usable_run" || col.name == "constraints_hold")
        csv << static_cast<long>(col.numbers[i]);
      else if (col.parameter || col.is_text)
        csv << csvText(col.texts[i]);
      else
        csv << csvNumber(col.numbers[i]);
      csv << (c + 1 < table.size() ? "," : "\n");
    }
  return csv.str();
}

// A series of points with its key title.
PlotSeries pointsSeries(const std::string& title) {
  PlotSeries s;
  s.title = title;
  s.style = "points";
  return s;
}

// Convergence: the objective of every usable evaluation, in order, and the best feasible value so far.
void convergenceFigure(const OptimizeOptions& o, const OptimizeResult& r, const std::vector<double>& best_curve,
                       const std::string& out_dir) {
  PlotSpec spec;
  spec.title = escapeUnderscores("convergence: " + o.minimize + " (" + r.method + ", " + o.model + " model)");
  spec.xlabel = "evaluation";
  spec.ylabel = escapeUnderscores(sweepParamLabel(o.minimize));
  spec.preamble = "set key below";
  PlotSeries all = pointsSeries("usable design, constraints hold"), bad = pointsSeries("constraint violated (usable run)");
  PlotSeries line;
  line.title = "best so far";
  line.style = "lines";
  line.line_width = 2;
  for (std::size_t i = 0; i < r.history.size(); ++i) {
    const OptimizeEvaluation& e = r.history[i];
    PlotSeries& s = e.feasible() ? all : bad;
    if (e.run_ok) {
      s.x.push_back(double(i + 1));
      s.y.push_back(e.objective);
    }
    line.x.push_back(double(i + 1));
    line.y.push_back(best_curve[i]);
  }
  spec.series = {all, bad, line};
  renderPlot(spec, out_dir + "/convergence");
}

// The evaluated designs and the optimum: objective against the parameter (one), or the designs in
// the plane of the two parameters. `self`: the one parameter is the minimised quantity, so the first
// constraint's metric stands on the vertical axis instead.
void designsFigure(const OptimizeOptions& o, const OptimizeResult& r, bool self, const std::string& out_dir) {
  PlotSpec d;
  d.title = escapeUnderscores("evaluated designs and the optimum (" + r.method + ")");
  d.xlabel = escapeUnderscores(sweepParamLabel(o.params[0].key));
  const std::string y_name = o.params.size() == 2 ? o.params[1].key : self ? o.constraints[0].metric : o.minimize;
  auto yOf = [&](const OptimizeEvaluation& e) {
    return o.params.size() == 2 ? e.x[1] : self ? e.constraint_metrics[0] : e.objective;
  };
  d.ylabel = escapeUnderscores(sweepParamLabel(y_name));
  d.preamble = "set key below";
  PlotSeries ok = pointsSeries("constraints hold"),
             viol = pointsSeries("infeasible (constraint violated or run not usable)"), opt = pointsSeries("optimum");
  opt.line_width = 3;
  for (const OptimizeEvaluation& e : r.history) {
    if (o.params.size() == 1 && !e.run_ok) continue;
    PlotSeries& s = e.feasible() ? ok : viol;
    s.x.push_back(e.x[0]);
    s.y.push_back(yOf(e));
  }
  const OptimizeEvaluation& b = r.history[r.best];
  opt.x.push_back(b.x[0]);
  opt.y.push_back(yOf(b));
  d.series = {ok, viol, opt};
  renderPlot(d, out_dir + "/designs");
}

// The designs figure (its png path into plots) when it can say something: at most two parameters
// and an optimum found; plot_note says why not when the only parameter is the minimised quantity
// and no constraint's metric can stand against it.
void designsFigureIfTelling(const OptimizeOptions& o, const OptimizeResult& r, const std::string& out_dir,
                            std::vector<std::string>& plots, std::string& plot_note) {
  // One parameter that is itself the minimised quantity: plot the first constraint's metric
  // against it instead (the objective against itself is a diagonal line and says nothing).
  const bool self = o.params.size() == 1 && o.params[0].key == o.minimize;
  if (self && o.constraints.empty())
    plot_note = "no designs figure: the minimised quantity is the only parameter and there is no constraint "
                "to plot against it";
  if (o.params.size() <= 2 && r.found && !(self && o.constraints.empty())) {
    designsFigure(o, r, self, out_dir);
    plots.push_back(out_dir + "/designs.png");
  }
}

// The figures that apply (png paths), and in plot_note why one is missing or plotting failed.
std::vector<std::string> optimizeFigures(const OptimizeOptions& o, const OptimizeResult& r,
                                         const std::vector<double>& best_curve, const std::string& out_dir,
                                         std::string& plot_note) {
  std::vector<std::string> plots;
  if (!gnuplotAvailable()) {
    plot_note = "no figures: gnuplot not found on PATH";
    return plots;
  }
  try {
    convergenceFigure(o, r, best_curve, out_dir);
    plots.push_back(out_dir + "/convergence.png");
    designsFigureIfTelling(o, r, out_dir, plots, plot_note);
  } catch (const std::exception& e) {
    plot_note = std::string("plotting failed: ") + e.what();
  }
  return plots;
}

}  // namespace

std::vector<std::string> writeOptimizeOutputs(const OptimizeOptions& o, const OptimizeResult& r,
                                              const std::string& out_dir, std::string* plot_note_out) {
  std::vector<std::string> files;
  std::vector<double> best_curve;
  writeFileAtomic(out_dir + "/history.csv", historyCsv(o, r, best_curve));
  files.push_back(out_dir + "/history.csv");

  std::string plot_note;
  const std::vector<std::string> plots = optimizeFigures(o, r, best_curve, out_dir, plot_note);
  for (const std::string& p : plots) files.push_back(p);

  // --- optimize.json ---
  nlohmann::json j = optimizeJson(o, r);
  j["plots"] = plots;
  j["plot_note"] = plot_note;
  if (plot_note_out) *plot_note_out = plot_note;
  writeFileAtomic(out_dir + "/optimize.json", j.dump(2) + "\n");
  files.push_back(out_dir + "/optimize.json");
  return files;
}

}  // namespace rollerdyn
