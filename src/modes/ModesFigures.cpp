#include "modes/ModesFigures.h"

#include <cmath>
#include <sstream>

#include "io/FieldFormat.h"
#include "report/Gnuplot.h"

namespace rollerdyn::modes {
namespace {

FigureFile fileOf(const std::string& dir, const std::string& name, const std::string& caption) {
  return {name, caption, dir + "/" + name + ".png", dir + "/" + name + ".svg"};
}

// v in printf's format f; "–" in a label for a value that is not finite.
std::string g(double v, const char* f = "%.4g") { return printfNumberOr(f, v, "–"); }

// One order's separation band on the Campbell diagram: the wedge 0.9·k·ω … 1.1·k·ω over the
// drawn speeds up to wmax, red where the margin FAILs, green where it passes, and its margin as a
// label beside the operating speed. Takes gnuplot's object numbers from `object` on.
void separationWedge(std::ostringstream& os, const SeparationMargins& sep, const SeparationMargin& m, double wmax,
                     int& object) {
  const double k = m.order, lo = (1 - sep.required) * k * wmax, hi = (1 + sep.required) * k * wmax;
  os << "set object " << object++ << " polygon from 0,0 to " << wmax << "," << lo << " to " << wmax << "," << hi
     << " to 0,0 fc rgb '" << (m.verdict == "FAIL" ? "#d62728" : "#2ca02c")
     << "' fs transparent solid 0.15 noborder behind\n";
  os << "set label " << object++ << " 'SM_{" << m.order << "} = " << g(100 * m.margin, "%.3g") << " % " << m.verdict
     << "' at " << sep.omega << "," << m.excitation << " left offset 0.8,0 font ',9' tc rgb '"
     << (m.verdict == "FAIL" ? "#d62728" : "#1a7a1a") << "' front\n";
}

// At the operating speed, a bar over the natural frequency p_lo … p_hi [rad/s] the margins are
// taken from (ω_n of the damped pair, or its band). Takes gnuplot's object numbers from `object` on.
void naturalFrequencyBar(std::ostringstream& os, double omega, double p_lo, double p_hi, int& object) {
  const double half = p_hi > p_lo ? 0.0 : 0.01 * p_lo;  // a single ω_n: a short bar to be seen
  os << "set arrow " << object++ << " from " << omega << "," << p_lo - half << " to " << omega << "," << p_hi + half
     << " nohead lw 4 lc rgb '#000000' front\n";
  os << "set label " << object++ << " 'ω_n' at " << omega << "," << 0.5 * (p_lo + p_hi)
     << " right offset -0.6,0 font ',9' front\n";
}

// The separation margins on the Campbell diagram (gnuplot commands for its preamble): for each
// order k that drives the coupling mode its wedge, at the operating speed the bar over the natural
// frequency and each order's margin beside it. Nothing where the margins do not apply.
std::string separationShading(const SeparationMargins& sep, double wmax) {
  if (!sep.applicable || !(wmax > 0)) return "";
  std::ostringstream os;
  int object = 100;  // clear of the objects gnuplot numbers by default
  double p_lo = NAN, p_hi = NAN;
  for (const SeparationMargin& m : sep.rows) {
    if (m.mode != "coupling mode") continue;  // the diagram draws the coupling mode only
    p_lo = m.p_low;
    p_hi = m.p_high;
    if (m.verdict == "pass" || m.verdict == "FAIL") separationWedge(os, sep, m, wmax, object);
  }
  if (std::isfinite(p_lo) && std::isfinite(p_hi)) naturalFrequencyBar(os, sep.omega, p_lo, p_hi, object);
  return os.str();
}

// One model's frozen-angle frequency against the crank angle (the second model dashed).
PlotSeries frozenFrequencyLine(const ModelFrozenModes& frozen, size_t m) {
  const char* colors[] = {"#1f77b4", "#d62728"};
  PlotSeries line;
  line.title = frozen.model + " model";
  line.color = colors[m % 2];
  line.dash = m ? 2 : 0;
  line.line_width = 2;
  for (const FrozenAngle& a : frozen.angles) {
    line.x.push_back(std::fmod(a.point.phi, 2 * M_PI) * 180 / M_PI);
    line.y.push_back(a.torsional_frequency());
  }
  return line;
}

// A frequency that does not depend on the crank angle, as a level over the revolution.
PlotSeries levelOverRevolution(const std::string& title, const std::string& color, int dash, double value) {
  PlotSeries level;
  level.title = title;
  level.color = color;
  level.dash = dash;
  level.x = {0, 360};
  level.y = {value, value};
  return level;
}

// Frozen-angle frequencies over the crank angle, both models, with the two-mass first estimate
// and the Floquet frequency.
void addFrozenFrequenciesFigure(const ModesReport& r, const std::string& dir, std::vector<PlotJob>& jobs,
                                FigureSet& set) {
  PlotSpec s;
  s.title = "Frozen-angle torsional natural frequency over one crank revolution";
  s.xlabel = "crank angle φ_2 [deg]";
  s.ylabel = "p [rad/s]";
  for (size_t m = 0; m < r.frozen.size(); ++m)
    if (r.frozen[m].ok) s.series.push_back(frozenFrequencyLine(r.frozen[m], m));
  s.series.push_back(
      levelOverRevolution("first estimate: two constant inertias (Dyomin p_0)", "#7f7f7f", 3, r.two_mass.p0));
  if (r.steady.found && r.steady.verdict.has_torsional && r.steady.verdict.torsional_resolved)
    s.series.push_back(levelOverRevolution("Floquet frequency of the steady motion", "#2ca02c", 0,
                                           r.steady.verdict.torsional_frequency));
  s.preamble = "set xrange [0:360]\nset xtics 45\nset key inside bottom right";
  jobs.push_back(plotJob(s, dir + "/frozen_frequencies"));
  set.figures.push_back(fileOf(dir, "frozen_frequencies",
                               "Torsional natural frequency of the drive with the crank angle frozen, along the "
                               "steady motion: both models, the two-mass first estimate and the Floquet frequency."));
}

// The Campbell diagram's four curves, styled and still empty: the frozen-angle mean, the low and
// high ends of its band over the crank angle, the Floquet frequency.
std::vector<PlotSeries> campbellCurveStyles() {
  PlotSeries mean, lo, hi, fl;
  mean.title = "p, frozen-angle mean";
  mean.color = "#1f77b4";
  mean.line_width = 2.5;
  lo.title = "p band over the crank angle";
  lo.color = hi.color = "#1f77b4";
  lo.dash = hi.dash = 2;
  hi.title = "";
  fl.title = "Floquet frequency";
  fl.color = "#2ca02c";
  fl.style = "linespoints";
  return {mean, lo, hi, fl};
}

// The Campbell diagram's curves over the speeds where a steady motion was found: the frozen-angle
// mean and band, the Floquet frequency; `wmax`, `fmax`: the largest speed and frozen frequency.
std::vector<PlotSeries> campbellCurves(const CampbellDiagram& campbell, double& wmax, double& fmax) {
  std::vector<PlotSeries> curves = campbellCurveStyles();
  PlotSeries &mean = curves[0], &lo = curves[1], &hi = curves[2], &fl = curves[3];
  wmax = 0, fmax = 0;
  for (const CampbellPoint& p : campbell.points) {
    if (!p.found) continue;
    mean.x.push_back(p.omega_mean);
    mean.y.push_back(p.frozen.mean);
    lo.x.push_back(p.omega_mean);
    lo.y.push_back(p.frozen.min);
    hi.x.push_back(p.omega_mean);
    hi.y.push_back(p.frozen.max);
    fl.x.push_back(p.omega_mean);
    fl.y.push_back(p.floquet_frequency);
    wmax = std::max(wmax, p.omega_mean);
    fmax = std::max(fmax, p.frozen.max);
  }
  return curves;
}

// The order lines k·ω (forced resonance) and k·ω/2 (principal parametric resonance) up to wmax.
void addOrderLines(const std::vector<int>& orders, double wmax, std::vector<PlotSeries>& series) {
  for (int k : orders) {
    PlotSeries o;
    o.title = "";
    o.color = "#bbbbbb";
    o.x = {0, wmax};
    o.y = {0, k * wmax};
    series.push_back(o);
    PlotSeries h = o;
    h.dash = 3;
    h.color = "#e8a0a0";
    h.y = {0, 0.5 * k * wmax};
    series.push_back(h);
  }
}

// The Campbell diagram's ranges, order labels, operating speed and separation margins (gnuplot).
std::string campbellPreamble(const ModesReport& r, double wmax, double fmax) {
  std::ostringstream pre;
  pre << "set xrange [0:" << wmax << "]\nset yrange [0:" << 1.3 * fmax << "]\nset key inside top left\n";
  for (int k : r.campbell.orders)
    if (k * wmax * 0.9 < 1.3 * fmax)
      pre << "set label '" << k << "ω' at " << 0.9 * wmax << "," << 0.9 * k * wmax << " tc rgb '#888888'\n";
  if (r.steady.found)
    pre << "set arrow from " << r.steady.omega_mean << ",graph 0 to " << r.steady.omega_mean
        << ",graph 1 nohead dt 2 lc rgb 'black'\nset label 'operating speed' at " << r.steady.omega_mean
        << ",graph 0.97 left offset 0.5,0\n";
  pre << separationShading(r.separation, wmax);
  return pre.str();
}

void addCampbellFigure(const ModesReport& r, const std::string& dir, std::vector<PlotJob>& jobs, FigureSet& set) {
  PlotSpec s;
  s.title = "Campbell diagram: torsional frequency against the orders of the crank speed";
  s.xlabel = "mean crank speed ω [rad/s]";
  s.ylabel = "frequency [rad/s]";
  double wmax = 0, fmax = 0;
  s.series = campbellCurves(r.campbell, wmax, fmax);
  addOrderLines(r.campbell.orders, wmax, s.series);
  s.preamble = campbellPreamble(r, wmax, fmax);
  jobs.push_back(plotJob(s, dir + "/campbell"));
  set.figures.push_back(fileOf(dir, "campbell",
                               "Campbell diagram: solid grey lines k·ω (forced resonance where the torsional "
                               "frequency meets them), dotted red lines k·ω/2 (principal parametric resonance, "
                               "2p = k·ω), for the orders k that excite this layout; crank speed varied as by a "
                               "frequency converter. Shaded: the band within 10 % of k·ω for each order k that "
                               "drives the coupling mode (the separation margin of API 617 / API 684 practice), "
                               "red where the mode's natural frequency at the operating speed (the vertical bar, "
                               "ω_n of the damped pair) lies inside it (FAIL), green where it stays outside (pass)."));
}

// The stiffness axis' tics at the whole powers of ten over `x` (log10 of the stiffnesses).
std::string powerOfTenTics(const std::vector<double>& x) {
  std::ostringstream pre;
  pre << "set xtics (";
  bool first = true;
  for (int e = int(std::floor(x.front())); e <= int(std::ceil(x.back())); ++e) {
    pre << (first ? "" : ", ") << "'10^{" << e << "}' " << e;
    first = false;
  }
  pre << ")\n";
  return pre.str();
}

// The scene's point on the chart (a white dot, labelled), the marked dampings (e.g. a paper's: a
// dashed line across the chart each) and the unstable zones' boxes.
std::string stabilityChartMarks(const StabilityChart& c) {
  std::ostringstream pre;
  if (std::isfinite(c.operating_c) && std::isfinite(c.operating_y))
    pre << "set label 1 '' at " << std::log10(c.operating_c) << "," << c.operating_y
        << " point pt 7 ps 2.5 lc rgb 'white' front\nset label 2 'scene' at " << std::log10(c.operating_c) << ","
        << c.operating_y << " offset 1.2,0.8 tc rgb 'white' front\n";
  int label = 10;
  for (double m : c.marked)
    pre << "set arrow from graph 0, first " << m << " to graph 1, first " << m
        << " nohead dt 2 lw 2 lc rgb 'white' front\nset label " << label++ << " '" << c.y_key_label() << " = " << g(m)
        << "' at graph 0.02, first " << m << " offset 0,0.6 tc rgb 'white' front\n";
  for (const StabilityZone& zz : c.zones)
    pre << "set object rect from " << std::log10(zz.c_min) << "," << zz.y_min << " to " << std::log10(zz.c_max)
        << "," << zz.y_max << " fs empty border lc rgb 'white' lw 2 front\n";
  return pre.str();
}

// A stability chart's axes, the scene's point, marked dampings and unstable zones (gnuplot);
// `x`: log10 of the chart's stiffnesses.
std::string stabilityChartPreamble(const StabilityChart& c, const std::vector<double>& x) {
  std::ostringstream pre;
  pre << powerOfTenTics(x) << "set cbrange [*:1]\n";
  if (x.size() > 1 && c.y.size() > 1) {  // the grid's cells, no padding around them
    const double dx = (x.back() - x.front()) / (x.size() - 1), dy = (c.y.back() - c.y.front()) / (c.y.size() - 1);
    pre << "set xrange [" << x.front() - dx / 2 << ":" << x.back() + dx / 2 << "]\nset yrange ["
        << c.y.front() - dy / 2 << ":" << c.y.back() + dy / 2 << "]\n";
  }
  pre << stabilityChartMarks(c);
  return pre.str();
}

// The n-th stability chart (from 0) as a heat map of log10 of the largest Floquet multiplier.
void addStabilityChartFigure(const StabilityChart& c, size_t n, const std::string& dir, std::vector<PlotJob>& jobs,
                             FigureSet& set) {
  std::vector<double> x;
  for (double v : c.c) x.push_back(std::log10(v));
  std::vector<std::vector<double>> z;
  for (const auto& row : c.grid) {
    std::vector<double> zr;
    for (const StabilityPoint& p : row) zr.push_back(p.found ? std::log10(std::max(p.max_modulus, 1e-12)) : NAN);
    z.push_back(zr);
  }
  const std::string title =
      c.y_key == "omega" ? "Stability of the steady motion: largest Floquet multiplier, k = " + g(c.fixed_damping) +
                               " N·m·s/rad"
                         : "Stability of the steady motion: largest Floquet multiplier, ω = " + g(c.fixed_speed) +
                               " rad/s";
  const std::string name = "stability_" + std::to_string(n + 1);
  jobs.push_back(heatMapJob(title, "coupling stiffness c [N·m/rad] (log scale)",
                            c.y_key == "omega" ? "mean crank speed ω [rad/s]" : "coupling damping k [N·m·s/rad]",
                            "log_{10} max|μ| per revolution (> 0: unstable)", x, c.y, z, dir + "/" + name, true,
                            true, stabilityChartPreamble(c, x)));
  set.figures.push_back(fileOf(dir, name,
                               "Stability chart from the Floquet multipliers of the steady motion (reduced model): "
                               "colour = log10 of the largest multiplier modulus per crank revolution (0 and above: "
                               "unstable; white boxes: unstable zones); white dot: the scene."));
}

}  // namespace

FigureSet drawModesFigures(const ModesReport& r, const std::string& dir) {
  FigureSet set;
  std::vector<PlotJob> jobs;
  if (!gnuplotAvailable()) {
    set.notes.push_back("gnuplot not found (Debian package gnuplot-nox): no figures of the torsional modes");
    return set;
  }
  if (r.elastic && !r.frozen.empty()) addFrozenFrequenciesFigure(r, dir, jobs, set);
  int campbell_found = 0;
  for (const CampbellPoint& p : r.campbell.points) campbell_found += p.found;
  if (r.campbell.applicable && campbell_found >= 2) addCampbellFigure(r, dir, jobs, set);
  for (size_t n = 0; n < r.charts.size(); ++n) addStabilityChartFigure(r.charts[n], n, dir, jobs, set);
  renderPlots(jobs);  // a few gnuplot processes at once, each drawing several figures
  return set;
}

namespace {

// One spectrum figure: the signals whose names start with either prefix.
struct SpectrumGroup {
  std::string name, title, prefix1, prefix2;
};

// The group's spectrum figure (no series when the spectrum has none of its signals).
PlotSpec spectrumFigure(const OrderSpectrum& s, const SpectrumGroup& gr) {
  PlotSpec p;
  p.title = "Order spectrum over the steady window (" + std::to_string(s.revolutions) + " revolutions): " + gr.title;
  p.xlabel = "order of the crank speed k [-]";
  p.ylabel = "amplitude [N·m or N] (log scale)";
  p.logy = true;
  for (size_t i = 0; i < s.signals.size(); ++i) {
    const std::string& c = s.signals[i];
    if (c.rfind(gr.prefix1, 0) != 0 && c.rfind(gr.prefix2, 0) != 0) continue;
    PlotSeries line;
    line.title = escapeUnderscores(c);
    line.style = "linespoints";
    for (size_t b = 1; b < s.orders.size(); ++b) {
      line.x.push_back(s.orders[b]);
      line.y.push_back(std::max(s.amplitude[i][b], 1e-9));
    }
    p.series.push_back(line);
  }
  p.preamble = "set xtics 1\nset grid xtics";
  return p;
}

}  // namespace

FigureSet drawSpectrumFigures(const OrderSpectrum& s, const std::string& dir) {
  FigureSet set;
  std::vector<PlotJob> jobs;
  if (!s.ok || !gnuplotAvailable()) return set;
  // One figure per group: coupling torque (and motor torque), guide reactions, rod and pin forces.
  const SpectrumGroup groups[] = {{"spectrum_torque", "coupling torque", "coupling_torque", "motor_torque"},
                                  {"spectrum_guides", "guide reactions", "N_front_", "N_rear_"},
                                  {"spectrum_rods", "rod forces and bearing", "F_rod_", "bearing_"}};
  for (const SpectrumGroup& gr : groups) {
    const PlotSpec p = spectrumFigure(s, gr);
    if (p.series.empty()) continue;
    jobs.push_back(plotJob(p, dir + "/" + gr.name));
    set.figures.push_back(fileOf(dir, gr.name,
                                 "Order spectrum of the " + gr.title +
                                     ": one-sided amplitude of each harmonic of the crank revolution over the steady "
                                     "window; a peak between whole orders is a vibration not locked to the crank "
                                     "(e.g. half an order: parametric resonance)."));
  }
  renderPlots(jobs);  // a few gnuplot processes at once, each drawing several figures
  return set;
}

}  // namespace rollerdyn::modes
