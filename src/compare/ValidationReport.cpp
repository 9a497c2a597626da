// report.md, figure specifications, results.json and result tables of the validation suite
// (ValidationSuite.h). Everything here is formatting of numbers computed in ValidationSuite.cpp.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <sstream>

#include "compare/ValidationSuite.h"

namespace rollerdyn::validation {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string g(double v, int prec = 3) {
  if (!std::isfinite(v)) return "–";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", prec, v);
  return buf;
}
std::string fx(double v, int decimals) {
  if (!std::isfinite(v)) return "–";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}
std::string pct(double ours, double published) {
  if (!std::isfinite(ours) || !std::isfinite(published) || published == 0) return "–";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%+.0f %%", 100.0 * (ours - published) / std::abs(published));
  return buf;
}
nlohmann::json num(double v) {
  if (std::isfinite(v)) return v;
  return nullptr;
}
double pub(const SweepPoint& p, const std::string& col) {
  const auto it = p.published.find(col);
  return (p.has_published && it != p.published.end()) ? it->second : kNaN;
}
// A metric of a run, NaN when the crank does not rotate steadily (the metric would describe a
// rocking or stalled crank, not the papers' steady rotation).
double ok(const RunMetrics& m, double RunMetrics::*f) { return m.rotating ? m.*f : kNaN; }

PlotSeries series(const std::string& title, std::vector<double> x, std::vector<double> y,
                  const std::string& style = "lines") {
  PlotSeries s;
  s.title = title;
  s.x = std::move(x);
  s.y = std::move(y);
  s.style = style;
  return s;
}

nlohmann::json metricsJson(const RunMetrics& m) {
  return {{"complete", m.complete},         {"status", m.status},
          {"steady", m.steady},             {"rotating", m.rotating},
          {"omega_min", num(m.omega_min)},  {"omega_max", num(m.omega_max)},
          {"omega_mean", num(m.omega_mean)}, {"delta", num(m.delta)},
          {"eps_abs_max", num(m.eps_abs_max)}, {"H", num(m.H)},
          {"k_p", num(m.k_p)},              {"coupling_torque_swing", num(m.torque_swing)},
          {"twist_swing", num(m.twist_swing)}, {"twist_rate_swing", num(m.twist_rate_swing)},
          {"twist_accel_swing", num(m.twist_accel_swing)}, {"cpu_seconds", num(m.cpu_seconds)}};
}

nlohmann::json caseJson(const ComparisonCase& c) {
  nlohmann::json m = nlohmann::json::object();
  for (const auto& [k, v] : c.measured) m[k] = v;
  return {{"label", c.label},
          {"description", c.description},
          {"command", c.command},
          {"revolutions", c.revolutions},
          {"t_end", num(c.t_end)},
          {"accuracy", num(c.accuracy)},
          {"max_rel_diff_omega_crank", num(c.max_rel_omega)},
          {"max_rel_diff_coupling_torque", num(c.max_rel_torque)},
          {"max_rel_diff_reactions_quasistatic", num(c.max_rel_reactions_quasistatic)},
          {"max_rel_diff_reactions_kinetostatic", num(c.max_rel_reactions_kinetostatic)},
          {"cpu_seconds_multibody", num(c.cpu_multibody)},
          {"cpu_seconds_reduced", num(c.cpu_reduced)},
          {"complete", c.complete},
          {"motion_equivalent", c.motion_equivalent},
          {"differences", c.topics},
          {"measured", m},
          {"explanation", c.explanation},
          {"pass", c.pass}};
}

// |a - b| / max|a| of two comparison.csv columns, against t.
PlotSeries relativeDifference(const Table& t, const std::string& q, const std::string& title) {
  const auto tt = t.column("t"), a = t.column(q + "_multibody"), b = t.column(q + "_reduced");
  double amax = 0;
  for (double v : a) amax = std::max(amax, std::abs(v));
  std::vector<double> y;
  for (std::size_t i = 0; i < a.size(); ++i) y.push_back(amax > 0 ? std::abs(a[i] - b[i]) / amax : kNaN);
  return series(title, tt, y);
}

// One column of a paper's sweep table in report.md: its header and its cell at one point.
struct SweepColumn {
  std::string header;
  std::function<std::string(const SweepPoint&)> cell;
};

// A markdown table with one row per sweep point.
void sweepTable(std::ostream& md, const std::vector<SweepColumn>& cols, const std::vector<SweepPoint>& pts) {
  for (const auto& c : cols) md << "| " << c.header << " ";
  md << "|\n";
  for (std::size_t i = 0; i < cols.size(); ++i) md << "|---";
  md << "|\n";
  for (const auto& s : pts) {
    for (const auto& c : cols) md << "| " << c.cell(s) << " ";
    md << "|\n";
  }
}

// A crank speed, published and ours in one cell ("9.67 / 9.71").
SweepColumn speedColumn(const std::string& name, const std::string& col, double RunMetrics::*f, int decimals) {
  return {name + " pub / ours",
          [=](const SweepPoint& s) { return fx(pub(s, col), decimals) + " / " + fx(ok(s.reduced, f), decimals); }};
}

void addPublishedAndOurs(std::vector<SweepColumn>& cols, const std::string& name, const std::string& col,
                         double RunMetrics::*f) {
  cols.push_back({name + " pub", [=](const SweepPoint& s) { return g(pub(s, col)); }});
  cols.push_back({name + " ours", [=](const SweepPoint& s) { return g(ok(s.reduced, f)); }});
}

// A coefficient (δ, H) as the Loveikin and Pochka (2007) and 003 tables show it: published, ours, gap, the Baranov
// variant (where `variant`), multibody (blank where it did not run).
void addCoefficient(std::vector<SweepColumn>& cols, const std::string& name, const std::string& col,
                    double RunMetrics::*f, bool variant) {
  addPublishedAndOurs(cols, name, col, f);
  cols.push_back({"gap", [=](const SweepPoint& s) { return pct(ok(s.reduced, f), pub(s, col)); }});
  if (variant) cols.push_back({name + " Baranov", [=](const SweepPoint& s) { return g(ok(s.variant, f)); }});
  cols.push_back({name + " mb", [=](const SweepPoint& s) { return s.has_multibody ? g(ok(s.multibody, f)) : ""; }});
}

// Our numbers of a Loveikin and Pochka (2007) / 003 sweep for results/*.csv (unmasked: the CSV keeps what the
// table leaves out where the crank does not rotate); H_baranov where the table shows it.
Table coefficientCsv(const std::vector<SweepPoint>& pts, const std::string& x_column, bool H_variant) {
  Table t;
  t.columns = {x_column, "omega_min", "omega_max", "omega_mean", "delta", "eps_abs_max", "H", "k_p", "delta_baranov"};
  if (H_variant) t.columns.push_back("H_baranov");
  for (const char* c : {"delta_multibody", "H_multibody", "delta_published", "H_published", "k_p_published"})
    t.columns.push_back(c);
  for (const auto& s : pts) {
    const RunMetrics& m = s.reduced;
    std::vector<double> row = {s.x, m.omega_min, m.omega_max, m.omega_mean, m.delta, m.eps_abs_max, m.H, m.k_p,
                               s.variant.delta};
    if (H_variant) row.push_back(s.variant.H);
    for (double v : {s.has_multibody ? s.multibody.delta : kNaN, s.has_multibody ? s.multibody.H : kNaN,
                     pub(s, "delta"), pub(s, "H"), pub(s, "k_p")})
      row.push_back(v);
    t.rows.push_back(row);
  }
  return t;
}

// A coefficient along a sweep as plotted: published, reduced and variant at every point (NaN
// where the crank does not rotate: gnuplot skips it), multibody where it ran.
struct CoefficientCurves {
  std::vector<double> x, published, reduced, variant, x_multibody, multibody;
};
CoefficientCurves coefficientCurves(const std::vector<SweepPoint>& pts, const std::string& col, double RunMetrics::*f) {
  CoefficientCurves c;
  for (const auto& s : pts) {
    c.x.push_back(s.x);
    c.published.push_back(pub(s, col));
    c.reduced.push_back(ok(s.reduced, f));
    c.variant.push_back(ok(s.variant, f));
    if (s.has_multibody) {
      c.x_multibody.push_back(s.x);
      c.multibody.push_back(ok(s.multibody, f));
    }
  }
  return c;
}

PlotSpec plot(const std::string& title, const std::string& xlabel, const std::string& ylabel, bool logy = false) {
  PlotSpec s;
  s.title = title;
  s.xlabel = xlabel;
  s.ylabel = ylabel;
  s.logy = logy;
  return s;
}

class ReportWriter {
 public:
  ReportWriter(const ValidationResults& r, const std::string& figdir) : r_(r), figdir_(figdir) {}
  ValidationReport build();

 private:
  void figure(const std::string& name, PlotSpec spec, const std::string& caption) {
    if (spec.preamble.empty()) spec.preamble = "set key below";
    out_.figures.push_back({name, std::move(spec)});
    md_ << "\n![" << caption << "](" << figdir_ << "/" << name << ".png)\n\n*" << caption << "*\n";
  }
  void header();
  void equivalence();
  void differences();
  // Published, reduced, [Baranov 1 deg,] multibody against the swept value (seeds 004 and 003).
  void coefficientFigure(const std::string& name, PlotSpec spec, const std::string& published_title,
                         const CoefficientCurves& c, bool variant, const std::string& caption) {
    spec.series = {series(published_title, c.x, c.published, "linespoints"), series("reduced model", c.x, c.reduced)};
    if (variant) spec.series.push_back(series("reduced, Baranov 1 deg", c.x, c.variant));
    spec.series.push_back(series("multibody", c.x_multibody, c.multibody, "points pt 7 ps 1.5"));
    figure(name, std::move(spec), caption);
  }
  void seed004(const PaperSweep& p);
  void seed003(const PaperSweep& p);
  void seed000(const PaperSweep& p);
  void sensitivity();
  void analytic();

  const ValidationResults& r_;
  std::string figdir_;
  std::ostringstream md_;
  ValidationReport out_;
};

void ReportWriter::header() {
  md_ << "# rollerdyn validation report\n\n"
      << "Written by `./build/rollerdyn validate" << (r_.quick ? " --quick" : "")
      << "` (src/compare/ValidationSuite.cpp); every number below comes from that run"
      << (r_.quick ? " in **quick mode** (coarser sweeps, 5 instead of 20 revolutions)" : "")
      << ". CPU time of the whole suite: " << g(r_.cpu_seconds, 3) << " s.\n\n"
      << "Reference for all relative differences: the multibody model (Simbody), "
      << "`max_rel_diff = max|multibody - reduced| / max|multibody|` over the compared run "
      << "(src/compare/ModelComparison.h). Each case lists the `rollerdyn compare` command that "
      << "reproduces it. Machine-readable results: `results.json`; our sweep numbers: `results/*.csv`.\n\n"
      << "Contents: (1) equivalence of the two models where their physics is identical; "
      << "(2) where the physics differ; (3) the papers' tables; (4) the analytic two-rotor check "
      << "of Dyomin (two rotors).\n";
}

void ReportWriter::equivalence() {
  md_ << "\n## (1) Equivalence: identical physics in both models\n\n"
      << "Scenes made identical in physics (ModelDifferences.h): split rods (Loveikin, Pochka, Romasevych (2018) eq. (2)-(3)), "
      << "no guide friction, exact kinematics, CVODE in the reduced model. Each run covers " << (r_.quick ? "5" : "20")
      << " crank revolutions from the scene's start (t_end from the crank angle of a reduced-model probe run). "
      << "Target: max_rel_diff <= " << g(kEquivalenceTarget) << " for crank speed and coupling torque "
      << "(ValidationSuite.h). E0 is the issue's command at accuracy 1e-9; E1-E7 run at 1e-11 (see the convergence "
      << "study below for why). The reactions column compares the multibody reactions with the reduced model's "
      << "*kinetostatic* reactions (cart statics with the carts' d'Alembert forces).\n\n"
      << "| case | scene | accuracy | revolutions | t_end [s] | max_rel ω_crank | max_rel coupling torque | max_rel reactions (kinetostatic) | CPU multibody [s] | CPU reduced [s] | result |\n"
      << "|---|---|---|---|---|---|---|---|---|---|---|\n";
  Table t;
  t.columns = {"case", "accuracy", "revolutions", "t_end", "max_rel_omega", "max_rel_torque", "max_rel_reactions_kinetostatic",
               "cpu_multibody", "cpu_reduced", "pass"};
  for (const auto& c : r_.equivalence) {
    md_ << "| " << c.label << " | " << c.description << " | " << g(c.accuracy) << " | " << g(c.revolutions) << " | "
        << g(c.t_end, 5) << " | " << g(c.max_rel_omega, 2) << " | " << g(c.max_rel_torque, 2) << " | "
        << g(c.max_rel_reactions_kinetostatic, 2) << " | " << g(c.cpu_multibody, 3) << " | " << g(c.cpu_reduced, 2)
        << " | " << (c.pass ? "pass" : ("**FAIL** " + c.explanation)) << " |\n";
    t.rows.push_back({std::stod(c.label.substr(1)), c.accuracy, c.revolutions, c.t_end, c.max_rel_omega, c.max_rel_torque,
                      c.max_rel_reactions_kinetostatic, c.cpu_multibody, c.cpu_reduced, c.pass ? 1.0 : 0.0});
  }
  if (!r_.convergence.empty()) {
    md_ << "\n**Convergence.** The same comparisons at other accuracies (both models). A modelling difference "
        << "would stay as the accuracy tightens; these fall about tenfold per decade, so what is left is "
        << "integration error.";
    bool above = false;
    for (const auto& c : r_.convergence) above = above || (c.accuracy >= 1e-9 && !c.pass);
    if (above)
      md_ << " At 1e-9 some of these exceed 1e-6 in the coupling torque: with loads opposing the cart velocity "
          << "(seeds 003/004) the load law tanh(v/v_s), v_s = 1 mm/s, flips the load within ~0.1 ms at every cart "
          << "reversal, where the two integrators' step choices differ most (the largest difference sits just "
          << "after a reversal, t_at_max in comparison.json), and a rigid drive's coupling torque "
          << "M_motor - J_n1*eps carries the acceleration's error; the single cart swings its crank speed most.";
    md_ << "\n\n"
        << "| case | accuracy | max_rel ω_crank | max_rel coupling torque | CPU multibody [s] | result |\n"
        << "|---|---|---|---|---|---|\n";
    for (const auto& c : r_.convergence)
      md_ << "| " << c.label << " | " << g(c.accuracy) << " | " << g(c.max_rel_omega, 2) << " | " << g(c.max_rel_torque, 2)
          << " | " << g(c.cpu_multibody, 3) << " | " << (c.pass ? "pass" : "above 1e-6") << " |\n";
  }
  out_.tables.push_back({"equivalence.csv", t});
  md_ << "\nCommands:\n\n";
  for (const auto& c : r_.equivalence) md_ << "- " << c.label << ": `" << c.command << "`\n";
  double lo = kNaN, hi = kNaN;
  for (const auto& c : r_.equivalence)
    if (c.cpu_reduced > 0 && c.cpu_multibody > 0) {
      const double f = c.cpu_multibody / c.cpu_reduced;
      lo = std::isfinite(lo) ? std::min(lo, f) : f;
      hi = std::isfinite(hi) ? std::max(hi, f) : f;
    }
  if (!r_.equivalence.empty() && r_.equivalence.front().cpu_reduced > 0) {
    const ComparisonCase& e0 = r_.equivalence.front();
    md_ << "\nSpeed (CPU seconds of the integration, same scene, same output grid): on E0 the reduced model took "
        << g(e0.cpu_reduced, 3) << " s against " << g(e0.cpu_multibody, 3) << " s for the multibody model (ratio "
        << "reduced/multibody " << g(e0.cpu_reduced / e0.cpu_multibody, 2) << ", i.e. " << g(e0.cpu_multibody / e0.cpu_reduced, 3)
        << "x faster); over all equivalence cases the speed-up ranges " << g(lo, 3) << " ... " << g(hi, 3) << "x.\n";
  }
  if (!r_.equivalence_example.rows.empty()) {
    PlotSpec s;
    s.title = "E0: |multibody - reduced| / max|multibody|";
    s.xlabel = "t [s]";
    s.ylabel = "relative difference [-]";
    s.logy = true;
    s.series.push_back(relativeDifference(r_.equivalence_example, "omega_crank", "crank speed"));
    s.series.push_back(relativeDifference(r_.equivalence_example, "coupling_torque", "coupling torque"));
    s.series.push_back(series("target", {r_.equivalence_example.rows.front()[0], r_.equivalence_example.rows.back()[0]},
                              {kEquivalenceTarget, kEquivalenceTarget}));
    figure("equivalence_E0", s, "E0 (the issue's command): relative difference of crank speed and coupling torque over the run");
  }
}

void ReportWriter::differences() {
  md_ << "\n## (2) Where the physics differ\n\n"
      << "Each case changes one modelling aspect away from (1) (or runs a shipped scene as it is); "
      << "the differences measured, and the measurement that explains them. \"reactions\" = largest "
      << "max_rel_diff over N_front_j, N_rear_j, F_rod_j; quasi-static = the reduced model's own "
      << "reaction output, kinetostatic = with the carts' d'Alembert forces.\n\n"
      << "| case | what differs | max_rel ω_crank | max_rel coupling torque | reactions quasi-static | reactions kinetostatic | CPU mb / red [s] |\n"
      << "|---|---|---|---|---|---|---|\n";
  for (const auto& c : r_.differences) {
    std::string topics;
    for (const auto& t : c.topics) topics += (topics.empty() ? "" : ", ") + t;
    md_ << "| " << c.label << " | " << c.description << " (" << topics << ") | " << g(c.max_rel_omega, 2) << " | "
        << g(c.max_rel_torque, 2) << " | " << g(c.max_rel_reactions_quasistatic, 2) << " | "
        << g(c.max_rel_reactions_kinetostatic, 2) << " | " << g(c.cpu_multibody, 3) << " / " << g(c.cpu_reduced, 2)
        << " |\n";
  }
  md_ << "\n";
  for (const auto& c : r_.differences) {
    md_ << "- **" << c.label << "** " << c.explanation;
    for (const auto& [k, v] : c.measured) md_ << " " << k << ": " << v << ".";
    if (!c.command.empty()) md_ << " `" << c.command << "`";
    md_ << "\n";
  }
  if (!r_.distributed_example.rows.empty()) {
    const Table& t = r_.distributed_example;
    const auto tt = t.column("t");
    // The last 0.6 s: about one revolution at ~10.7 rad/s.
    std::vector<double> x;
    std::vector<std::vector<double>> ys(3);
    const char* cols[] = {"N_front_1_multibody", "N_front_1_reduced", "N_front_1_reduced_kinetostatic"};
    for (std::size_t i = 0; i < tt.size(); ++i)
      if (tt[i] >= tt.back() - 0.6) {
        x.push_back(tt[i]);
        for (int k = 0; k < 3; ++k) ys[k].push_back(t.rows[i][t.index(cols[k])]);
      }
    PlotSpec s;
    s.title = "D1 (distributed rods): front guide reaction of cart 1";
    s.xlabel = "t [s]";
    s.ylabel = "N_{front,1} [N]";
    s.series = {series("multibody (dynamic)", x, ys[0]), series("reduced, quasi-static (Loveikin, Pochka, Romasevych (2018) eq. (18))", x, ys[1]),
                series("reduced, kinetostatic (+ cart d'Alembert force)", x, ys[2])};
    figure("reactions_D1", s, "D1: guide reaction of cart 1 over the last revolution, three ways");
  }
  if (!r_.friction_example.rows.empty()) {
    const Table& t = r_.friction_example;
    const auto tt = t.column("t"), a = t.column("omega_crank_multibody"), b = t.column("omega_crank_reduced");
    std::vector<double> d;
    for (std::size_t i = 0; i < a.size(); ++i) d.push_back(a[i] - b[i]);
    PlotSpec s;
    s.title = "D3 (guide friction): crank speed, multibody - reduced";
    s.xlabel = "t [s]";
    s.ylabel = "ω_{crank} difference [rad/s]";
    s.series = {series("multibody - reduced", tt, d)};
    figure("friction_D3", s, "D3: crank speed difference caused by friction from dynamic vs quasi-static reactions");
  }
}

void ReportWriter::seed004(const PaperSweep& p) {
  md_ << "\n### Loveikin and Pochka (2007): recuperative drive, Δφ sweep\n\n"
      << "Scene `model/" << p.scene_file << "` as shipped (its header lists every assumption), "
      << "`--set " << p.x_key << "=...`. \"ours\" = reduced model (CVODE, exact); \"Baranov\" = "
      << p.variant_label << "; \"mb\" = multibody model. Published: `validation/published/" << p.published_file
      << "`. Gap = (ours - published)/published.\n\n";
  std::vector<SweepColumn> cols = {{"Δφ [deg]", [](const SweepPoint& s) { return g(s.x); }},
                                   speedColumn("ω_min", "omega_min", &RunMetrics::omega_min, 2),
                                   speedColumn("ω_max", "omega_max", &RunMetrics::omega_max, 2)};
  addCoefficient(cols, "δ", "delta", &RunMetrics::delta, /*variant=*/true);
  addCoefficient(cols, "H", "H", &RunMetrics::H, /*variant=*/true);
  addPublishedAndOurs(cols, "k_p", "k_p", &RunMetrics::k_p);
  sweepTable(md_, cols, p.points);
  out_.tables.push_back({"seed004_sweep.csv", coefficientCsv(p.points, "dphi_deg", /*H_variant=*/true)});
  coefficientFigure("seed004_delta", plot("Loveikin and Pochka (2007): coefficient of unevenness δ (eq. (12))", p.x_label, "δ [-]"),
                    "published (Loveikin and Pochka (2007) table)", coefficientCurves(p.points, "delta", &RunMetrics::delta),
                    /*variant=*/true, "Loveikin and Pochka (2007): δ against the crank offset, published and ours");
  coefficientFigure("seed004_H", plot("Loveikin and Pochka (2007): coefficient of dynamics H (eq. (13))", p.x_label, "H [-]"),
                    "published (Loveikin and Pochka (2007) table)", coefficientCurves(p.points, "H", &RunMetrics::H),
                    /*variant=*/true, "Loveikin and Pochka (2007): H against the crank offset, published and ours");
}

void ReportWriter::seed003(const PaperSweep& p) {
  md_ << "\n### The energy-balanced drive paper: energy-balanced drive, flywheel sweep\n\n"
      << "Scene `model/" << p.scene_file << "` as shipped, `--set " << p.x_key << "=...` (flywheel on the "
      << "crankshaft, see the scene header). Columns as for Loveikin and Pochka (2007). Published: `validation/published/"
      << p.published_file << "`.\n\n";
  // Speeds to three decimals, as the energy-balanced drive paper prints them (Loveikin and Pochka (2007): two), and the mean speed too.
  std::vector<SweepColumn> cols = {{"I_fw [kg·m²]", [](const SweepPoint& s) { return g(s.x, 6); }},
                                   speedColumn("ω_min", "omega_min", &RunMetrics::omega_min, 3),
                                   speedColumn("ω_max", "omega_max", &RunMetrics::omega_max, 3),
                                   speedColumn("ω_mean", "omega_mean", &RunMetrics::omega_mean, 3)};
  addCoefficient(cols, "δ", "delta", &RunMetrics::delta, /*variant=*/true);
  addCoefficient(cols, "H", "H", &RunMetrics::H, /*variant=*/false);
  addPublishedAndOurs(cols, "k_p", "k_p", &RunMetrics::k_p);
  sweepTable(md_, cols, p.points);
  out_.tables.push_back({"seed003_sweep.csv", coefficientCsv(p.points, "flywheel_inertia", /*H_variant=*/false)});
  // δ and H fall tenfold over the flywheel sweep: logarithmic y axis.
  coefficientFigure("seed003_delta", plot("the energy-balanced drive paper: coefficient of unevenness δ vs flywheel inertia", p.x_label, "δ [-]", true),
                    "published (the energy-balanced drive paper Table 1)", coefficientCurves(p.points, "delta", &RunMetrics::delta),
                    /*variant=*/true, "The energy-balanced drive paper: δ against the flywheel inertia, published and ours");
  coefficientFigure("seed003_H", plot("the energy-balanced drive paper: coefficient of dynamics H vs flywheel inertia", p.x_label, "H [-]", true),
                    "published (the energy-balanced drive paper Table 1)", coefficientCurves(p.points, "H", &RunMetrics::H),
                    /*variant=*/false, "The energy-balanced drive paper: H against the flywheel inertia, published and ours");
}

void ReportWriter::seed000(const PaperSweep& p) {
  md_ << "\n### Loveikin, Pochka, Romasevych (2018): four carts, elastic coupling, Table 1\n\n"
      << "Scene `model/" << p.scene_file << "` as shipped (start from rest, roller forces as printed, "
      << "distributed rods, f = 0.008), `--set crank.offset_deg=... --set coupling.damping=k`. "
      << "\"variant\" = " << p.variant_label << ". Swings (max - min) over the steady window. "
      << "\"rotates\": the crank turns steadily (mean crank speed in rad/s); where it does not (it swings back "
      << "and forth without whole turns in one direction, or the motor cannot start it) the swings describe a different motion and are left out "
      << "(\"–\"). Published: `validation/published/" << p.published_file << "`.\n\n"
      << "| Δφ [deg] | k | rotates (mean ω) | ΔM pub [N·m] | ΔM ours | gap | ΔM variant | ΔM mb | Δψ pub [rad] | Δψ ours | Δψ̇ pub [rad/s] | Δψ̇ ours | Δψ̈ pub [rad/s²] | Δψ̈ ours |\n"
      << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  Table t;
  t.columns = {"dphi_deg", "k", "rotating", "omega_mean", "coupling_torque_swing", "twist_swing", "twist_rate_swing",
               "twist_accel_swing", "coupling_torque_swing_variant", "coupling_torque_swing_multibody",
               "coupling_torque_swing_published"};
  std::map<double, std::vector<double>> x, mp, mr, mv;
  std::vector<double> xm, mm;
  for (const auto& s : p.points) {
    const RunMetrics& m = s.reduced;
    std::string rot = m.rotating ? "yes (" + fx(m.omega_mean, 2) + ")"
                      : !m.complete ? "no: " + m.status
                                    : "no: oscillates (mean " + fx(m.omega_mean, 2) + ")";
    md_ << "| " << g(s.x) << " | " << g(s.k, 6) << " | " << rot << " | " << g(pub(s, "coupling_torque_swing"), 4) << " | " << g(ok(m, &RunMetrics::torque_swing), 4) << " | "
        << pct(ok(m, &RunMetrics::torque_swing), pub(s, "coupling_torque_swing")) << " | "
        << g(ok(s.variant, &RunMetrics::torque_swing), 4) << " | "
        << (s.has_multibody ? g(ok(s.multibody, &RunMetrics::torque_swing), 4) : "") << " | "
        << g(pub(s, "twist_swing")) << " | " << g(ok(m, &RunMetrics::twist_swing)) << " | "
        << g(pub(s, "twist_rate_swing")) << " | " << g(ok(m, &RunMetrics::twist_rate_swing)) << " | "
        << g(pub(s, "twist_accel_swing")) << " | " << g(ok(m, &RunMetrics::twist_accel_swing)) << " |\n";
    t.rows.push_back({s.x, s.k, m.rotating ? 1.0 : 0.0, m.omega_mean, m.torque_swing, m.twist_swing, m.twist_rate_swing,
                      m.twist_accel_swing, s.variant.torque_swing, s.has_multibody ? s.multibody.torque_swing : kNaN,
                      pub(s, "coupling_torque_swing")});
    x[s.k].push_back(s.x);
    mp[s.k].push_back(pub(s, "coupling_torque_swing"));
    mr[s.k].push_back(ok(m, &RunMetrics::torque_swing));
    mv[s.k].push_back(ok(s.variant, &RunMetrics::torque_swing));
    if (s.has_multibody && s.k == 8000) {
      xm.push_back(s.x);
      mm.push_back(ok(s.multibody, &RunMetrics::torque_swing));
    }
  }
  out_.tables.push_back({"seed000_sweep.csv", t});
  PlotSpec s;
  s.title = "Loveikin, Pochka, Romasevych (2018) Table 1: coupling torque swing";
  s.xlabel = p.x_label;
  s.ylabel = "coupling torque swing [N m]";
  s.logy = true;
  for (const auto& [k, xs] : x) {
    s.series.push_back(series("published, k = " + g(k, 6), xs, mp[k], "linespoints"));
    s.series.push_back(series("reduced, k = " + g(k, 6), xs, mr[k], "linespoints"));
  }
  s.series.push_back(series("multibody, k = 8000", xm, mm, "points pt 7 ps 1.5"));
  figure("seed000_torque_swing", s, "Loveikin, Pochka, Romasevych (2018): coupling torque swing against the crank offset (missing points: the crank does not rotate)");
}

void ReportWriter::sensitivity() {
  md_ << "\n### Sensitivity to what the papers leave open (reduced model, one change at a time)\n\n"
      << "Not fits: each row changes one unstated input or modelling choice at one point and shows "
      << "how far the metric moves; the tables above keep the shipped scenes.\n\n"
      << "| paper | point | change | metric | baseline | changed | published |\n|---|---|---|---|---|---|---|\n";
  for (const auto& s : r_.sensitivity)
    md_ << "| " << s.paper << " | " << s.point << " | " << s.change << " | " << s.metric << " | " << g(s.baseline, 4)
        << " | " << g(s.changed, 4) << " | " << g(s.published, 5) << " |\n";
}

void ReportWriter::analytic() {
  const AnalyticResults& a = r_.analytic;
  if (a.closed_forced.empty()) return;
  const double p0 = naturalFrequency(a.forced);
  md_ << "\n## (4) Analytic: two rotors on an elastic link (Dyomin (two rotors)) against the ElasticCoupling element\n\n"
      << "A Simbody system of two Pin rotors joined by `ElasticCoupling` (src/multibody/ElasticCoupling.h), "
      << "driven by the paper's torque series eq. (8) on rotor 1 and a constant resisting torque on rotor 2 "
      << "(src/compare/TwoRotorCheck.h). Dyomin (two rotors) prints no numbers; the rotors are the Loveikin, Pochka, Romasevych (2018) drive "
      << "(ASSUMED): J1 = " << g(a.forced.J1, 4) << " kg·m², J2 = " << g(a.forced.J2, 4) << " kg·m², k = "
      << g(a.forced.k) << " N·m/rad, b = " << g(a.forced.b) << " N·m·s/rad, M1 = " << g(a.forced.M1)
      << " N·m, α = 30°, M_c = " << g(a.forced.Mc, 4) << " N·m. Integrator RungeKuttaMerson at accuracy "
      << g(a.accuracy) << ", no interpolation.\n\n";
  const auto& u = a.measured_undamped;
  const auto& d = a.measured_damped;
  md_ << "| check | closed form | simulated | relative error |\n|---|---|---|---|\n"
      << "| p0, eq. (10), free oscillation b = 0 [rad/s] | " << g(p0, 10) << " | " << g(u.frequency, 10) << " | "
      << g(u.frequency / p0 - 1, 2) << " |\n"
      << "| p1, eq. (14), b = " << g(a.free_damped.b) << " [rad/s] | " << g(dampedFrequency(a.free_damped), 10) << " | "
      << g(d.frequency, 10) << " | " << g(d.frequency / dampedFrequency(a.free_damped) - 1, 2) << " |\n"
      << "| δ1, eq. (9), b = " << g(a.free_damped.b) << " [1/s] | " << g(dampingRate(a.free_damped), 10) << " | "
      << g(d.decay_rate, 10) << " | " << g(d.decay_rate / dampingRate(a.free_damped) - 1, 2) << " |\n"
      << "| p0 from the damped run, sqrt(p1² + δ1²) [rad/s] | " << g(p0, 10) << " | " << g(d.natural_frequency, 10)
      << " | " << g(d.natural_frequency / p0 - 1, 2) << " |\n"
      << "| mean twist Φ0, eq. (42)-(43) [rad] | " << g(a.mean_twist_expected, 8) << " | "
      << g(a.measured_forced.mean_twist, 8) << " | " << g(a.measured_forced.mean_twist / a.mean_twist_expected - 1, 2)
      << " |\n\n"
      << "Frequencies from " << u.periods << " (undamped) and " << d.periods
      << " (damped) periods of upward zero crossings located by cubic Hermite interpolation; decay from maxima one "
      << "period apart.\n\n";
  auto harmonics = [&](const char* title, const TwoRotorParameters& pp, const std::vector<HarmonicResponse>& cf,
                       const ForcedResponseMeasurement& m) {
    md_ << "**" << title << "** (ω = " << g(pp.omega, 5) << " rad/s, p0/ω = " << g(p0 / pp.omega, 4)
        << "): steady twist harmonics, measured over " << m.periods << " periods after " << g(m.settle_time)
        << " s.\n\n| harmonic | exact closed form [rad] | paper as printed, eq. (16)-(21), (27)-(28) [rad] | simulated [rad] | error vs exact (of the 1st harmonic) |\n|---|---|---|---|---|\n";
    double a1 = 0;
    for (const auto& h : cf)
      if (h.n == 1) a1 = h.amplitude;
    for (std::size_t i = 0; i < cf.size() && i < m.harmonics.size(); ++i) {
      const double err = std::hypot(m.harmonics[i].a_sin - cf[i].a_sin, m.harmonics[i].b_cos - cf[i].b_cos);
      md_ << "| " << cf[i].n << "ω | " << g(cf[i].amplitude, 6) << " | " << g(cf[i].amplitude_printed, 6) << " | "
          << g(m.harmonics[i].amplitude, 6) << " | " << g(err / a1, 2) << " |\n";
    }
    md_ << "\n";
  };
  harmonics("Forced, crank speed of Loveikin, Pochka, Romasevych (2018)", a.forced, a.closed_forced, a.measured_forced);
  harmonics("Forced, third harmonic at resonance (3ω = p0)", a.resonant, a.closed_resonant, a.measured_resonant);
  md_ << "The simulated harmonics (sin and cos parts) match the exact steady solution of eq. (7) with the "
      << "forcing of eq. (8). The paper's printed amplitudes agree for the first harmonic up to its phase "
      << "combination: eq. (17), (18), (20), (21) as printed omit the 1/n factor of the series (8) (they are n "
      << "times the response to (8)), and eq. (15) writes the cosine responses as cos(nωt + ξ) where a damped "
      << "oscillator lags, cos(nωt - ξ), which eq. (27)-(28) inherit (the -2Ψ·Ψ·sin 2ξ term). With the 1/n and the "
      << "lag restored the closed form and the simulation agree to integration accuracy.\n";
  // Figure: ψ(t) over two periods, simulated samples vs closed form.
  {
    const auto& m = a.measured_forced;
    const double T = 2 * M_PI / a.forced.omega;
    std::vector<double> ts, ys, tc, yc;
    for (std::size_t i = 0; i < m.t.size(); ++i)
      if (m.t[i] <= m.settle_time + 2 * T) {
        if (i % 4 == 0) {
          ts.push_back(m.t[i]);
          ys.push_back(m.twist[i]);
        }
        double y = a.mean_twist_expected;
        for (const auto& h : a.closed_forced)
          y += h.a_sin * std::sin(h.n * a.forced.omega * m.t[i]) + h.b_cos * std::cos(h.n * a.forced.omega * m.t[i]);
        tc.push_back(m.t[i]);
        yc.push_back(y);
      }
    PlotSpec s;
    s.title = "Dyomin (two rotors): steady twist of two rotors on the ElasticCoupling element";
    s.xlabel = "t [s]";
    s.ylabel = "twist ψ = φ_1 - φ_2 [rad]";
    s.series = {series("closed form (eq. (7), (8), exact)", tc, yc), series("Simbody simulation", ts, ys, "points pt 6")};
    figure("seed002_forced", s, "Dyomin (two rotors): simulated twist against the closed-form steady response");
  }
  {
    const auto& m = a.measured_damped;
    std::vector<double> ts, ys;
    for (std::size_t i = 0; i < m.t.size(); ++i) {
      ts.push_back(m.t[i]);
      ys.push_back(m.twist[i]);
    }
    const double dl = dampingRate(a.free_damped);
    std::vector<double> env, envn;
    for (double t : ts) {
      env.push_back(m.initial_twist * std::exp(-dl * t));
      envn.push_back(-m.initial_twist * std::exp(-dl * t));
    }
    PlotSpec s;
    s.title = "Dyomin (two rotors): free oscillation, b = " + g(a.free_damped.b) + " N m s/rad";
    s.xlabel = "t [s]";
    s.ylabel = "twist [rad]";
    s.series = {series("Simbody simulation", ts, ys), series("±ψ_0 exp(-δ_1 t), eq. (9)", ts, env),
                series("", ts, envn)};
    figure("seed002_free", s, "Dyomin (two rotors): free oscillation and the decay envelope of eq. (9)");
  }
}

ValidationReport ReportWriter::build() {
  header();
  equivalence();
  differences();
  md_ << "\n## (3) The papers' tables\n\nInputs are the shipped scene files; they are never tuned to "
      << "the published numbers. The published tables came from the papers' own coarse scheme and "
      << "partly unstated inputs (docs/physics-digest.md, scene file headers); the likely causes of "
      << "each gap are listed after its table.\n";
  for (const auto& p : r_.papers) {
    if (p.id == "seed004") seed004(p);
    if (p.id == "seed003") seed003(p);
    if (p.id == "seed000") seed000(p);
    if (!p.causes.empty()) {
      md_ << "\nLikely causes of the gap:\n\n";
      for (const auto& c : p.causes) md_ << "- " << c << "\n";
    }
  }
  sensitivity();
  analytic();
  out_.markdown = md_.str();

  // results.json
  nlohmann::json j;
  j["quick"] = r_.quick;
  j["cpu_seconds"] = num(r_.cpu_seconds);
  j["equivalence_target"] = kEquivalenceTarget;
  j["equivalence"] = nlohmann::json::array();
  for (const auto& c : r_.equivalence) j["equivalence"].push_back(caseJson(c));
  j["convergence"] = nlohmann::json::array();
  for (const auto& c : r_.convergence) j["convergence"].push_back(caseJson(c));
  j["differences"] = nlohmann::json::array();
  for (const auto& c : r_.differences) j["differences"].push_back(caseJson(c));
  j["papers"] = nlohmann::json::object();
  for (const auto& p : r_.papers) {
    nlohmann::json pts = nlohmann::json::array();
    for (const auto& s : p.points) {
      nlohmann::json pj = {{"x", s.x}, {"reduced", metricsJson(s.reduced)}};
      if (s.k != 0) pj["k"] = s.k;
      if (s.has_variant) pj["variant"] = metricsJson(s.variant);
      if (s.has_multibody) pj["multibody"] = metricsJson(s.multibody);
      if (s.has_published) pj["published"] = s.published;
      pts.push_back(pj);
    }
    j["papers"][p.id] = {{"title", p.title}, {"scene", p.scene_file}, {"x_key", p.x_key},
                         {"variant", p.variant_label}, {"causes", p.causes}, {"points", pts}};
  }
  j["sensitivity"] = nlohmann::json::array();
  for (const auto& s : r_.sensitivity)
    j["sensitivity"].push_back({{"paper", s.paper}, {"point", s.point}, {"change", s.change}, {"metric", s.metric},
                                {"baseline", num(s.baseline)}, {"changed", num(s.changed)}, {"published", num(s.published)}});
  const AnalyticResults& a = r_.analytic;
  if (!a.closed_forced.empty()) {
    auto harm = [](const std::vector<HarmonicResponse>& cf, const ForcedResponseMeasurement& m) {
      nlohmann::json arr = nlohmann::json::array();
      for (std::size_t i = 0; i < cf.size() && i < m.harmonics.size(); ++i)
        arr.push_back({{"n", cf[i].n}, {"exact", cf[i].amplitude}, {"printed", cf[i].amplitude_printed},
                       {"simulated", m.harmonics[i].amplitude}});
      return arr;
    };
    j["analytic_seed002"] = {
        {"p0_closed_form", naturalFrequency(a.forced)},
        {"p0_simulated", a.measured_undamped.frequency},
        {"p1_closed_form", dampedFrequency(a.free_damped)},
        {"p1_simulated", a.measured_damped.frequency},
        {"delta1_closed_form", dampingRate(a.free_damped)},
        {"delta1_simulated", a.measured_damped.decay_rate},
        {"mean_twist_closed_form", a.mean_twist_expected},
        {"mean_twist_simulated", a.measured_forced.mean_twist},
        {"harmonics_forced", harm(a.closed_forced, a.measured_forced)},
        {"harmonics_resonant", harm(a.closed_resonant, a.measured_resonant)}};
  }
  out_.results = j;
  return std::move(out_);
}

}  // namespace

ValidationReport buildValidationReport(const ValidationResults& results, const std::string& figure_dir) {
  return ReportWriter(results, figure_dir).build();
}

}  // namespace rollerdyn::validation
