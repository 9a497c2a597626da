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
                    {"value", jsonNumber(e.point.metric(o.constraints[j].metric))},
                    {"holds", e.run_ok && e.constraint_values[j] <= 0.0}});
  return {{"parameters", at},        {"objective", jsonNumber(e.objective)}, {"metrics", metrics},
          {"constraints", cons},     {"constraints_hold", e.constraints_hold}, {"usable_run", e.run_ok},
          {"reason", e.reason},      {"status", e.point.status},
          {"steady_state_reached", e.point.steady}, {"cpu_seconds", jsonNumber(e.point.cpu_seconds)}};
}

}  // namespace

std::vector<std::string> writeOptimizeOutputs(const OptimizeOptions& o, const OptimizeResult& r,
                                              const std::string& out_dir, std::string* plot_note_out) {
  std::vector<std::string> files;
  // --- history.csv: one row per distinct evaluation, in the order they were made ---
  std::ostringstream csv;
  csv << "evaluation";
  for (const SampleRange& p : o.params) csv << ',' << csvText(p.key);
  csv << ",objective";
  for (const OptimizeConstraint& c : o.constraints) csv << ',' << csvText(c.text);
  csv << ",usable_run,constraints_hold,best_so_far";
  for (const std::string& m : sweepNumericMetrics()) csv << ',' << m;
  csv << ",status,reason,cpu_seconds\n";
  double best = NAN;
  std::vector<double> best_curve;
  for (std::size_t i = 0; i < r.history.size(); ++i) {
    const OptimizeEvaluation& e = r.history[i];
    if (e.feasible() && !(e.objective >= best)) best = e.objective;
    best_curve.push_back(best);
    csv << i + 1;
    for (const std::string& t : e.texts) csv << ',' << csvText(t);
    csv << ',' << csvNumber(e.objective);
    for (const OptimizeConstraint& c : o.constraints) csv << ',' << csvNumber(e.point.metric(c.metric));
    csv << ',' << int(e.run_ok) << ',' << int(e.constraints_hold) << ',' << csvNumber(best);
    for (const std::string& m : sweepNumericMetrics()) csv << ',' << csvNumber(e.point.metric(m));
    csv << ',' << csvText(e.point.status) << ',' << csvText(e.reason) << ',' << csvNumber(e.point.cpu_seconds) << '\n';
  }
  writeFileAtomic(out_dir + "/history.csv", csv.str());
  files.push_back(out_dir + "/history.csv");

  // --- figures ---
  std::vector<std::string> plots;
  std::string plot_note;
  if (!gnuplotAvailable()) {
    plot_note = "no figures: gnuplot not found on PATH";
  } else {
    try {
      PlotSpec spec;
      spec.title = escapeUnderscores("convergence: " + o.minimize + " (" + r.method + ", " + o.model + " model)");
      spec.xlabel = "evaluation";
      spec.ylabel = escapeUnderscores(sweepParamLabel(o.minimize));
      spec.preamble = "set key below";
      PlotSeries all, bad, line;
      all.title = "usable design, constraints hold";
      all.style = "points";
      bad.title = "constraint violated (usable run)";
      bad.style = "points";
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
      plots.push_back(out_dir + "/convergence.png");
      // One parameter that is itself the minimised quantity: plot the first constraint's metric
      // against it instead (the objective against itself is a diagonal line and says nothing).
      const bool self = o.params.size() == 1 && o.params[0].key == o.minimize;
      if (self && o.constraints.empty())
        plot_note = "no designs figure: the minimised quantity is the only parameter and there is no constraint "
                    "to plot against it";
      if (o.params.size() <= 2 && r.found && !(self && o.constraints.empty())) {
        // The evaluated designs and the optimum: objective against the parameter (one), or the
        // designs in the plane of the two parameters.
        PlotSpec d;
        d.title = escapeUnderscores("evaluated designs and the optimum (" + r.method + ")");
        d.xlabel = escapeUnderscores(sweepParamLabel(o.params[0].key));
        const std::string y_name = o.params.size() == 2 ? o.params[1].key : self ? o.constraints[0].metric : o.minimize;
        auto yOf = [&](const OptimizeEvaluation& e) {
          return o.params.size() == 2 ? e.x[1] : self ? e.point.metric(o.constraints[0].metric) : e.objective;
        };
        d.ylabel = escapeUnderscores(sweepParamLabel(y_name));
        d.preamble = "set key below";
        PlotSeries ok, viol, opt;
        ok.title = "constraints hold";
        ok.style = "points";
        viol.title = "infeasible (constraint violated or run not usable)";
        viol.style = "points";
        opt.title = "optimum";
        opt.style = "points";
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
        plots.push_back(out_dir + "/designs.png");
      }
    } catch (const std::exception& e) {
      plot_note = std::string("plotting failed: ") + e.what();
    }
  }
  for (const std::string& p : plots) files.push_back(p);

  // --- optimize.json ---
  nlohmann::json j;
  j["scene"] = o.scene_path;
  j["model"] = o.model;
  j["base_overrides"] = o.base_overrides;
  j["minimize"] = o.minimize;
  j["constraints"] = nlohmann::json::array();
  for (const OptimizeConstraint& c : o.constraints) j["constraints"].push_back(c.text);
  j["parameters"] = nlohmann::json::array();
  for (const SampleRange& p : o.params) j["parameters"].push_back({{"key", p.key}, {"lower", p.lower}, {"upper", p.upper}});
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
  j["plots"] = plots;
  j["plot_note"] = plot_note;
  if (plot_note_out) *plot_note_out = plot_note;
  writeFileAtomic(out_dir + "/optimize.json", j.dump(2) + "\n");
  files.push_back(out_dir + "/optimize.json");
  return files;
}

}  // namespace rollerdyn
