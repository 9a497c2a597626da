// Internals of the validation report shared by its source files (ValidationReport.cpp:
// header, sections (1) and (2), results.json; PaperReport.cpp: sections (3) and (4)). Everything
// here formats numbers computed by the suite; nothing is computed from constants. Not a public
// header.
#pragma once

#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "compare/ValidationSuite.h"
#include "io/FieldFormat.h"

namespace rollerdyn::validation::report_detail {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

inline std::string g(double v, int prec = 3) { return significantOr(v, prec, "–"); }
inline std::string fx(double v, int decimals) {
  if (!std::isfinite(v)) return "–";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}
inline std::string pct(double ours, double published) {
  if (!std::isfinite(ours) || !std::isfinite(published) || published == 0) return "–";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%+.0f %%", 100.0 * (ours - published) / std::abs(published));
  return buf;
}
inline double pub(const SweepPoint& p, const std::string& col) {
  const auto it = p.published.find(col);
  return (p.has_published && it != p.published.end()) ? it->second : kNaN;
}
// A metric of a run, NaN when the crank does not rotate steadily (the metric would describe a
// rocking or stalled crank, not the papers' steady rotation).
inline double ok(const RunMetrics& m, double RunMetrics::*f) { return m.rotating ? m.*f : kNaN; }

inline PlotSeries series(const std::string& title, std::vector<double> x, std::vector<double> y,
                  const std::string& style = "lines") {
  PlotSeries s;
  s.title = title;
  s.x = std::move(x);
  s.y = std::move(y);
  s.style = style;
  return s;
}

inline PlotSpec plot(const std::string& title, const std::string& xlabel, const std::string& ylabel, bool logy = false) {
  PlotSpec s;
  s.title = title;
  s.xlabel = xlabel;
  s.ylabel = ylabel;
  s.logy = logy;
  return s;
}

// A coefficient along a sweep as plotted: published, reduced and variant at every point (NaN
// where the crank does not rotate: gnuplot skips it), multibody where it ran.
struct CoefficientCurves {
  std::vector<double> x, published, reduced, variant, x_multibody, multibody;
};

class ReportWriter {
 public:
  ReportWriter(const ValidationResults& r, const std::string& figdir) : r_(r), figdir_(figdir) {}
  ValidationReport build();

 private:
  // Every verdict the report prints goes through here, so report.md, results.json, the summary
  // and the exit status count the same claims. Returns verdictText(v); a Measurement is not
  // recorded.
  std::string verdict(const std::string& id, Verdict v, const std::string& text) {
    if (v != Verdict::Measurement) out_.claims.push_back({id, section_, text, v});
    return verdictText(v);
  }
  void section(const std::string& title) { section_ = title; }
  void figure(const std::string& name, PlotSpec spec, const std::string& caption) {
    if (spec.preamble.empty()) spec.preamble = "set key below";
    out_.figures.push_back({name, std::move(spec)});
    md_ << "\n![" << caption << "](" << figdir_ << "/" << name << ".png)\n\n*" << caption << "*\n";
  }
  void header();
  void equivalence();
  void convergence();
  void convergenceClaim(const std::string& label, const std::vector<const ComparisonCase*>& cs);
  void perCart();
  void differences();
  // Published, reduced, [Baranov 1 deg,] multibody against the swept value (seeds 004 and 003).
  void coefficientFigure(const std::string& name, PlotSpec spec, const std::string& published_title,
                         const CoefficientCurves& c, bool variant, const std::string& caption);
  void papers();
  void paperFindings(const PaperSweep& p);
  void loveikin2007(const PaperSweep& p);
  void energyBalanced(const PaperSweep& p);
  void loveikin2018(const PaperSweep& p);
  void sensitivity();
  void analytic();
  void analyticCheck(int n, const std::string& what, double closed, double simulated, int prec);
  void analyticFrequencies(double p0);
  void analyticHarmonicsClaim(double worst);
  void motor();
  void items();
  nlohmann::json resultsJson() const;
  int firstItemNumber() const;  // (5) when there is no motor section, else (6)

  const ValidationResults& r_;
  std::string figdir_;
  std::ostringstream md_;
  ValidationReport out_;
  std::string section_;  // title of the section being written (Claim::section)
};

}  // namespace rollerdyn::validation::report_detail
