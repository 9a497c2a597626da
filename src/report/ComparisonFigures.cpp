#include "report/ComparisonFigures.h"

#include <algorithm>
#include <cmath>

#include "report/FigureSupport.h"

namespace rollerdyn {

namespace {

using namespace figures;  // FigureSupport.h

// A column name as part of a file name: anything but letters, digits, '_' and '-' becomes '_',
// so a CSV header can never point a figure outside the figures folder.
std::string fileSafe(const std::string& s) {
  std::string out;
  for (char c : s) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
    out += ok ? c : '_';
  }
  return out.empty() ? "_" : out;
}

// Unit of a compared quantity, from its name (RunResult.h conventions).
std::string unitOf(const std::string& q) {
  if (q.rfind("omega", 0) == 0) return "rad/s";
  if (q.rfind("eps", 0) == 0) return "rad/s^2";
  if (q.find("torque") != std::string::npos) return "N·m";
  if (q.rfind("twist", 0) == 0) return "rad";
  if (q.rfind("phi", 0) == 0) return "rad";
  if (q.rfind("x_cart", 0) == 0) return "m";
  if (q.rfind("v_cart", 0) == 0) return "m/s";
  if (q.rfind("a_cart", 0) == 0) return "m/s^2";
  return "N";
}

// comparison.csv left in a folder by `compare` may come from another run than the folder's
// timeseries.csv (other --set values): its multibody column then differs from this run. The note
// that says so, empty when the two agree (or cannot be compared).
std::string anotherRunNote(const OutputFolder& out, const std::vector<double>& t) {
  const Table& c = out.comparison;
  if (!(out.has_timeseries && c.has("omega_crank_multibody") && out.timeseries.has("t") &&
        out.timeseries.has("omega_crank")))
    return "";
  const std::vector<double> ts_t = out.timeseries.column("t"), ts_w = out.timeseries.column("omega_crank"),
                            cw = c.column("omega_crank_multibody");
  double dev = 0, scale = 0;
  for (size_t i = 0; i < t.size(); ++i) {
    const double here = interp(ts_t, ts_w, t[i]);
    if (!std::isfinite(here) || !std::isfinite(cw[i])) continue;
    dev = std::max(dev, std::abs(here - cw[i]));
    scale = std::max(scale, std::abs(cw[i]));
  }
  if (dev <= 1e-6 * std::max(scale, 1.0)) return "";
  return "comparison figures left out: comparison.csv comes from another run (its multibody "
         "omega_crank differs from timeseries.csv by up to " + printfNumber("%.3g", dev) +
         " rad/s); run `rollerdyn compare` with the same scene and --set into this folder";
}

// Over the whole run the oscillations merge into a band: draw the steady window, else the last
// quarter of the compared span.
TimeWindow comparedWindow(const TimeWindow& window, const std::vector<double>& t) {
  TimeWindow cw = window;
  if (!cw.found && t.size() > 1) {
    cw.t_end = t.back();
    cw.t_begin = t.back() - 0.25 * (t.back() - t.front());
    cw.found = true;
  }
  return cw;
}

// What the figures of one comparison share: the table, the compared window's rows and times, the
// folder's own window (for the caption) and the scene's label.
struct ComparedSpan {
  const Table& c;
  TimeWindow cw;
  std::vector<size_t> rows;
  std::vector<double> tw;
  bool steady;
  std::string scene_label;
};

// Quantity q: the multibody column against the reduced model's (and its kinetostatic reactions').
FigurePlan comparisonFigure(const ComparedSpan& span, const std::string& q) {
  const Table& c = span.c;
  const std::vector<double>& tw = span.tw;
  PlotSpec p;
  p.title = sceneTitle(span.scene_label, "multibody vs reduced model: " + literal(q) + " (" + windowText(span.cw) + ")");
  p.xlabel = "t [s]";
  p.ylabel = literal(q) + " [" + unitOf(q) + "]";
  p.preamble = "set key below\nset xrange [" + printfNumber("%.9g", tw.empty() ? 0.0 : tw.front()) + ":" +
               printfNumber("%.9g", tw.empty() ? 1.0 : tw.back()) + "]";
  p.series.push_back(series("multibody (Simbody)", tw, pick(c.column(q + "_multibody"), span.rows), kBlue, 2.0));
  if (c.has(q + "_reduced"))
    p.series.push_back(series("reduced-mass model", tw, pick(c.column(q + "_reduced"), span.rows), kOrange, 1.5));
  if (c.has(q + "_reduced_kinetostatic"))
    p.series.push_back(series("reduced model, kinetostatic reactions", tw,
                              pick(c.column(q + "_reduced_kinetostatic"), span.rows), kGreen, 1.5));
  return {"comparison_" + fileSafe(q),
          "The multibody model against the papers' reduced-mass model for " + q +
              " (comparison.csv of `rollerdyn compare`), over " +
              (span.steady ? "the steady window" : "the last quarter of the run") + ".",
          std::move(p)};
}

// The compared quantities: one per <quantity>_multibody column, in the table's order.
std::vector<std::string> comparedQuantities(const Table& c) {
  const std::string suffix = "_multibody";
  std::vector<std::string> quantities;
  for (const std::string& name : c.columns)
    if (name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
      quantities.push_back(name.substr(0, name.size() - suffix.size()));
  return quantities;
}

}  // namespace

void planComparisonFigures(const OutputFolder& out, const TimeWindow& window, const std::string& scene_label,
                           std::vector<FigurePlan>& plans, std::vector<std::string>& notes) {
  if (!out.has_comparison) return;
  const Table& c = out.comparison;
  const std::vector<double> t = col(c, "t");
  if (t.empty()) {
    notes.push_back("comparison figures left out: comparison.csv has no t column");
    return;
  }
  const std::string another_run = anotherRunNote(out, t);
  if (!another_run.empty()) {
    notes.push_back(another_run);
    return;
  }
  ComparedSpan span{c, comparedWindow(window, t), {}, {}, window.found, scene_label};
  span.rows = windowRows(t, span.cw);
  span.tw = pick(t, span.rows);
  const std::vector<std::string> quantities = comparedQuantities(c);
  for (const std::string& q : quantities) plans.push_back(comparisonFigure(span, q));
  if (quantities.empty()) notes.push_back("comparison figures left out: comparison.csv has no <quantity>_multibody columns");
}

}  // namespace rollerdyn
