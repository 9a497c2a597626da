#include "report/RunFigures.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <set>
#include <stdexcept>

#include "analysis/SteadyState.h"
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

// Number of carts j = 1, 2, ... for which `table` has column prefix + j.
int cartsWith(const Table& table, const std::string& prefix) {
  int n = 0;
  while (table.has(prefix + std::to_string(n + 1))) ++n;
  return n;
}

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

  std::string title(const std::string& what) const {
    return scene_label.empty() ? what : scene_label + ": " + what;
  }

  void crankFigures() {
    const Table& ts = out.timeseries;
    const std::vector<double> t = col(ts, "t"), phi = col(ts, "phi_crank");
    if (t.empty() || phi.empty()) {
      notes.push_back("crank speed/acceleration figures left out: timeseries.csv has no t or phi_crank");
      return;
    }
    const std::vector<size_t> rows = windowRows(t, window);
    std::vector<long> fold;
    const std::vector<double> theta = foldedAngle(pick(phi, rows), &fold);
    struct Q {
      const char* column;
      const char* what;
      const char* ylabel;
      const char* stem;
    };
    const Q qs[] = {{"omega_crank", "crank speed", "crank speed ω_2 [rad/s]", "crank_speed"},
                    {"eps_crank", "crank acceleration", "crank acceleration ε_2 [rad/s^2]", "crank_accel"}};
    for (const Q& q : qs) {
      const std::vector<double> y = col(ts, q.column);
      if (!anyFinite(y)) {
        notes.push_back(std::string(q.stem) + " figures left out: timeseries.csv has no " + q.column);
        continue;
      }
      PlotSpec a;
      a.title = title(std::string(q.what) + " against crank angle (" + windowText(window) + ")");
      a.xlabel = kAngleLabel;
      a.ylabel = q.ylabel;
      a.preamble = std::string(kAnglePreamble) + "\nset key off";
      PlotSeries s = series("", theta, alongFold(pick(y, rows), fold), kBlue, 1.2);
      s.break_at_nonfinite = true;
      a.series.push_back(std::move(s));
      add(std::string(q.stem) + "_vs_angle",
          capitalized(q.what) + " of the crankshaft against its angle over the steady window, one "
          "curve per revolution (they coincide when the motion is periodic).",
          std::move(a));

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

  void reactionFigures() {
    if (!out.has_reactions) {
      notes.push_back("guide reaction and rod force figures left out: no reactions.csv");
      return;
    }
    const Table& rx = out.reactions;
    const std::vector<double> t = col(rx, "t");
    std::vector<double> phi;
    if (rx.has("phi_crank")) {
      phi = rx.column("phi_crank");
    } else {
      const std::vector<double> ts_t = col(out.timeseries, "t"), ts_phi = col(out.timeseries, "phi_crank");
      if (ts_t.empty() || ts_phi.empty() || t.empty()) {
        notes.push_back("guide reaction and rod force figures left out: no crank angle (timeseries.csv)");
        return;
      }
      const bool same = ts_t.size() == t.size() && ts_t.front() == t.front() && ts_t.back() == t.back();
      for (size_t i = 0; i < t.size(); ++i) phi.push_back(same ? ts_phi[i] : interp(ts_t, ts_phi, t[i]));
    }
    const std::vector<size_t> rows = windowRows(t, window);
    std::vector<long> fold;
    const std::vector<double> theta = foldedAngle(pick(phi, rows), &fold);
    auto along = [&](const std::string& c) { return alongFold(pick(rx.column(c), rows), fold); };

    const int n_guide = std::min(cartsWith(rx, "N_front_"), cartsWith(rx, "N_rear_"));
    if (n_guide > 0) {
      PlotSpec p;
      p.title = title("guide reactions against crank angle (" + windowText(window) + ")");
      p.xlabel = kAngleLabel;
      p.ylabel = "guide reaction N [N] (> 0: guide presses the roller down)";
      p.preamble = kAnglePreamble;
      for (int j = 1; j <= n_guide; ++j)
        for (const char* side : {"front", "rear"}) {
          PlotSeries s = series("N_{" + std::string(side) + "," + std::to_string(j) + "}", theta,
                                along("N_" + std::string(side) + "_" + std::to_string(j)), cartColor(j), 1.3);
          s.break_at_nonfinite = true;
          if (std::string(side) == "rear") s.dash = 2;
          p.series.push_back(std::move(s));
        }
      add("guide_reactions_vs_angle",
          "Normal forces of the front (solid) and rear (dashed) guide rollers of every cart over the "
          "steady window, one colour per cart (N > 0 when the guide presses the roller down, Loveikin, Pochka, Romasevych (2018) fig. 3).",
          std::move(p));
    } else {
      notes.push_back("guide reaction figure left out: reactions.csv has no N_front_j/N_rear_j");
    }
    const int n_rod = cartsWith(rx, "F_rod_");
    if (n_rod > 0) {
      PlotSpec p;
      p.title = title("rod forces against crank angle (" + windowText(window) + ")");
      p.xlabel = kAngleLabel;
      p.ylabel = "rod force F [N] (> 0: tension)";
      p.preamble = kAnglePreamble;
      for (int j = 1; j <= n_rod; ++j) {
        PlotSeries s = series("F_{rod," + std::to_string(j) + "}", theta, along("F_rod_" + std::to_string(j)),
                              cartColor(j), 1.3);
        s.break_at_nonfinite = true;
        p.series.push_back(std::move(s));
      }
      add("rod_forces_vs_angle",
          "Axial force in each connecting rod over the steady window (> 0 in tension, Loveikin, Pochka, Romasevych (2018) eq. (14)).",
          std::move(p));
    } else {
      notes.push_back("rod force figure left out: reactions.csv has no F_rod_j");
    }
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
    struct P {
      const char* stem;
      const char* what;
      const std::vector<double>* x;
      const char* xl;
      const std::vector<double>* y;
      const char* yl;
      const char* fig;
    };
    const P ps[] = {{"twist_phase_rate", "twist rate against twist", &p0, l0, &p1, l1, "8"},
                    {"twist_phase_rate_accel", "twist acceleration against twist rate", &p1, l1, &p2, l2, "9"},
                    {"twist_phase_accel", "twist acceleration against twist", &p0, l0, &p2, l2, "10"}};
    for (const P& q : ps) {
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
  }

  void comparisonFigures() {
    if (!out.has_comparison) return;
    const Table& c = out.comparison;
    const std::vector<double> t = col(c, "t");
    if (t.empty()) {
      notes.push_back("comparison figures left out: comparison.csv has no t column");
      return;
    }
    // comparison.csv left in a folder by `compare` may come from another run than the folder's
    // timeseries.csv (other --set values): its multibody column then differs from this run.
    if (out.has_timeseries && c.has("omega_crank_multibody") && out.timeseries.has("t") &&
        out.timeseries.has("omega_crank")) {
      const std::vector<double> ts_t = out.timeseries.column("t"), ts_w = out.timeseries.column("omega_crank"),
                                cw = c.column("omega_crank_multibody");
      double dev = 0, scale = 0;
      for (size_t i = 0; i < t.size(); ++i) {
        const double here = interp(ts_t, ts_w, t[i]);
        if (!std::isfinite(here) || !std::isfinite(cw[i])) continue;
        dev = std::max(dev, std::abs(here - cw[i]));
        scale = std::max(scale, std::abs(cw[i]));
      }
      if (dev > 1e-6 * std::max(scale, 1.0)) {
        notes.push_back("comparison figures left out: comparison.csv comes from another run (its multibody "
                        "omega_crank differs from timeseries.csv by up to " + fmt("%.3g", dev) +
                        " rad/s); run `rollerdyn compare` with the same scene and --set into this folder");
        return;
      }
    }
    // Over the whole run the oscillations merge into a band: draw the steady window, else the
    // last quarter of the compared span.
    TimeWindow cw = window;
    if (!cw.found && t.size() > 1) {
      cw.t_end = t.back();
      cw.t_begin = t.back() - 0.25 * (t.back() - t.front());
      cw.found = true;
    }
    const std::vector<size_t> rows = windowRows(t, cw);
    const std::vector<double> tw = pick(t, rows);
    const std::string suffix = "_multibody";
    int drawn = 0;
    for (const std::string& name : c.columns) {
      if (name.size() <= suffix.size() || name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
        continue;
      const std::string q = name.substr(0, name.size() - suffix.size());
      PlotSpec p;
      p.title = title("multibody vs reduced model: " + literal(q) + " (" + windowText(cw) + ")");
      p.xlabel = "t [s]";
      p.ylabel = literal(q) + " [" + unitOf(q) + "]";
      p.preamble = "set key below\nset xrange [" + fmt("%.9g", tw.empty() ? 0.0 : tw.front()) + ":" +
                   fmt("%.9g", tw.empty() ? 1.0 : tw.back()) + "]";
      p.series.push_back(series("multibody (Simbody)", tw, pick(c.column(name), rows), kBlue, 2.0));
      if (c.has(q + "_reduced"))
        p.series.push_back(series("reduced-mass model", tw, pick(c.column(q + "_reduced"), rows), kOrange, 1.5));
      if (c.has(q + "_reduced_kinetostatic"))
        p.series.push_back(series("reduced model, kinetostatic reactions", tw,
                                  pick(c.column(q + "_reduced_kinetostatic"), rows), kGreen, 1.5));
      add("comparison_" + fileSafe(q),
          "The multibody model against the papers' reduced-mass model for " + q +
              " (comparison.csv of `rollerdyn compare`), over " +
              (window.found ? "the steady window" : "the last quarter of the run") + ".",
          std::move(p));
      ++drawn;
    }
    if (drawn == 0) notes.push_back("comparison figures left out: comparison.csv has no <quantity>_multibody columns");
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
  p.comparisonFigures();
  return std::move(p.plans);
}

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
  // A figure of an earlier plot that this run does not have (e.g. comparison_* after a run with
  // other --set values) would sit next to the new ones as if it belonged to them: remove it.
  // Only files named like the figures of this file are touched.
  for (const auto& entry : fs::directory_iterator(fig_dir)) {
    const fs::path& p = entry.path();
    if (p.extension() != ".png" && p.extension() != ".svg") continue;
    const std::string stem = p.stem().string();
    if (drawn.count(stem) || !isRunFigureName(stem)) continue;
    std::error_code ec;
    fs::remove(p, ec);
  }
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
