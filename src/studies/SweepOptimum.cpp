// The optimum of a sweep (declared in Sweep.h): the best grid point, the parabola's vertex as a
// prediction, and the judgement of the vertex's run. What the console, sweep.json and Python say
// about the optimum is rendered from the SweepOptimum these fill in.
#include <cmath>
#include <limits>
#include <sstream>

#include "scene/SceneSchema.h"
#include "studies/Sweep.h"
#include "io/FieldFormat.h"

namespace rollerdyn {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Whether any completed point reached steady state with a finite metric: then only such points
// are candidates.
bool anySteady(const std::vector<SweepPoint>& points, const std::string& metric) {
  for (const SweepPoint& p : points)
    if (p.complete && p.steady && std::isfinite(p.metric(metric))) return true;
  return false;
}

// A rocking or stalled crank, or one still starting when its run ended, is never an optimum,
// whatever its number says.
bool candidate(const SweepPoint& p, const std::string& metric, bool any_steady) {
  return p.complete && p.motion != "rocking" && p.motion != "stalled" && p.motion != "starting" &&
         std::isfinite(p.metric(metric)) && (!any_steady || p.steady);
}

std::string number(double v) { return significant(v, 6); }

// The best candidate point into opt: its index, value and steadiness (found stays false without one).
void bestGridPoint(const std::vector<SweepPoint>& points, bool any_steady, SweepOptimum& opt) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!candidate(points[i], opt.metric, any_steady)) continue;
    if (!opt.found || points[i].metric(opt.metric) < opt.value) {
      opt.found = true;
      opt.index = i;
      opt.value = points[i].metric(opt.metric);
      opt.steady = points[i].steady;
    }
  }
}

// The vertex of the parabola through the best point and its two neighbours, where it opens upwards:
// the value to run (as --set applies it), the predicted minimum and the grid to refine.
void fitParabolaVertex(const std::vector<SweepPoint>& points, SweepOptimum& opt) {
  const double x0 = points[opt.index - 1].values[0], x1 = points[opt.index].values[0],
               x2 = points[opt.index + 1].values[0];
  const double y0 = points[opt.index - 1].metric(opt.metric), y1 = opt.value,
               y2 = points[opt.index + 1].metric(opt.metric);
  const double den = (x0 - x1) * (x0 - x2) * (x1 - x2);
  if (den == 0.0) return;
  const double A = (x2 * (y1 - y0) + x1 * (y0 - y2) + x0 * (y2 - y1)) / den;
  const double B = (x2 * x2 * (y0 - y1) + x1 * x1 * (y2 - y0) + x0 * x0 * (y1 - y2)) / den;
  const double C = (x1 * x2 * (x1 - x2) * y0 + x2 * x0 * (x2 - x0) * y1 + x0 * x1 * (x0 - x1) * y2) / den;
  if (!(A > 0.0)) return;
  SweepVertex& v = opt.vertex;
  v.available = true;
  v.text = formatNumber(-B / (2 * A));  // what --set applies; the run uses exactly this value
  v.parameter = std::stod(v.text);
  v.predicted = C - B * B / (4 * A);
  v.value = kNaN;
  v.tolerance = 0;
  v.refine_lower = std::min(x0, x2);
  v.refine_upper = std::max(x0, x2);
  v.refine_step = std::stod(formatNumber((v.refine_upper - v.refine_lower) / 20.0));
  v.note = "not run";
}

}  // namespace

SweepOptimum findOptimum(const std::vector<SweepParameter>& params,
                         const std::vector<SweepPoint>& points, const std::string& metric) {
  SweepOptimum opt;
  opt.metric = metric;
  const bool any_steady = anySteady(points, metric);
  bestGridPoint(points, any_steady, opt);
  opt.grid_value = opt.value;
  if (!opt.found) {
    opt.note = "no completed point has a finite " + metric;
    return opt;
  }
  opt.note = any_steady ? "minimum over the points that completed at steady state"
                        : "no point reached steady state: minimum over the completed points";
  if (params.size() == 1 && params[0].numeric() && opt.index > 0 && opt.index + 1 < points.size() &&
      candidate(points[opt.index - 1], metric, any_steady) && candidate(points[opt.index + 1], metric, any_steady))
    fitParabolaVertex(points, opt);
  return opt;
}

namespace {

// What the run at the vertex says about the parabola's estimate.
std::string vertexRunNote(const SweepVertex& v, const SweepPoint& run) {
  if (!v.usable)
    return "run, not usable: " + (run.complete ? "the crank is " + run.motion + (run.steady ? "" : ", no steady state")
                                               : run.status);
  if (v.holds) return "run; the parabola's estimate holds within the integration tolerance";
  if (v.lower) return "run; lower than the parabola's estimate: the metric is no parabola between the grid points";
  return "run; the parabola's estimate does not hold: the minimum is a kink or lies between grid points";
}

}  // namespace

void judgeVertexRun(SweepOptimum& opt, const std::vector<SweepPoint>& points, const SweepPoint& run, double accuracy) {
  SweepVertex& v = opt.vertex;
  if (!opt.found || !v.available) return;
  v.ran = true;
  v.point = run;
  const std::string& m = opt.metric;
  v.usable = candidate(run, m, anySteady(points, m));
  v.value = v.usable ? run.metric(m) : kNaN;
  // The integration tolerance of the comparison: the integrator's relative accuracy times the
  // metric's size at the three grid points the parabola went through.
  double scale = 0;
  for (std::size_t i = opt.index - 1; i <= opt.index + 1; ++i) scale = std::max(scale, std::abs(points[i].metric(m)));
  v.tolerance = accuracy * scale;
  v.holds = v.usable && std::abs(v.value - v.predicted) <= v.tolerance;
  v.lower = v.usable && v.value < v.predicted - v.tolerance;
  opt.at_vertex = v.usable && v.value < opt.grid_value;
  if (opt.at_vertex) {
    opt.value = v.value;
    opt.steady = run.steady;
  }
  v.note = vertexRunNote(v, run);
}

namespace {

// Where to refine the grid when the parabola's estimate does not hold: near the better of the vertex
// and the best grid design, with the --values range that does it.
std::string refineAdvice(const SweepOptimum& opt, const SweepPoint& best) {
  const SweepVertex& v = opt.vertex;
  return "refine the grid near " + (opt.at_vertex ? v.text : best.texts[0]) + " (--values " +
         formatNumber(v.refine_lower) + ":" + formatNumber(v.refine_upper) + ":" + formatNumber(v.refine_step) + ")";
}

// The second line: the parabola's estimate and what the run at its vertex gave.
std::string vertexVerdict(const SweepOptions& o, const SweepOptimum& opt, const SweepPoint& best) {
  const SweepVertex& v = opt.vertex;
  const std::string where = o.params[0].key + "=" + v.text;
  const std::string estimate = "the parabola through the neighbours puts the minimum at " + where + " with " +
                               opt.metric + " = " + number(v.predicted);
  std::ostringstream os;
  if (!v.ran) {
    os << estimate << ": an estimate, " << v.note;
  } else if (!v.usable) {
    os << estimate << ": a run there is not usable (" << v.note.substr(v.note.find(": ") + 2) << ")";
  } else if (v.holds) {
    os << estimate << "; a run there gives " << number(v.value) << " (the estimate holds)";
  } else {
    const std::string refine = refineAdvice(opt, best);
    if (v.lower)
      os << estimate << "; a run there gives " << number(v.value)
         << ", lower still: the metric is no parabola between the grid points; " << refine;
    else
      os << "the parabola's estimate " << opt.metric << " = " << number(v.predicted) << " at " << where
         << " does not hold: a run there gives " << number(v.value)
         << "; the minimum is a kink or lies between grid points: " << refine;
  }
  return os.str();
}

}  // namespace

std::string describeOptimum(const SweepOptions& o, const SweepResult& r) {
  const SweepOptimum& opt = r.optimum;
  if (opt.metric.empty()) return "";
  if (!opt.found) return "minimum of " + opt.metric + ": none (" + opt.note + ")";
  const SweepVertex& v = opt.vertex;
  const SweepPoint& best = r.points[opt.index];
  std::string grid_at;
  for (std::size_t k = 0; k < o.params.size(); ++k) grid_at += " " + o.params[k].key + "=" + best.texts[k];
  const std::string steady = opt.steady ? " (steady state reached)" : " (steady state NOT reached)";
  std::ostringstream os;
  if (opt.at_vertex)
    os << "minimum of " << opt.metric << " = " << number(opt.value) << " at " << o.params[0].key << "=" << v.text
       << steady << ", a run at the vertex of the parabola through the best grid point" << grid_at << " ("
       << opt.metric << " = " << number(opt.grid_value) << ") and its neighbours";
  else
    os << "minimum of " << opt.metric << " = " << number(opt.value) << " at" << grid_at << steady;
  if (!v.available) return os.str();
  os << "\n" << vertexVerdict(o, opt, best);
  return os.str();
}

}  // namespace rollerdyn
