#include "report/RunFigures.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <set>
#include <stdexcept>

#include "analysis/SteadyState.h"
#include "report/ComparisonFigures.h"
#include "report/FigureSupport.h"
#include "report/MotorFigures.h"
#include "report/StartUpFigures.h"

namespace rollerdyn {

namespace {

using namespace figures;  // FigureSupport.h


// Every fixed figure name of planRunFigures() (plus comparison_<quantity>).
const std::set<std::string> kFigureNames = {
    "crank_speed_vs_angle",  "crank_accel_vs_angle",     "crank_speed_vs_time",
    "crank_accel_vs_time",   "coupling_torque_vs_time",  "motor_operating_point",
    "motor_operating_point_steady", "motor_torque_vs_time", "motor_torque_vs_angle",
    "motor_power_vs_time", "motor_power_vs_angle", "guide_reactions_vs_angle", "rod_forces_vs_angle",
    "twist_phase_rate",      "twist_phase_rate_accel",   "twist_phase_accel"};

// Number of carts j = 1, 2, ... for which `table` has column prefix + j.
int cartsWith(const Table& table, const std::string& prefix) {
  int n = 0;
  while (table.has(prefix + std::to_string(n + 1))) ++n;
  return n;
}

// A crank quantity drawn against the angle and against time.
struct CrankQuantity {
  const char* column;
  const char* what;
  const char* ylabel;
  const char* stem;
};

// A phase portrait of the twist: one of ψ, ψ', ψ'' against another.
struct TwistPortrait {
  const char* stem;
  const char* what;
  const std::vector<double>* x;
  const char* xl;
  const std::vector<double>* y;
  const char* yl;
  const char* fig;
};

struct Planner {
  const OutputFolder& out;
  const Scene* scene;
  std::vector<std::string>& notes;
  std::vector<FigurePlan> plans;
  std::string scene_label;
  TimeWindow window;

  void add(std::string name, std::string caption, PlotSpec spec) {
    plans.push_back({std::move(name), std::move(caption), std::move(spec)});
  }

  std::string title(const std::string& what) const { return sceneTitle(scene_label, what); }

  void crankFigures() {
    const Table& ts = out.timeseries;
    const std::vector<double> t = col(ts, "t"), phi = col(ts, "phi_crank");
    if (t.empty() || phi.empty()) {
      notes.push_back("crank speed/acceleration figures left out: timeseries.csv has no t or phi_crank");
      return;
    }
    const FoldedWindow folded(t, phi, window);
    const CrankQuantity qs[] = {{"omega_crank", "crank speed", "crank speed ω_2 [rad/s]", "crank_speed"},
                                {"eps_crank", "crank acceleration", "crank acceleration ε_2 [rad/s^2]", "crank_accel"}};
    for (const CrankQuantity& q : qs) {
      const std::vector<double> y = col(ts, q.column);
      if (!anyFinite(y)) {
        notes.push_back(std::string(q.stem) + " figures left out: timeseries.csv has no " + q.column);
        continue;
      }
      crankAngleFigure(q, folded, y);
      crankTimeFigure(q, t, y);
    }
  }

  void crankAngleFigure(const CrankQuantity& q, const FoldedWindow& folded, const std::vector<double>& y) {
    PlotSpec a;
    a.title = title(std::string(q.what) + " against crank angle (" + windowText(window) + ")");
    a.xlabel = kAngleLabel;
    a.ylabel = q.ylabel;
    a.preamble = std::string(kAnglePreamble) + "\nset key off";
    PlotSeries s = series("", folded.theta, folded.along(y), kBlue, 1.2);
    s.break_at_nonfinite = true;
    a.series.push_back(std::move(s));
    add(std::string(q.stem) + "_vs_angle",
        capitalized(q.what) + " of the crankshaft against its angle over the steady window, one "
        "curve per revolution (they coincide when the motion is periodic).",
        std::move(a));
  }

  void crankTimeFigure(const CrankQuantity& q, const std::vector<double>& t, const std::vector<double>& y) {
    PlotSpec b;
    b.title = title(std::string(q.what) + " against time");
    b.xlabel = "t [s]";
    b.ylabel = q.ylabel;
    b.preamble = windowMarker(window) + "\nset key off";
    b.series.push_back(series("", t, y, kBlue));
    add(std::string(q.stem) + "_vs_time",
        capitalized(q.what) + " over the whole run, from start-up; the dashed line marks the "
        "start of the steady window.",
        std::move(b));
  }

  void couplingFigure() {
    const std::vector<double> t = col(out.timeseries, "t"), m = col(out.timeseries, "coupling_torque");
    if (t.empty() || !anyFinite(m)) {
      notes.push_back("coupling torque figure left out: timeseries.csv has no coupling_torque");
      return;
    }
    PlotSpec p;
    p.title = title("coupling torque against time");
    p.xlabel = "t [s]";
    p.ylabel = "coupling torque M_c [N·m] (crank axis)";
    p.preamble = windowMarker(window) + "\nset key off";
    p.series.push_back(series("", t, m, kBlue));
    add("coupling_torque_vs_time",
        "Torque the coupling transmits to the crankshaft (elastic plus damping part, reduced to "
        "the crank axis) over the whole run.",
        std::move(p));
  }

  // The crank angle at the reactions' rows: their own column, else the time series' (interpolated
  // where the rows differ). False (with a note) when there is none.
  bool reactionCrankAngle(const std::vector<double>& t, std::vector<double>& phi) {
    const Table& rx = out.reactions;
    if (rx.has("phi_crank")) {
      phi = rx.column("phi_crank");
      return true;
    }
    const std::vector<double> ts_t = col(out.timeseries, "t"), ts_phi = col(out.timeseries, "phi_crank");
    if (ts_t.empty() || ts_phi.empty() || t.empty()) {
      notes.push_back("guide reaction and rod force figures left out: no crank angle (timeseries.csv)");
      return false;
    }
    const bool same = ts_t.size() == t.size() && ts_t.front() == t.front() && ts_t.back() == t.back();
    for (size_t i = 0; i < t.size(); ++i) phi.push_back(same ? ts_phi[i] : interp(ts_t, ts_phi, t[i]));
    return true;
  }

  void reactionFigures() {
    if (!out.has_reactions) {
      notes.push_back("guide reaction and rod force figures left out: no reactions.csv");
      return;
    }
    const std::vector<double> t = col(out.reactions, "t");
    std::vector<double> phi;
    if (!reactionCrankAngle(t, phi)) return;
    const FoldedWindow folded(t, phi, window);
    guideReactionFigure(folded);
    rodForceFigure(folded);
  }

  void guideReactionFigure(const FoldedWindow& folded) {
    const Table& rx = out.reactions;
    const int n_guide = std::min(cartsWith(rx, "N_front_"), cartsWith(rx, "N_rear_"));
    if (n_guide <= 0) {
      notes.push_back("guide reaction figure left out: reactions.csv has no N_front_j/N_rear_j");
      return;
    }
    PlotSpec p;
    p.title = title("guide reactions against crank angle (" + windowText(window) + ")");
    p.xlabel = kAngleLabel;
    p.ylabel = "guide reaction N [N] (> 0: guide presses the roller down)";
    p.preamble = kAnglePreamble;
    for (int j = 1; j <= n_guide; ++j)
      for (const char* side : {"front", "rear"}) p.series.push_back(guideReactionSeries(folded, j, side));
    add("guide_reactions_vs_angle",
        "Normal forces of the front (solid) and rear (dashed) guide rollers of every cart over the "
        "steady window, one colour per cart (N > 0 when the guide presses the roller down, Loveikin, Pochka, Romasevych (2018) fig. 3).",
        std::move(p));
  }

  // Cart j's front (solid) or rear (dashed) guide reaction in its cart's colour.
  PlotSeries guideReactionSeries(const FoldedWindow& folded, int j, const std::string& side) const {
    PlotSeries s = series("N_{" + side + "," + std::to_string(j) + "}", folded.theta,
                          folded.along(out.reactions.column("N_" + side + "_" + std::to_string(j))), cartColor(j), 1.3);
    s.break_at_nonfinite = true;
    if (side == "rear") s.dash = 2;
    return s;
  }

  void rodForceFigure(const FoldedWindow& folded) {
    const Table& rx = out.reactions;
    const int n_rod = cartsWith(rx, "F_rod_");
    if (n_rod <= 0) {
      notes.push_back("rod force figure left out: reactions.csv has no F_rod_j");
      return;
    }
    PlotSpec p;
    p.title = title("rod forces against crank angle (" + windowText(window) + ")");
    p.xlabel = kAngleLabel;
    p.ylabel = "rod force F [N] (> 0: tension)";
    p.preamble = kAnglePreamble;
    for (int j = 1; j <= n_rod; ++j) {
      PlotSeries s = series("F_{rod," + std::to_string(j) + "}", folded.theta,
                            folded.along(rx.column("F_rod_" + std::to_string(j))), cartColor(j), 1.3);
      s.break_at_nonfinite = true;
      p.series.push_back(std::move(s));
    }
    add("rod_forces_vs_angle",
        "Axial force in each connecting rod over the steady window (> 0 in tension, Loveikin, Pochka, Romasevych (2018) eq. (14)).",
        std::move(p));
  }

  void twistFigures() {
    const Table& ts = out.timeseries;
    const std::vector<double> t = col(ts, "t"), psi = col(ts, "twist"), rate = col(ts, "twist_rate"),
                              acc = col(ts, "twist_accel");
    if (psi.empty() || rate.empty() || acc.empty()) {
      notes.push_back("twist phase portraits left out: timeseries.csv has no twist, twist_rate, twist_accel");
      return;
    }
    if (absMax(psi) == 0 && absMax(rate) == 0) {
      notes.push_back("twist phase portraits left out: the coupling does not twist (rigid coupling)");
      return;
    }
    const std::vector<size_t> rows = windowRows(t, window);
    const std::vector<double> p0 = pick(psi, rows), p1 = pick(rate, rows), p2 = pick(acc, rows);
    const char* l0 = "twist ψ = φ_1 - φ_2, motor minus crank angle (crank axis) [rad]";
    const char* l1 = "twist rate dψ/dt [rad/s]";
    const char* l2 = "twist acceleration d^2ψ/dt^2 [rad/s^2]";
    const TwistPortrait ps[] = {{"twist_phase_rate", "twist rate against twist", &p0, l0, &p1, l1, "8"},
                                {"twist_phase_rate_accel", "twist acceleration against twist rate", &p1, l1, &p2, l2, "9"},
                                {"twist_phase_accel", "twist acceleration against twist", &p0, l0, &p2, l2, "10"}};
    for (const TwistPortrait& q : ps) twistPortraitFigure(q);
  }

  void twistPortraitFigure(const TwistPortrait& q) {
    PlotSpec p;
    p.title = title("phase portrait: " + std::string(q.what) + " (" + windowText(window) + ")");
    p.xlabel = q.xl;
    p.ylabel = q.yl;
    p.preamble = "set key off";
    p.width = 720;
    p.height = 620;
    p.series.push_back(series("", *q.x, *q.y, kBlue));
    add(q.stem,
        "Phase portrait of the coupling twist over the steady window, as in Loveikin, Pochka, Romasevych (2018) fig. " +
            std::string(q.fig) + ": a closed loop is a periodic steady state.",
        std::move(p));
  }
};

}  // namespace

using figures::kNaN;
using figures::kPi;

TimeWindow steadyWindow(const OutputFolder& out) {
  TimeWindow w;
  if (out.has_summary && out.summary.contains("steady_state") && out.summary["steady_state"].is_object()) {
    const auto& ss = out.summary["steady_state"];
    if (ss.contains("t_begin") && ss.contains("t_end") && ss["t_begin"].is_number() && ss["t_end"].is_number()) {
      w.t_begin = ss["t_begin"].get<double>();
      w.t_end = ss["t_end"].get<double>();
      if (w.t_end > w.t_begin) {
        w.found = true;
        w.source = "summary.json";
        return w;
      }
    }
  }
  if (out.has_timeseries && out.timeseries.has("t") && out.timeseries.has("phi_crank")) {
    const SteadyState ss = detectSteadyState(out.timeseries, 5.0);
    if (std::isfinite(ss.t_begin) && std::isfinite(ss.t_end) && ss.t_end > ss.t_begin) {
      w.t_begin = ss.t_begin;
      w.t_end = ss.t_end;
      w.found = true;
      w.source = "detected";
    }
  }
  return w;
}

std::vector<double> foldedAngle(const std::vector<double>& phi, std::vector<long>* index) {
  std::vector<double> out;
  if (index) index->clear();
  double prev = kNaN;
  for (size_t i = 0; i < phi.size(); ++i) {
    double a = std::fmod(phi[i], 2 * kPi);
    if (a < 0) a += 2 * kPi;
    if (std::isfinite(prev) && std::isfinite(a) && std::abs(a - prev) > kPi) {
      out.push_back(kNaN);  // wrapped: start a new curve
      if (index) index->push_back(-1);
    }
    out.push_back(a);
    if (index) index->push_back(static_cast<long>(i));
    prev = a;
  }
  return out;
}

std::vector<FigurePlan> planRunFigures(const OutputFolder& out, const Scene* scene,
                                       std::vector<std::string>& notes) {
  Planner p{out, scene, notes, {}, "", {}};
  if (scene) {
    p.scene_label = literal(scene->name);
  } else if (out.has_summary && out.summary.contains("scene") && out.summary["scene"].is_string()) {
    p.scene_label = literal(out.summary["scene"].get<std::string>());
  }
  p.window = steadyWindow(out);
  if (out.has_timeseries) {
    if (!p.window.found) notes.push_back("no steady window found: the angle plots show the whole run");
    p.crankFigures();
    p.couplingFigure();
    planMotorFigures(out, scene, p.window, p.scene_label, p.plans, notes);  // MotorFigures.h
    planStartUpFigures(out, p.window, p.scene_label, p.plans, notes);     // StartUpFigures.h
    p.reactionFigures();
    p.twistFigures();
  } else if (out.has_summary || out.has_reactions) {
    notes.push_back("time-series figures left out: no timeseries.csv");
  }
  planComparisonFigures(out, p.window, p.scene_label, p.plans, notes);  // ComparisonFigures.h
  return std::move(p.plans);
}

namespace {

// A figure of an earlier plot that this run does not have (e.g. comparison_* after a run with
// other --set values) would sit next to the new ones as if it belonged to them: remove it.
// Only files named like the figures of this file are touched.
void removeStaleFigures(const std::string& fig_dir, const std::set<std::string>& drawn) {
  namespace fs = std::filesystem;
  for (const auto& entry : fs::directory_iterator(fig_dir)) {
    const fs::path& p = entry.path();
    if (p.extension() != ".png" && p.extension() != ".svg") continue;
    const std::string stem = p.stem().string();
    if (drawn.count(stem) || !isRunFigureName(stem)) continue;
    std::error_code ec;
    fs::remove(p, ec);
  }
}

}  // namespace

FigureSet drawRunFigures(const OutputFolder& out, const Scene* scene, const std::string& fig_dir,
                         const FigureOptions& options) {
  FigureSet set;
  const std::vector<FigurePlan> plans = planRunFigures(out, scene, set.notes);
  if (plans.empty()) return set;
  if (!gnuplotAvailable())
    throw std::runtime_error("gnuplot not found: install the Debian package gnuplot-nox (scripts/setup.sh)");
  namespace fs = std::filesystem;
  fs::create_directories(fig_dir);
  std::set<std::string> drawn;
  std::vector<PlotJob> jobs;
  for (const FigurePlan& plan : plans) jobs.push_back(plotJob(plan.spec, (fs::path(fig_dir) / plan.name).string(), options.png, options.svg));
  renderPlots(jobs);  // a few gnuplot processes at once, each drawing several figures
  for (const FigurePlan& plan : plans) {
    const std::string base = (fs::path(fig_dir) / plan.name).string();
    set.figures.push_back({plan.name, plan.caption, options.png ? base + ".png" : "",
                           options.svg ? base + ".svg" : ""});
    drawn.insert(plan.name);
  }
  removeStaleFigures(fig_dir, drawn);
  return set;
}

bool isRunFigureName(const std::string& stem) {
  const std::vector<std::string>& start_up = startUpFigureNames();
  return kFigureNames.count(stem) || stem.rfind("comparison_", 0) == 0 ||
         std::find(start_up.begin(), start_up.end(), stem) != start_up.end();
}

std::string figureSetText(const FigureSet& set, const std::string& fig_dir) {
  std::string s = std::to_string(set.figures.size()) + " figures in " + fig_dir + "/ (png and svg):";
  for (const FigureFile& f : set.figures) s += " " + f.name;
  s += "\n";
  for (const std::string& n : set.notes) s += "note: " + n + "\n";
  return s;
}

}  // namespace rollerdyn
