#include "studies/SweepPlots.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
#include <sstream>

#include "report/Gnuplot.h"
#include "scene/SceneSchema.h"
#include "io/FieldFormat.h"

namespace rollerdyn {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string num(double v) { return significant(v, 12); }

const char* kLegend =
    "black-hatched colour: turning, steady state not reached;  grey hatched: starting (run too short), rocking, stalled or "
    "failed (no value)";

}  // namespace

std::string sweepParamLabel(const std::string& key) {
  const KeySpec* spec = findSceneKey(key);
  if (spec && !spec->unit.empty() && spec->unit != "-") return key + " [" + spec->unit + "]";
  return key;
}

std::string sweepMetricUnit(const std::string& m) {
  if (m == "delta" || m == "H" || m == "k_p" || m == "energy_residual_rel" ||
      m.find("_over_") != std::string::npos || m == "motor_thermal_whole_run")
    return "-";
  if (m == "load_power_per_cart" || m == "motor_power_line_mean_whole_run") return "W";
  if (m == "coupling_torque_peak_whole_run") return "N*m";
  if (m.rfind("omega_crank", 0) == 0 || m == "twist_rate_swing") return "rad/s";
  if (m == "twist_swing") return "rad";
  if (m == "twist_accel_swing" || m == "eps_crank_abs_max") return "rad/s^2";
  if (m == "coupling_torque_swing" || m == "coupling_torque_peak" || m.rfind("motor_torque", 0) == 0)
    return "N*m";
  if (m.rfind("motor_power", 0) == 0) return "W";
  if (m == "energy_per_revolution" || m == "kinetic_energy_swing") return "J";
  if (m.size() > 5 && (m.compare(m.size() - 5, 5, "_peak") == 0 ||
                       m.find("equivalent_load") != std::string::npos))
    return "N";
  if (m == "cpu_seconds") return "s";
  return "";
}

namespace {

// What each metric is, in the words of the figures' axes (the others: their names).
const std::vector<std::pair<std::string, std::string>>& metricDescriptions() {
  static const std::vector<std::pair<std::string, std::string>> names = {
      {"delta", "δ, coefficient of unevenness (Loveikin and Pochka (2007) eq. (12))"},
      {"H", "H, coefficient of dynamics (Loveikin and Pochka (2007) eq. (13))"},
      {"k_p", "k_p, generalised coefficient (Loveikin and Pochka (2007) eq. (14))"},
      {"coupling_torque_swing", "coupling torque swing ΔM"},
      {"twist_swing", "twist swing"},
      {"twist_rate_swing", "twist rate swing"},
      {"twist_accel_swing", "twist acceleration swing"},
      {"eps_crank_abs_max", "max |ε_{crank}|, crank angular acceleration"},
      {"energy_residual_rel", "energy residual (relative)"},
      {"motor_torque_rotor_rms", "RMS motor torque at the rotor"},
      {"motor_torque_rotor_peak", "peak motor torque at the rotor"},
      {"motor_rms_over_nominal", "RMS motor torque / nominal torque M_n"},
      {"motor_peak_over_breakdown", "peak motor torque / breakdown torque M_{kr}"},
      {"motor_power_mean", "mean motor shaft power"},
      {"motor_power_peak", "peak motor shaft power"},
      {"energy_per_revolution", "motor energy per crank revolution"},
      {"kinetic_energy_swing", "kinetic-energy swing per revolution"},
      {"coupling_torque_peak", "peak coupling torque"},
      {"coupling_torque_peak_whole_run", "peak coupling torque over the whole run (start-up included)"},
      {"motor_torque_rotor_rms_whole_run", "RMS motor torque at the rotor over the whole run"},
      {"motor_thermal_whole_run", "motor thermal equivalent / nominal over the whole run"},
      {"motor_power_line_mean_whole_run", "mean power from the line over the whole run"},
      {"load_power_per_cart", "mean power the load absorbs per cart"},
      {"load_net_over_gross", "net / gross work of the load"},
      {"guide_roller_peak", "peak front guide-roller force"},
      {"guide_roller_rear_peak", "peak rear guide-roller force"},
      {"rod_force_peak", "peak rod force"},
      {"crank_pin_peak", "peak crank-pin force"},
      {"main_bearing_peak", "peak main-bearing force"},
      {"guide_roller_equivalent_load", "guide-roller equivalent dynamic load P"},
      {"crank_pin_equivalent_load", "crank-pin equivalent dynamic load P"},
      {"main_bearing_equivalent_load", "main-bearing equivalent dynamic load P"},
  };
  return names;
}

}  // namespace

std::string sweepMetricLabel(const std::string& m) {
  std::string label = escapeUnderscores(m);
  for (const auto& [k, v] : metricDescriptions())
    if (k == m) label = v;
  std::string unit = sweepMetricUnit(m);
  if (unit == "N*m") unit = "N·m";
  if (unit == "rad/s^2") unit = "rad/s²";
  return label + (unit.empty() ? "" : " [" + unit + "]");
}

SweepPointClass classifySweepPoint(const SweepPoint& p) {
  if (!p.complete || p.motion != "turning") return SweepPointClass::NoValue;
  return p.steady ? SweepPointClass::Steady : SweepPointClass::Unsteady;
}

std::vector<std::pair<double, double>> heatMapCellEdges(const std::vector<double>& v) {
  const std::size_t n = v.size();
  std::vector<std::pair<double, double>> e(n);
  if (n == 0) return e;
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return v[a] < v[b]; });
  if (n == 1) {
    const double h = std::max(0.5 * std::abs(v[0]), 0.5);
    e[0] = {v[0] - h, v[0] + h};
    return e;
  }
  for (std::size_t r = 0; r < n; ++r) {
    const double x = v[order[r]];
    const double lo = r == 0 ? x : 0.5 * (v[order[r - 1]] + x);
    const double hi = r + 1 == n ? x : 0.5 * (x + v[order[r + 1]]);
    e[order[r]] = {lo, hi};
  }
  return e;
}

namespace {

// Why a sweep gets no plots (empty: it gets them): only a grid over one or two numeric
// parameters is drawn, and only with gnuplot.
std::string noPlotsReason(const SweepOptions& o) {
  const bool all_numeric = std::all_of(o.params.begin(), o.params.end(),
                                       [](const SweepParameter& p) { return p.numeric(); });
  if (o.params.size() > 2) return "no plots: more than two parameters";
  if (!o.designs.empty()) return "no plots: the designs (values file or Latin hypercube) are not a grid";
  if (!all_numeric) return "no plots: a parameter has non-numeric values";
  if (!gnuplotAvailable()) return "no plots: gnuplot not found on PATH";
  return "";
}

// Only metrics with a finite, non-zero value at some drawable point are worth a figure.
bool worthAFigure(const SweepResult& r, const std::string& m) {
  bool worth = false;
  for (const SweepPoint& p : r.points) {
    const double v = p.metric(m);
    worth = worth || (classifySweepPoint(p) != SweepPointClass::NoValue && std::isfinite(v) && v != 0.0);
  }
  return worth;
}

// The grey hatched band (gnuplot object `obj`) over the cell of value x of parameter p that has no value.
std::string noValueBand(const SweepParameter& p, const std::vector<std::pair<double, double>>& edges, double x,
                        int obj) {
  // Index into the parameter's value list for the band's extent.
  std::size_t k = 0;
  while (k < p.values.size() && p.values[k] != x) ++k;
  double lo = x, hi = x;
  if (k < edges.size()) lo = edges[k].first, hi = edges[k].second;
  if (hi - lo <= 0) lo = x - 0.5, hi = x + 0.5;
  std::ostringstream band;
  band << "set object " << obj << " rect from " << num(lo) << ", graph 0 to " << num(hi)
       << ", graph 1 behind fc rgb '#999999' fs pattern 4 noborder\n";
  return band.str();
}

// The whole grid's extent along one parameter: from the first cell's lower edge to the last one's
// upper edge, so the edge cells are never clipped.
std::pair<double, double> gridExtent(const std::vector<std::pair<double, double>>& edges) {
  double lo = INFINITY, hi = -INFINITY;
  for (const auto& e : edges) lo = std::min(lo, e.first), hi = std::max(hi, e.second);
  return {lo, hi};
}

// The points in the order of the one parameter's value.
std::vector<std::size_t> orderOfParameter(const SweepResult& r) {
  std::vector<std::size_t> idx(r.points.size());
  std::iota(idx.begin(), idx.end(), 0);
  std::sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) {
    return r.points[a].values[0] < r.points[b].values[0];
  });
  return idx;
}

// A metric's curve over one parameter: steady points joined, unsteady ones marked, and the gnuplot
// commands that hatch the cells without a value.
struct MetricCurve {
  PlotSeries steady, unsteady;
  std::ostringstream pre;
  int obj = 1;
  bool any_bad = false;

  MetricCurve() {
    steady.title = "turning, steady state";
    steady.style = "linespoints pt 7";
    steady.break_at_nonfinite = true;
    steady.color = "#1f77b4";
    unsteady.title = "turning, steady state not reached";
    unsteady.style = "points pt 9 ps 1.5";
    unsteady.color = "#ff7f0e";
  }

  void add(const SweepParameter& param, const std::vector<std::pair<double, double>>& edges, const SweepPoint& p,
           double y) {
    const SweepPointClass c = classifySweepPoint(p);
    const double x = p.values[0];
    steady.x.push_back(x);
    steady.y.push_back(c == SweepPointClass::Steady ? y : kNaN);
    if (c == SweepPointClass::Unsteady) {
      unsteady.x.push_back(x);
      unsteady.y.push_back(y);
    }
    if (c == SweepPointClass::NoValue) {
      any_bad = true;
      pre << noValueBand(param, edges, x, obj++);
    }
  }
};

// One parameter: metric m against it, steady points joined, unsteady ones marked, the cells
// without a value hatched.
void drawMetricCurve(const SweepOptions& o, const SweepResult& r, const std::string& m, const std::string& out_dir) {
  PlotSpec spec;
  spec.title = escapeUnderscores(m + " vs " + o.params[0].key + " (" + o.model + " model)");
  spec.xlabel = escapeUnderscores(sweepParamLabel(o.params[0].key));
  spec.ylabel = sweepMetricLabel(m);
  const auto edges = heatMapCellEdges(o.params[0].values);
  MetricCurve curve;
  for (std::size_t i : orderOfParameter(r)) curve.add(o.params[0], edges, r.points[i], r.points[i].metric(m));
  // The whole grid stays in view, whichever points have values.
  const auto [xl, xh] = gridExtent(edges);
  if (xh > xl) curve.pre << "set xrange [" << num(xl) << ":" << num(xh) << "]\n";
  if (curve.any_bad)
    curve.pre << "set label 1 \"grey hatched: starting, rocking, stalled or failed (no value)\" at graph 0.01, graph 0.97 left front\n";
  spec.preamble = curve.pre.str();
  spec.series.push_back(curve.steady);
  if (!curve.unsteady.x.empty()) spec.series.push_back(curve.unsteady);
  renderPlot(spec, out_dir + "/plot_" + m);
}

// A cell's value as gnuplot label `lab` at the cell's centre (x, y).
std::string cellLabel(int lab, double v, double x, double y) {
  std::ostringstream label;
  label << "set label " << lab << " \"" << significant(v, 3) << "\" at " << num(x) << "," << num(y)
        << " center front font 'Sans,8'\n";
  return label.str();
}

// The heat map's cells (gnuplot objects): coloured by the value, hatched where there is none,
// overlaid where the steady state was not reached, labelled with the value up to 150 points.
// `ex`, `ey`: the cells' edges along x and y.
void addHeatMapCells(const SweepParameter& px, const std::vector<std::pair<double, double>>& ex,
                     const std::vector<std::pair<double, double>>& ey, const SweepResult& r, const std::string& m,
                     std::ostringstream& pre) {
  const bool labels = r.points.size() <= 150;
  int obj = 1, lab = 2;
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    const SweepPoint& p = r.points[i];
    const std::size_t iy = i / px.values.size(), ix = i % px.values.size();
    const auto [x0, x1] = ex[ix];
    const auto [y0, y1] = ey[iy];
    const std::string rect = "rect from " + num(x0) + "," + num(y0) + " to " + num(x1) + "," + num(y1);
    const SweepPointClass c = classifySweepPoint(p);
    const double v = p.metric(m);
    if (c == SweepPointClass::NoValue || !std::isfinite(v)) {
      pre << "set object " << obj++ << " " << rect << " fc rgb '#999999' fs pattern 4 border lc rgb '#666666'\n";
      continue;
    }
    pre << "set object " << obj++ << " " << rect << " fc palette cb " << num(v) << " fs solid 1.0 noborder\n";
    if (c == SweepPointClass::Unsteady)
      pre << "set object " << obj++ << " " << rect << " fc rgb '#000000' fs transparent pattern 5 noborder\n";
    if (labels) pre << cellLabel(lab++, v, 0.5 * (x0 + x1), 0.5 * (y0 + y1));
  }
}

// The colour scale's range: the metric's values at the points that have one (a little width when
// they are all equal).
std::pair<double, double> colourRange(const SweepResult& r, const std::string& m) {
  double lo = INFINITY, hi = -INFINITY;
  for (const SweepPoint& p : r.points) {
    const double v = p.metric(m);
    if (classifySweepPoint(p) != SweepPointClass::NoValue && std::isfinite(v))
      lo = std::min(lo, v), hi = std::max(hi, v);
  }
  if (hi <= lo) hi = lo + std::max(std::abs(lo) * 1e-6, 1e-12);
  return {lo, hi};
}

// One invisible point that uses the palette, so the colour box is drawn.
PlotSeries paletteAnchor(double x, double y, double lo) {
  PlotSeries anchor;
  anchor.title = "";
  anchor.style = "points pt 7 ps 0 lc palette cb " + num(lo);
  anchor.x = {x};
  anchor.y = {y};
  return anchor;
}

// Two parameters: a heat map of metric m, rows following the first parameter (y), columns the second (x).
void drawMetricHeatMap(const SweepOptions& o, const SweepResult& r, const std::string& m, const std::string& out_dir) {
  const SweepParameter &py = o.params[0], &px = o.params[1];
  const auto ex = heatMapCellEdges(px.values), ey = heatMapCellEdges(py.values);
  const auto [lo, hi] = colourRange(r, m);
  std::ostringstream pre;
  pre << "set palette rgb 33,13,10\nset cbrange [" << num(lo) << ":" << num(hi) << "]\n"
      << "unset key\nset cblabel \"" << sweepMetricLabel(m) << "\"\nset colorbox\nunset grid\n"
      << "set bmargin 6\nset label 1 \"" << kLegend << "\" at screen 0.02, screen 0.03 left\n";
  const auto [xl, xh] = gridExtent(ex);
  const auto [yl, yh] = gridExtent(ey);
  pre << "set xrange [" << num(xl) << ":" << num(xh) << "]\nset yrange [" << num(yl) << ":" << num(yh) << "]\n";
  addHeatMapCells(px, ex, ey, r, m, pre);
  PlotSpec spec;
  spec.title = escapeUnderscores(m + " (" + o.model + " model)");
  spec.xlabel = escapeUnderscores(sweepParamLabel(px.key));
  spec.ylabel = escapeUnderscores(sweepParamLabel(py.key));
  spec.width = 900;
  spec.height = 680;
  spec.preamble = pre.str();
  spec.series.push_back(paletteAnchor(px.values[0], py.values[0], lo));
  renderPlot(spec, out_dir + "/heatmap_" + m);
}

}  // namespace

std::vector<std::string> drawSweepPlots(const SweepOptions& o, const SweepResult& r,
                                        const std::string& out_dir, std::string* note) {
  std::vector<std::string> plots;
  *note = noPlotsReason(o);
  if (!note->empty()) return plots;
  for (const std::string& m : sweepNumericMetrics()) {
    if (!worthAFigure(r, m)) continue;
    if (o.params.size() == 1) {
      drawMetricCurve(o, r, m, out_dir);
      plots.push_back(out_dir + "/plot_" + m + ".png");
    } else {
      drawMetricHeatMap(o, r, m, out_dir);
      plots.push_back(out_dir + "/heatmap_" + m + ".png");
    }
  }
  return plots;
}

}  // namespace rollerdyn
