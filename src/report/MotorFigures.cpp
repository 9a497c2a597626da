#include "report/MotorFigures.h"

#include <algorithm>
#include <cmath>

#include "analysis/DriveSizing.h"
#include "analysis/StartUp.h"
#include "motor/BreakdownTorque.h"
#include "motor/SharedMotorLaw.h"
#include "report/FigureSupport.h"
#include "scene/MotorModels.h"

namespace rollerdyn {

namespace {

using namespace figures;  // FigureSupport.h

// The motor's nominal and breakdown points, at the rotor.
struct MotorMarks {
  double u = 1, eta = 1;          // reducer ratio and efficiency [-]
  double M_n = kNaN, w_n = kNaN;  // nominal torque [N·m] and rotor speed [rad/s]
  double M_kr = kNaN, w_kr = kNaN;  // breakdown torque [N·m] and rotor speed [rad/s]
  double P_n = kNaN;              // nominal shaft power M_n·ω_n [W]
};

// A catalogue law (circuit, Park machine) is drawn with its own curve: mark its own breakdown
// point (the curve's largest torque, where it lies) and its catalogue's rated point, not Kloss's
// (the second trial saw the M_kr marker at Kloss's s_kr beside a curve peaking elsewhere).
void markMachineLawPoints(const Scene& sc, MotorMarks& k) {
  try {
    const std::shared_ptr<const MotorLaw> law = sharedMotorLaw(sc);
    const SteadyTorquePeak peak = largestSteadyTorquePoint(*law, SupplyState{});  // the sizing's M_kr too
    k.w_kr = peak.speed;
    k.M_kr = peak.torque;
    const MotorCatalogue& cat = sc.induction.catalogue;
    if (sc.sizing.motor_omega_nominal <= 0 && cat.given() && cat.omega_nominal > 0) {
      k.w_n = cat.omega_nominal;
      k.M_n = law->steadyTorque(SupplyState{}, cat.omega_nominal);
    }
  } catch (const std::exception&) {
    // no law: the Kloss data stand
  }
}

MotorMarks motorMarks(const Scene& sc) {
  MotorMarks k;
  k.u = sc.reducer.ratio;
  k.eta = sc.reducer.efficiency;
  k.M_kr = sc.motor.breakdown_torque;
  const double w0 = sc.motor.omega_sync, s_kr = sc.motor.critical_slip;
  k.w_kr = w0 * (1.0 - s_kr);
  k.M_n = nominalMotorTorque(sc);
  if (sc.sizing.motor_omega_nominal > 0) {
    k.w_n = sc.sizing.motor_omega_nominal;
  } else if (std::isfinite(k.M_n) && k.M_n < k.M_kr) {
    // Kloss: M = 2·M_kr/(s/s_kr + s_kr/s) = M_n at s_n = s_kr·(λ - √(λ² - 1)), λ = M_kr/M_n.
    const double lambda = k.M_kr / k.M_n;
    k.w_n = w0 * (1.0 - s_kr * (lambda - std::sqrt(lambda * lambda - 1.0)));
  }
  if (isMachineLaw(sc.induction.model)) markMachineLawPoints(sc, k);
  k.P_n = k.M_n * k.w_n;
  return k;
}

std::string hline(double y, const char* color, const std::string& label) {
  if (!std::isfinite(y)) return "";
  return "set arrow from graph 0, first " + printfNumber("%.9g", y) + " to graph 1, first " + printfNumber("%.9g", y) +
         " nohead dt 2 lw 1.5 lc rgb '" + color + "' front\nset label \"" + label + "\" at graph 0.01, first " +
         printfNumber("%.9g", y) + " offset 0,0.6 font ',9' tc rgb '" + color + "' front\n";
}

// A marked point with a label on the Kloss curve.
std::string markPoint(int id, double x, double y, const char* color, const std::string& label) {
  if (!std::isfinite(x) || !std::isfinite(y)) return "";
  return "set label " + std::to_string(id) + " \"" + label + "\" at " + printfNumber("%.9g", x) + "," + printfNumber("%.9g", y) +
         " point pt 7 ps 1.8 lc rgb '" + color + "' offset 1,-1 font ',9' tc rgb '" + color + "' front\n";
}

// The y range spanning the data and a level line (the nominal or breakdown level), so the margin
// to it is visible; "" when the data have no spread.
std::string yRangeWithLevel(const std::vector<double>& y, double level) {
  double lo = 0, hi = 0;
  for (double v : y)
    if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  if (std::isfinite(level)) hi = std::max(hi, level);
  const double pad = 0.05 * (hi - lo);
  return hi > lo ? "set yrange [" + printfNumber("%.9g", lo - pad) + ":" + printfNumber("%.9g", hi + pad) + "]\n" : std::string();
}

// One of the motor's quantities drawn against time and crank angle, with its level lines.
struct MotorQuantity {
  const char* stem;       // figure name's stem
  const char* what;       // the quantity in words
  const char* ylabel;     // y axis label, with its unit
  std::vector<double> y;  // its values per row
  std::string lines;      // the gnuplot level lines (nominal, breakdown)
  double level;           // highest level line, kept in view [same unit as y]
};

// The rotor torque M = M_n1/(u·η) and the shaft power M·ω_r [kW] of the run's rows.
std::vector<MotorQuantity> torqueAndPowerQuantities(const MotorMarks& k, const std::vector<double>& w,
                                                    const std::vector<double>& m) {
  std::vector<double> M(m.size()), P(m.size());
  for (size_t i = 0; i < m.size(); ++i) {
    M[i] = m[i] / (k.u * k.eta);        // rotor torque
    P[i] = M[i] * k.u * w[i] * 1e-3;    // shaft power M·ω_r [kW]
  }
  const std::string lines_M = hline(k.M_n, kGreen, "nominal torque M_n") + hline(k.M_kr, kRed, "breakdown torque M_{kr}");
  const std::string lines_P = hline(k.P_n * 1e-3, kGreen, "nominal power P_n = M_n·ω_n");
  return {{"motor_torque", "motor torque", "motor torque at the rotor M [N·m]", std::move(M), lines_M, k.M_kr},
          {"motor_power", "motor shaft power", "shaft power M·ω_r [kW] (ω_r rotor speed)", std::move(P), lines_P,
           k.P_n * 1e-3}};
}

// The operating-point figure's caption: the Kloss curve of the papers or the law's own steady curve.
std::string operatingPointCaption(bool kloss_law) {
  return std::string(kloss_law ? "The motor's static Kloss characteristic reduced to the crank axis, M_n1 = M(u·ω_1)·u·η "
                                 "(Loveikin, Pochka, Romasevych (2018) eq. (37)"
                               : "The steady torque-speed curve of the motor's law at the rated supply (motor.model, "
                                 "fitted to its catalogue) reduced to the crank axis, M_n1 = M(u·ω_1)·u·η (") +
         "; M motor torque at the rotor, ω_1 motor speed reduced to the crank, u reducer ratio, η its efficiency), "
         "the run's operating points over the whole run (thin line; a start with switching transients or a "
         "starting method leaves the steady curve), the steady-window operating points (red), and the "
         "nominal and breakdown points.";
}

// The speeds and torques the steady window's operating points span.
struct OperatingRange {
  double wlo = INFINITY, whi = -INFINITY;  // speed reduced to the crank [rad/s]
  double mlo = INFINITY, mhi = -INFINITY;  // torque at the crank [N·m]
};

OperatingRange operatingRange(const std::vector<size_t>& rows, const std::vector<double>& w,
                              const std::vector<double>& m) {
  OperatingRange g;
  for (size_t r : rows)
    if (r < w.size() && r < m.size() && std::isfinite(w[r]) && std::isfinite(m[r])) {
      g.wlo = std::min(g.wlo, w[r]), g.whi = std::max(g.whi, w[r]);
      g.mlo = std::min(g.mlo, m[r]), g.mhi = std::max(g.mhi, m[r]);
    }
  return g;
}

struct MotorPlanner {
  const OutputFolder& out;
  const Scene* scene;
  const TimeWindow& window;
  const std::string& scene_label;
  std::vector<FigurePlan>& plans;
  std::vector<std::string>& notes;

  std::string title(const std::string& what) const {
    return scene_label.empty() ? what : scene_label + ": " + what;
  }
  void add(std::string name, std::string caption, PlotSpec spec) {
    plans.push_back({std::move(name), std::move(caption), std::move(spec)});
  }

  // A static law's torque is its curve at the run's speed: a note when the two disagree, so a run
  // made with other motor data (--set motor.*) is not silently drawn on a wrong curve. (A law with
  // states, or a starting method that changes the supply, leaves the curve by design.)
  template <class Curve>
  void noteRunOffCurve(const MotorLaw& law, const MotorMarks& k, const Curve& curve, const std::vector<double>& w,
                       const std::vector<double>& m, const char* curve_name) {
    const bool on_curve = law.stateCount() == 0 && !out.timeseries.has("supply_voltage_ratio");
    double dev = 0;
    for (size_t i = 0; on_curve && i < w.size() && i < m.size(); ++i)
      if (std::isfinite(w[i]) && std::isfinite(m[i])) dev = std::max(dev, std::abs(m[i] - curve(w[i])));
    const double scale = motorBreakdownTorque(*scene, &law) * k.u * k.eta;
    if (scale > 0 && dev > 1e-3 * scale)
      notes.push_back(std::string("motor operating point: the run's motor_torque differs from the ") + curve_name +
                      " of scene '" + scene->name + "' by up to " + printfNumber("%.3g", dev) +
                      " N·m; was the run made with other motor data (--set motor.* / reducer.*)? "
                      "Pass the same --scene and --set to `rollerdyn plot`.");
  }

  // The law's steady torque-speed curve reduced to the crank axis over [lo, hi] on p, a note when
  // the run's torque leaves a static law's curve; returns the nominal and breakdown marks.
  std::string lawCurve(PlotSpec& p, const MotorLaw& law, const MotorMarks& k, double lo, double& hi,
                       const std::vector<double>& w, const std::vector<double>& m) {
    const double u = k.u, eta = k.eta;
    hi = std::max(hi, 1.03 * scene->motor.omega_sync / u);
    // The law's steady torque-speed curve at the rated supply (the Kloss curve for motor.model kloss).
    auto curve = [&](double w_crank) { return law.steadyTorque(SupplyState{}, w_crank * u) * u * eta; };
    std::vector<double> cx, cy;
    const int n = 600;
    for (int i = 0; i <= n; ++i) {
      cx.push_back(lo + (hi - lo) * i / n);
      cy.push_back(curve(cx.back()));
    }
    const bool kloss = scene->induction.model == MotorModel::Kloss;
    const char* curve_name = kloss ? "Kloss curve" : "steady torque-speed curve";
    p.series.push_back(series(curve_name + std::string(" (scene ") + literal(scene->name) + ")", cx, cy, kGrey, 4.0));
    noteRunOffCurve(law, k, curve, w, m, curve_name);
    return markPoint(101, k.w_kr / u, k.M_kr * u * eta, kRed, "breakdown M_{kr}") +
           markPoint(102, k.w_n / u, k.M_n * u * eta, kGreen, "nominal M_n");
  }

  // The close-up on the steady window's operating range (zoom: the first figure's spec).
  void operatingPointZoom(PlotSpec zoom, const std::vector<size_t>& rows, const MotorMarks& k,
                          const std::vector<double>& w, const std::vector<double>& m) {
    const OperatingRange range = operatingRange(rows, w, m);
    const double wlo = range.wlo, whi = range.whi, mlo = range.mlo, mhi = range.mhi;
    if (!(whi > wlo) || !(mhi > mlo)) return;
    // Zoom on the operating range; the torque axis keeps the nominal and breakdown lines in view.
    const double dw = 0.5 * (whi - wlo);
    double ylo = std::min(0.0, mlo), yhi = mhi;
    if (scene) yhi = std::max(yhi, 1.05 * k.M_kr * k.u * k.eta);
    ylo -= 0.05 * (yhi - ylo);  // the lowest operating points stay off the frame
    zoom.title = title("motor operating points, steady window (" + windowText(window) + ")");
    zoom.preamble = "set key inside right center box opaque\nset xrange [" + printfNumber("%.9g", wlo - dw) + ":" +
                    printfNumber("%.9g", whi + dw) + "]\nset yrange [" + printfNumber("%.9g", ylo) + ":" + printfNumber("%.9g", yhi) + "]\n";
    if (scene)
      zoom.preamble += hline(k.M_n * k.u * k.eta, kGreen, "nominal torque M_n·u·η") +
                       hline(k.M_kr * k.u * k.eta, kRed, "breakdown torque M_{kr}·u·η");
    if (!zoom.series.empty() && scene) zoom.series[0].line_width = 2.0;
    if (zoom.series.size() >= 2) zoom.series[zoom.series.size() - 2].title = "whole run";
    if (!zoom.series.empty()) zoom.series.back().style = "points pt 7 ps 0.9";
    add("motor_operating_point_steady",
        "Close-up of the previous figure on the steady operating range: how far the motor's speed "
        "and torque swing on its characteristic while the crank turns, against its nominal torque "
        "M_n and breakdown torque M_kr (both reduced to the crank, × u·η).",
        std::move(zoom));
  }

  // The law's curve and marks on p, or a note why the figure has none; k gets the marks drawn.
  std::string curveAndMarks(PlotSpec& p, MotorMarks& k, double lo, double& hi, const std::vector<double>& w,
                            const std::vector<double>& m) {
    if (!scene) {
      notes.push_back("motor operating point drawn without its Kloss curve: no scene file (pass --scene FILE)");
      return "";
    }
    std::shared_ptr<const MotorLaw> law;
    try {
      law = sharedMotorLaw(*scene);
    } catch (const std::exception& ex) {
      notes.push_back(std::string("motor operating point drawn without its curve: ") + ex.what());
      return "";
    }
    k = motorMarks(*scene);
    return lawCurve(p, *law, k, lo, hi, w, m);
  }

  void operatingPoint(const std::vector<double>& t, const std::vector<double>& w,
                      const std::vector<double>& m) {
    PlotSpec p;
    const bool kloss_law = !scene || hasKlossCurve(scene->induction.model);
    p.title = title(kloss_law ? "motor operating points on its Kloss curve"
                              : "motor operating points on its steady torque-speed curve");
    p.xlabel = "motor speed reduced to the crank axis ω_1 = ω_r/u [rad/s]";
    p.ylabel = "motor torque at the crank axis M_{n1} = M·u·η [N·m]";
    p.preamble = "set key inside left bottom box opaque\n";
    double lo = 0, hi = 0;
    for (double v : w)
      if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
    MotorMarks k;
    p.preamble += curveAndMarks(p, k, lo, hi, w, m);
    const std::vector<size_t> rows = windowRows(t, window);
    p.series.push_back(series("start-up and whole run", w, m, kBlue, 0.8));
    PlotSeries steady = series("operating points, steady window", pick(w, rows), pick(m, rows), kRed);
    steady.style = "points pt 7 ps 0.6";
    if (window.found) p.series.push_back(steady);
    PlotSpec zoom = p;
    add("motor_operating_point", operatingPointCaption(kloss_law), std::move(p));
    if (!window.found || rows.empty()) return;
    operatingPointZoom(std::move(zoom), rows, k, w, m);
  }

  void quantityVsTime(const MotorQuantity& q, const std::vector<double>& t) {
    PlotSpec a;
    a.title = title(std::string(q.what) + " against time");
    a.xlabel = "t [s]";
    a.ylabel = q.ylabel;
    a.preamble = windowMarker(window) + "\nset key off\n" + q.lines + yRangeWithLevel(q.y, q.level);
    a.series.push_back(series("", t, q.y, kBlue));
    add(std::string(q.stem) + "_vs_time",
        capitalized(q.what) + " over the whole run, with the motor's nominal (green) and, for the "
        "torque, breakdown (red) levels; the dashed vertical line marks the start of the steady window.",
        std::move(a));
  }

  void quantityVsAngle(const MotorQuantity& q, const FoldedWindow& folded) {
    PlotSpec b;
    b.title = title(std::string(q.what) + " against crank angle (" + windowText(window) + ")");
    b.xlabel = kAngleLabel;
    b.ylabel = q.ylabel;
    b.preamble = std::string(kAnglePreamble) + "\nset key off\n" + q.lines + yRangeWithLevel(q.y, q.level);
    PlotSeries s = series("", folded.theta, folded.along(q.y), kBlue, 1.2);
    s.break_at_nonfinite = true;
    b.series.push_back(std::move(s));
    add(std::string(q.stem) + "_vs_angle",
        capitalized(q.what) + " against the crank angle over the steady window, one curve per "
        "revolution, with the nominal and breakdown levels.",
        std::move(b));
  }

  void torqueAndPower(const std::vector<double>& t, const std::vector<double>& w,
                      const std::vector<double>& m) {
    if (!scene) {
      notes.push_back("motor torque and power figures left out: no scene file for u and η (pass --scene FILE)");
      return;
    }
    const std::vector<double> phi = col(out.timeseries, "phi_crank");
    const FoldedWindow folded(t, phi, window);
    for (const MotorQuantity& q : torqueAndPowerQuantities(motorMarks(*scene), w, m)) {
      quantityVsTime(q, t);
      if (!phi.empty() && !folded.theta.empty()) quantityVsAngle(q, folded);
    }
  }
};

}  // namespace

void planMotorFigures(const OutputFolder& out, const Scene* scene, const TimeWindow& window,
                      const std::string& scene_label, std::vector<FigurePlan>& plans,
                      std::vector<std::string>& notes) {
  const std::vector<double> t = col(out.timeseries, "t"), w = col(out.timeseries, "omega_motor"),
                            m = col(out.timeseries, "motor_torque");
  if (!anyFinite(w) || !anyFinite(m)) {
    notes.push_back("motor figures left out: timeseries.csv has no omega_motor/motor_torque");
    return;
  }
  if (scene && !scene->motor.enabled) {
    notes.push_back("motor figures left out: the scene's motor is disabled (motor.enabled = false)");
    return;
  }
  MotorPlanner p{out, scene, window, scene_label, plans, notes};
  p.operatingPoint(t, w, m);
  p.torqueAndPower(t, w, m);
}

}  // namespace rollerdyn
