#include "modes/ModesHtml.h"

#include <cmath>
#include <sstream>

#include "io/FieldFormat.h"
#include "modes/RunModes.h"
#include "report/HtmlReport.h"

namespace rollerdyn::modes {
namespace {

// v in printf's format f; "–" in a table cell for a value that is not finite.
std::string g(double v, const char* f = "%.4g") { return printfNumberOr(f, v, "–"); }

// A natural frequency [rad/s] as the table shows it: one value, or the band low … high.
std::string frequencyBand(double lo, double hi) {
  return lo == hi ? g(lo, "%.5g") : g(lo, "%.5g") + " … " + g(hi, "%.5g");
}

// One order's row of the separation margins' table.
std::string separationRowHtml(const SeparationMargin& m) {
  std::ostringstream h;
  h << "<tr><td>" << htmlEscape(m.mode) << "</td><td class=\"n\">" << m.order << "</td><td class=\"n\">"
    << g(m.excitation, "%.5g")
    << "</td><td class=\"n\">" << g(m.exciting_torque, "%.4g") << "</td><td class=\"n\">"
    << frequencyBand(m.p_low, m.p_high) << " (" << htmlEscape(m.frequency_source) << ")</td><td class=\"n\">"
    << frequencyBand(m.undamped_low, m.undamped_high) << "</td><td class=\"n\">" << g(100 * m.margin, "%.3g")
    << "</td><td class=\"n\">" << g(m.amplification, "%.3g") << "</td><td>" << htmlEscape(m.verdict)
    << "</td><td>" << htmlEscape(m.reason) << "</td></tr>\n";
  return h.str();
}

// The orders a start passes through below the operating speed, one sentence; none when none.
std::string startCrossingsHtml(const SeparationMargins& sep) {
  if (sep.start_crossings.empty()) return "";
  std::ostringstream h;
  h << "<p class=\"small\">Passed through in a start (below the operating speed, judged by the start's torques): ";
  for (size_t i = 0; i < sep.start_crossings.size(); ++i)
    h << (i ? ", " : "") << "order " << sep.start_crossings[i].order << " at ω = "
      << g(sep.start_crossings[i].omega, "%.4g") << " rad/s";
  h << ".</p>\n";
  return h.str();
}

// The separation margins' table of the report (the same rows as modes.json and the console).
std::string separationHtml(const SeparationMargins& sep) {
  std::ostringstream h;
  h << "<h3>Separation margins of the torsional modes (API 617 / API 684 practice)</h3>\n";
  if (!sep.applicable) {
    h << "<p>n/a: " << htmlEscape(sep.not_applicable) << "</p>\n";
    return h.str();
  }
  h << "<p class=\"small\">SM = |p − k·ω|/(k·ω) at the operating crank speed ω = " << g(sep.omega, "%.5g")
    << " rad/s, required ≥ " << g(100 * sep.required, "%.3g")
    << " %; p the natural frequency ω_n of the coupling mode's damped pair (√λ, the Campbell diagram's undamped "
       "frequency, beside it); AF = 1/(2ζ) the amplification factor.</p>\n"
    << "<table>\n<tr><th>mode</th><th>order k</th><th>k·ω [rad/s]</th><th>exciting torque [N·m]</th><th>ω_n [rad/s]</th>"
       "<th>√λ [rad/s]</th><th>SM [%]</th><th>AF</th><th>verdict</th><th>why</th></tr>\n";
  for (const SeparationMargin& m : sep.rows) h << separationRowHtml(m);
  h << "</table>\n" << startCrossingsHtml(sep);
  return h.str();
}

// The rows of a table of quantities and their values, the text escaped.
struct KeyRows {
  std::ostringstream h;
  void row(const std::string& k, const std::string& v) {
    h << "<tr><td>" << htmlEscape(k) << "</td><td class=\"n\">" << htmlEscape(v) << "</td></tr>\n";
  }
};

// The coupling, the first estimate and the frozen-angle modes of both models with the mode's shape.
void frozenModeRows(KeyRows& t, const ModesReport& r) {
  t.row("coupling", r.elastic ? "elastic" : "rigid");
  if (r.two_mass.applicable) t.row("first estimate p0, two constant inertias [rad/s]", g(r.two_mass.p0, "%.5g"));
  for (const ModelFrozenModes& m : r.frozen)
    if (m.ok && r.elastic)
      t.row("frozen-angle p, " + m.model + " model: mean (min … max) [rad/s]",
            g(m.torsional.mean, "%.6g") + " (" + g(m.torsional.min, "%.6g") + " … " + g(m.torsional.max, "%.6g") + ")");
  if (std::isfinite(r.model_difference)) t.row("multibody against reduced, largest relative difference of p", g(r.model_difference, "%.2e"));
  if (r.elastic && !r.frozen.empty() && r.frozen[0].ok) {
    const ModelFrozenModes& m = r.frozen[0];
    t.row("mode shape", m.torsional_name + ": kinetic energy motor side " + g(100 * m.energy_motor_side, "%.0f") +
                            " %, crankshaft and rods " + g(100 * m.energy_shaft_rods, "%.0f") + " %, carts " +
                            g(100 * m.energy_carts, "%.0f") + " %");
  }
}

// The steady motion and its Floquet verdicts (n/a where the run's stability does not apply).
void floquetRows(KeyRows& t, const ModesReport& r, const std::string& run_na) {
  if (!run_na.empty()) {
    t.row("stability of the steady motion (Floquet)", "n/a: " + run_na);
  } else if (r.steady.found) {
    const FloquetVerdict& v = r.steady.verdict;
    t.row("mean crank speed of the steady motion [rad/s]", g(r.steady.omega_mean, "%.6g"));
    t.row("Floquet verdict (reduced model)", v.text + ", largest |μ| = " + g(v.max_modulus) + " per revolution, margin " +
                                                g(v.margin));
    if (v.has_torsional && !v.torsional_resolved)
      t.row("torsional mode from the multipliers", "decays more than a million-fold per revolution (not resolved)");
    else if (v.has_torsional)
      t.row("torsional mode from the multipliers", g(v.torsional_frequency, "%.5g") + " rad/s, damping ratio " +
                                                      g(v.torsional_damping_ratio, "%.3g"));
  } else {
    t.row("steady motion", "not found: " + r.steady.failure);
  }
  if (run_na.empty() && r.has_multibody_steady && r.steady_multibody.found)
    t.row("Floquet verdict (multibody model)", r.steady_multibody.verdict.text + ", largest |μ| = " +
                                                   g(r.steady_multibody.verdict.max_modulus));
}

// The layout's excitation orders (the first 12) and each stability chart's unstable points.
void orderAndChartRows(KeyRows& t, const ModesReport& r) {
  std::string orders;
  for (size_t i = 0; i < r.orders.layout.size() && i < 12; ++i) orders += (i ? ", " : "") + std::to_string(r.orders.layout[i]);
  t.row("excitation orders of the layout", orders);
  for (const StabilityChart& c : r.charts)
    t.row(c.y_key == "omega" ? "stability chart c × ω at k = " + g(c.fixed_damping) + " N·m·s/rad"
                             : "stability chart c × k at ω = " + g(c.fixed_speed) + " rad/s",
          std::to_string(c.unstable_points) + " unstable points, " + std::to_string(c.zones.size()) + " zone(s)");
}

// The section's key figures, one row each: the modes of both models, the Floquet verdicts, the
// excitation orders and the stability charts.
std::string modesKeyTable(const ModesReport& r, const std::string& run_na) {
  KeyRows t;
  t.h << "<table>\n<tr><th>quantity</th><th>value</th></tr>\n";
  frozenModeRows(t, r);
  floquetRows(t, r, run_na);
  orderAndChartRows(t, r);
  t.h << "</table>\n";
  return t.h.str();
}

std::string campbellCrossingsHtml(const ModesReport& r) {
  std::ostringstream h;
  if (!r.campbell.crossings.empty()) {
    h << "<h3>Campbell crossings</h3>\n<table>\n<tr><th>order k</th><th>kind</th><th>crank speed [rad/s]</th>"
         "<th>frequency [rad/s]</th><th>band crossed between [rad/s]</th></tr>\n";
    for (const CampbellCrossing& c : r.campbell.crossings)
      h << "<tr><td class=\"n\">" << c.order << "</td><td>" << (c.parametric ? "parametric, 2p = kω" : "forced, p = kω")
        << "</td><td class=\"n\">" << g(c.omega) << "</td><td class=\"n\">" << g(c.frequency) << "</td><td class=\"n\">"
        << g(c.omega_band_low) << " … " << g(c.omega_band_high) << "</td></tr>\n";
    h << "</table>\n";
  }
  return h.str();
}

// The run's strongest orders per signal and how much of each signal is locked to the crank.
std::string orderSpectrumHtml(const OrderSpectrum* spectrum) {
  std::ostringstream h;
  if (spectrum && spectrum->ok) {
    h << "<h3>Order spectrum of the run (steady window, " << spectrum->revolutions << " revolutions)</h3>\n"
      << "<table>\n<tr><th>signal</th><th>strongest orders (amplitude)</th><th>share at whole orders</th></tr>\n";
    for (size_t i = 0; i < spectrum->signals.size(); ++i) {
      std::string peaks;
      for (size_t k = 0; k < spectrum->peaks[i].size() && k < 4; ++k)
        peaks += (k ? ", " : "") + g(spectrum->peaks[i][k].order, "%.3g") + " (" +
                 g(spectrum->peaks[i][k].amplitude, "%.3g") + ")";
      h << "<tr><td><code>" << htmlEscape(spectrum->signals[i]) << "</code></td><td>" << htmlEscape(peaks)
        << "</td><td class=\"n\">" << g(100 * spectrum->whole_order_share[i], "%.4g") << " %</td></tr>\n";
    }
    h << "</table>\n";
  }
  return h.str();
}

// The figures, embedded in the page (PNG as data).
std::string figuresHtml(const FigureSet& figures) {
  std::ostringstream h;
  for (const FigureFile& f : figures.figures) {
    h << "<figure id=\"" << htmlEscape(f.name) << "\">";
    h << embeddedPngHtml(f);
    h << "<figcaption>" << htmlEscape(f.caption) << "</figcaption></figure>\n";
  }
  return h.str();
}

}  // namespace

std::string modesHtmlSection(const ModesReport& r, const FigureSet& figures, const OrderSpectrum* spectrum,
                             const nlohmann::json& run_summary) {
  const std::string run_na = runStabilityNotApplicable(run_summary);
  std::ostringstream h;
  h << "<h2 id=\"modes\">Torsional modes and stability</h2>\n";
  h << "<p class=\"small\">The drive linearized about its steady motion: frozen-angle modes (the crank angle held, "
       "both models), Floquet multipliers of the steady motion over one revolution (exact for the linearized "
       "periodic motion), Campbell diagram and stability charts. The two-mass value is the first, cheap estimate "
       "(two constant inertias, Dyomin (two rotors) eq. (10)).</p>\n";
  h << modesKeyTable(r, run_na);
  h << campbellCrossingsHtml(r);
  h << separationHtml(r.separation);
  h << orderSpectrumHtml(spectrum);
  // The run's resonance warnings (its verdict, at its steady mean crank speed), as summary.json has them.
  const nlohmann::json& modal = run_summary.contains("resonance_modal") ? run_summary["resonance_modal"] : nlohmann::json();
  if (modal.is_object() && modal.contains("warnings") && modal["warnings"].is_array())
    for (const nlohmann::json& w : modal["warnings"])
      if (w.is_string()) h << "<p><b>Warning:</b> " << htmlEscape(w.get<std::string>()) << "</p>\n";
  for (const std::string& n : r.notes) h << "<p class=\"small\">Note: " << htmlEscape(n) << "</p>\n";
  for (const auto& [name, meaning] : r.approximations)
    h << "<p class=\"small\">Approximation, " << htmlEscape(name) << ": " << htmlEscape(meaning) << "</p>\n";
  h << figuresHtml(figures);
  return h.str();
}


}  // namespace rollerdyn::modes
