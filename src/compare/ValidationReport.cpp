// report.md (header, sections (1) and (2)), results.json and the result tables of the
// validation suite (ValidationSuite.h); sections (3) and (4) are in PaperReport.cpp. Everything
// here formats numbers computed by the suite.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <map>
#include <sstream>

#include "compare/ReportInternal.h"

namespace rollerdyn::validation {
namespace report_detail {
namespace {

nlohmann::json metricsJson(const RunMetrics& m) {
  return {{"complete", m.complete},         {"status", m.status},
          {"steady", m.steady},             {"rotating", m.rotating},
          {"omega_min", jsonNumber(m.omega_min)},  {"omega_max", jsonNumber(m.omega_max)},
          {"omega_mean", jsonNumber(m.omega_mean)}, {"delta", jsonNumber(m.delta)},
          {"eps_abs_max", jsonNumber(m.eps_abs_max)}, {"H", jsonNumber(m.H)},
          {"k_p", jsonNumber(m.k_p)},              {"coupling_torque_swing", jsonNumber(m.torque_swing)},
          {"twist_swing", jsonNumber(m.twist_swing)}, {"twist_rate_swing", jsonNumber(m.twist_rate_swing)},
          {"twist_accel_swing", jsonNumber(m.twist_accel_swing)}, {"cpu_seconds", jsonNumber(m.cpu_seconds)}};
}

nlohmann::json caseJson(const ComparisonCase& c) {
  nlohmann::json m = nlohmann::json::object();
  for (const auto& [k, v] : c.measured) m[k] = v;
  return {{"label", c.label},
          {"description", c.description},
          {"command", c.command},
          {"revolutions", c.revolutions},
          {"t_end", jsonNumber(c.t_end)},
          {"accuracy", jsonNumber(c.accuracy)},
          {"max_rel_diff_omega_crank", jsonNumber(c.max_rel_omega)},
          {"max_rel_diff_coupling_torque", jsonNumber(c.max_rel_torque)},
          {"max_rel_diff_reactions_quasistatic", jsonNumber(c.max_rel_reactions_quasistatic)},
          {"max_rel_diff_reactions_kinetostatic", jsonNumber(c.max_rel_reactions_kinetostatic)},
          {"cpu_seconds_multibody", jsonNumber(c.cpu_multibody)},
          {"cpu_seconds_reduced", jsonNumber(c.cpu_reduced)},
          {"complete", c.complete},
          {"motion_equivalent", c.motion_equivalent},
          {"differences", c.topics},
          {"measured", m},
          {"explanation", c.explanation},
          {"verdict", c.verdict == Finding::Verdict::Holds   ? "holds"
                      : c.verdict == Finding::Verdict::Fails ? "failed"
                                                             : "measurement"},
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

nlohmann::json casesJson(const std::vector<ComparisonCase>& cases) {
  nlohmann::json a = nlohmann::json::array();
  for (const auto& c : cases) a.push_back(caseJson(c));
  return a;
}

// A paper's sweep in results.json: every point with our runs and the published row, the findings,
// and (Loveikin, Pochka, Romasevych (2018)) the other reading of the roller forces.
nlohmann::json paperJson(const PaperSweep& p) {
  nlohmann::json pts = nlohmann::json::array();
  for (const auto& s : p.points) {
    nlohmann::json pj = {{"x", s.x}, {"reduced", metricsJson(s.reduced)}};
    if (s.k != 0) pj["k"] = s.k;
    if (s.has_variant) pj["variant"] = metricsJson(s.variant);
    if (s.has_multibody) pj["multibody"] = metricsJson(s.multibody);
    if (s.has_published) pj["published"] = s.published;
    pts.push_back(pj);
  }
  nlohmann::json findings = nlohmann::json::array();
  for (const auto& f : p.findings) findings.push_back({{"text", f.text}, {"verdict", verdictKey(f.verdict)}});
  nlohmann::json other = nlohmann::json::array();
  for (const auto& s : p.other_reading) other.push_back({{"x", s.x}, {"k", s.k}, {"reduced", metricsJson(s.reduced)}});
  nlohmann::json j = {{"title", p.title}, {"scene", p.scene_file}, {"start", p.start}, {"x_key", p.x_key},
                      {"variant", p.variant_label}, {"findings", findings}, {"points", pts}};
  if (!other.empty()) j["other_reading"] = other;
  return j;
}

nlohmann::json sensitivityJson(const std::vector<SensitivityRow>& rows) {
  nlohmann::json a = nlohmann::json::array();
  for (const auto& s : rows)
    a.push_back({{"paper", s.paper}, {"point", s.point}, {"change", s.change}, {"metric", s.metric},
                 {"baseline", jsonNumber(s.baseline)}, {"changed", jsonNumber(s.changed)}, {"published", jsonNumber(s.published)}});
  return a;
}

nlohmann::json harmonicsJson(const std::vector<HarmonicResponse>& cf, const ForcedResponseMeasurement& m) {
  nlohmann::json arr = nlohmann::json::array();
  for (std::size_t i = 0; i < cf.size() && i < m.harmonics.size(); ++i)
    arr.push_back({{"n", cf[i].n}, {"exact", cf[i].amplitude}, {"printed", cf[i].amplitude_printed},
                   {"simulated", m.harmonics[i].amplitude}});
  return arr;
}

nlohmann::json analyticJson(const AnalyticResults& a) {
  return {{"p0_closed_form", naturalFrequency(a.forced)},
          {"p0_simulated", a.measured_undamped.frequency},
          {"p1_closed_form", dampedFrequency(a.free_damped)},
          {"p1_simulated", a.measured_damped.frequency},
          {"delta1_closed_form", dampingRate(a.free_damped)},
          {"delta1_simulated", a.measured_damped.decay_rate},
          {"mean_twist_closed_form", a.mean_twist_expected},
          {"mean_twist_simulated", a.measured_forced.mean_twist},
          {"harmonics_forced", harmonicsJson(a.closed_forced, a.measured_forced)},
          {"harmonics_resonant", harmonicsJson(a.closed_resonant, a.measured_resonant)}};
}

// What section (1) compares and how its table reads.
void equivalenceSetup(std::ostream& md, bool quick) {
  md << "\n## (1) Equivalence: identical physics in both models\n\n"
     << "Scenes made identical in physics: rods split into two point masses (Loveikin, Pochka, Romasevych (2018), eq. (2)-(3)), "
     << "no guide friction, exact kinematics, CVODE in the reduced model. Each run covers " << (quick ? "5" : "20")
     << " crank revolutions from the scene's start (t_end from the crank angle of a reduced-model probe run). "
     << "Target: max_rel_diff <= " << g(kEquivalenceTarget) << " for crank speed and coupling torque "
     << "E0 runs at accuracy 1e-9; E1-E7 at 1e-11 (see the convergence study below for why). The reactions column compares the multibody reactions with the reduced model's "
     << "*kinetostatic* reactions (cart statics with the carts' d'Alembert forces).\n\n";
}

void equivalenceTable(std::ostream& md, const std::vector<ComparisonCase>& cases) {
  md << "| case | scene | accuracy | revolutions | t_end [s] | max_rel ω_crank | max_rel coupling torque | max_rel reactions (kinetostatic) | CPU multibody [s] | CPU reduced [s] | result |\n"
     << "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& c : cases)
    md << "| " << c.label << " | " << c.description << " | " << g(c.accuracy) << " | " << g(c.revolutions) << " | "
       << g(c.t_end, 5) << " | " << g(c.max_rel_omega, 2) << " | " << g(c.max_rel_torque, 2) << " | "
       << g(c.max_rel_reactions_kinetostatic, 2) << " | " << g(c.cpu_multibody, 3) << " | " << g(c.cpu_reduced, 2)
       << " | " << (c.pass ? "pass" : ("**FAIL** " + c.explanation)) << " |\n";
}

// results/equivalence.csv: the table's numbers, the case by its number (E3 -> 3).
Table equivalenceCsv(const std::vector<ComparisonCase>& cases) {
  Table t;
  t.columns = {"case", "accuracy", "revolutions", "t_end", "max_rel_omega", "max_rel_torque", "max_rel_reactions_kinetostatic",
               "cpu_multibody", "cpu_reduced", "pass"};
  for (const auto& c : cases)
    t.rows.push_back({std::stod(c.label.substr(1)), c.accuracy, c.revolutions, c.t_end, c.max_rel_omega, c.max_rel_torque,
                      c.max_rel_reactions_kinetostatic, c.cpu_multibody, c.cpu_reduced, c.pass ? 1.0 : 0.0});
  return t;
}

// Why E1-E7 run at 1e-11, when some runs at 1e-9 and looser miss the target.
void convergenceNote(std::ostream& md, const std::vector<ComparisonCase>& convergence) {
  bool above = false;
  for (const auto& c : convergence) above = above || (c.accuracy >= 1e-9 && !c.pass);
  if (above)
    md << "\nAt 1e-9 some of these exceed " << g(kEquivalenceTarget) << " in the coupling torque. Loads opposing "
       << "the cart velocity follow tanh(v/v_s), v_s = 1 mm/s, and flip within ~0.1 ms at every cart reversal, "
       << "where the two integrators' step choices differ most; a rigid drive's coupling torque "
       << "M_motor − J_n1·ε (J_n1: motor-side inertia, ε: crank acceleration) carries the acceleration's error; "
       << "the single cart swings its crank speed most. Hence E1-E7 run at 1e-11.";
}

void convergenceTable(std::ostream& md, const std::vector<ComparisonCase>& convergence) {
  md << "\n\n"
     << "| case | accuracy | max_rel ω_crank | max_rel coupling torque | CPU multibody [s] | result |\n"
     << "|---|---|---|---|---|---|\n";
  for (const auto& c : convergence)
    md << "| " << c.label << " | " << g(c.accuracy) << " | " << g(c.max_rel_omega, 2) << " | " << g(c.max_rel_torque, 2)
       << " | " << g(c.cpu_multibody, 3) << " | " << (c.pass ? "pass" : "above 1e-6") << " |\n";
}

// The reduced model's speed-up over the multibody model: on E0 and its range over all cases.
void equivalenceSpeed(std::ostream& md, const std::vector<ComparisonCase>& cases) {
  double lo = kNaN, hi = kNaN;
  for (const auto& c : cases)
    if (c.cpu_reduced > 0 && c.cpu_multibody > 0) {
      const double f = c.cpu_multibody / c.cpu_reduced;
      lo = std::isfinite(lo) ? std::min(lo, f) : f;
      hi = std::isfinite(hi) ? std::max(hi, f) : f;
    }
  if (cases.empty() || !(cases.front().cpu_reduced > 0)) return;
  const ComparisonCase& e0 = cases.front();
  md << "\nSpeed (CPU seconds of the integration, same scene, same output grid): on E0 the reduced model took "
     << g(e0.cpu_reduced, 3) << " s against " << g(e0.cpu_multibody, 3) << " s for the multibody model (ratio "
     << "reduced/multibody " << g(e0.cpu_reduced / e0.cpu_multibody, 2) << ", i.e. " << g(e0.cpu_multibody / e0.cpu_reduced, 3)
     << "x faster); over all equivalence cases the speed-up ranges " << g(lo, 3) << " ... " << g(hi, 3) << "x.\n";
}

PlotSpec equivalencePlot(const Table& e0) {
  PlotSpec s = plot("E0: |multibody - reduced| / max|multibody|", "t [s]", "relative difference [-]", /*logy=*/true);
  s.series.push_back(relativeDifference(e0, "omega_crank", "crank speed"));
  s.series.push_back(relativeDifference(e0, "coupling_torque", "coupling torque"));
  s.series.push_back(series("target", {e0.rows.front()[0], e0.rows.back()[0]}, {kEquivalenceTarget, kEquivalenceTarget}));
  return s;
}

// A case's measured numbers and the command that reproduces it, ending its line of the list.
void caseDetails(std::ostream& md, const ComparisonCase& c) {
  for (const auto& [k, v] : c.measured) md << " " << k << ": " << v << ".";
  if (!c.command.empty()) md << " `" << c.command << "`";
  md << "\n";
}

// What section (2) changes and how its table reads.
void differencesSetup(std::ostream& md) {
  md << "\n## (2) Where the physics differ\n\n"
     << "Each case changes one modelling aspect away from (1) (or runs a shipped scene as it is); "
     << "the differences measured, and the measurement that explains them. \"reactions\" = largest "
     << "max_rel over the front and rear guide reactions and the rod force of every cart; quasi-static = the reduced model's own "
     << "reaction output, kinetostatic = with the carts' d'Alembert forces.\n\n";
}

// A case's topics in plain words: "guide_friction" -> "guide friction".
std::string topicWords(const std::vector<std::string>& topics) {
  std::string words;
  for (std::string t : topics) {
    std::replace(t.begin(), t.end(), '_', ' ');
    words += (words.empty() ? "" : ", ") + t;
  }
  return words;
}

void differencesTable(std::ostream& md, const std::vector<ComparisonCase>& cases) {
  md << "| case | what differs | max_rel ω_crank | max_rel coupling torque | reactions quasi-static | reactions kinetostatic | CPU mb / red [s] |\n"
     << "|---|---|---|---|---|---|---|\n";
  for (const auto& c : cases)
    md << "| " << c.label << " | " << c.description << " (" << topicWords(c.topics) << ") | " << g(c.max_rel_omega, 2) << " | "
       << g(c.max_rel_torque, 2) << " | " << g(c.max_rel_reactions_quasistatic, 2) << " | "
       << g(c.max_rel_reactions_kinetostatic, 2) << " | " << g(c.cpu_multibody, 3) << " / " << g(c.cpu_reduced, 2)
       << " |\n";
}

// The start of the run's last revolution: integrate the crank speed backwards from the end until
// it covers 2π (trapezoids on the output grid).
double lastRevolutionStart(const std::vector<double>& tt, const std::vector<double>& w) {
  double t_from = tt.front(), angle = 0;
  for (std::size_t i = tt.size() - 1; i > 0 && angle < 2.0 * M_PI; --i) {
    angle += 0.5 * (w[i] + w[i - 1]) * (tt[i] - tt[i - 1]);
    t_from = tt[i - 1];
  }
  return t_from;
}

// D1: cart 1's front guide reaction over the last revolution, multibody and both reduced readings.
PlotSpec reactionsD1Plot(const Table& t) {
  const auto tt = t.column("t");
  const double t_from = lastRevolutionStart(tt, t.column("omega_crank_multibody"));
  std::vector<double> x;
  std::vector<std::vector<double>> ys(3);
  const char* cols[] = {"N_front_1_multibody", "N_front_1_reduced", "N_front_1_reduced_kinetostatic"};
  for (std::size_t i = 0; i < tt.size(); ++i)
    if (tt[i] >= t_from) {
      x.push_back(tt[i]);
      for (int k = 0; k < 3; ++k) ys[k].push_back(t.rows[i][t.index(cols[k])]);
    }
  PlotSpec s = plot("D1 (distributed rods): front guide reaction of cart 1", "t [s]", "N_{front,1} [N]");
  s.series = {series("multibody (dynamic)", x, ys[0]), series("reduced, quasi-static (Loveikin, Pochka, Romasevych (2018) eq. (18))", x, ys[1]),
              series("reduced, kinetostatic (+ cart d'Alembert force)", x, ys[2])};
  return s;
}

// D3: the crank speed difference multibody - reduced over the run.
PlotSpec frictionD3Plot(const Table& t) {
  const auto tt = t.column("t"), a = t.column("omega_crank_multibody"), b = t.column("omega_crank_reduced");
  std::vector<double> d;
  for (std::size_t i = 0; i < a.size(); ++i) d.push_back(a[i] - b[i]);
  PlotSpec s = plot("D3 (guide friction): crank speed, multibody - reduced", "t [s]", "ω_{crank} difference [rad/s]");
  s.series = {series("multibody - reduced", tt, d)};
  return s;
}

}  // namespace

// The symbols of the whole report.
const char* const kSymbols =
    "Symbols: ω crank speed [rad/s]; Δφ crank offset between successive carts [°]; δ = (ω_max − ω_min)/ω_mean "
    "coefficient of unevenness (Loveikin and Pochka (2007), eq. (12)); H coefficient of dynamics and k_p "
    "dynamic factor of the drive torque (Loveikin and Pochka (2007), eq. (13)-(14)); c, k coupling stiffness "
    "[N·m/rad] and damping [N·m·s/rad]; ψ = φ_motor − φ_crank coupling twist [rad]; ΔM, Δψ, Δψ̇, Δψ̈ swings "
    "(max − min over the steady window) of the coupling torque c·ψ + k·ψ̇ and of the twist and its "
    "derivatives.\n\n";

void ReportWriter::header() {
  md_ << "# rollerdyn validation report\n\n"
      << "Written by `rollerdyn validate" << (r_.quick ? " --quick" : "")
      << "` (run from the repository root); every number below comes from that run"
      << (r_.quick ? " in **quick mode** (coarser sweeps, 5 instead of 20 revolutions)" : "")
      << ", and every claim is a comparison made in that run, printed with its outcome: **holds**, "
      << "**FAILED**, or, for a published table our inputs cannot reproduce, **gap, explained** (the gap's "
      << "numbers and its reason, whose own claims are checked in the same run). `rollerdyn validate` exits "
      << "with status 1 when any claim is FAILED or any equivalence case fails. CPU time of the whole suite: "
      << g(r_.cpu_seconds, 3) << " s.\n\n"
      << "Two models of the same machine are compared: the multibody model (Simbody: every body, joint and "
      << "constraint) and the reduced model (one equation of motion per shaft in the crank angle φ, with the "
      << "reduced inertia J(φ) of the papers). Reference for all relative differences: the multibody model, "
      << "max_rel = max|multibody − reduced| / max|multibody| over the compared run. Each case lists the "
      << "`rollerdyn compare` command that reproduces it. Machine-readable results: `results.json`; our sweep "
      << "numbers: `results/*.csv`.\n\n"
      << kSymbols
      << "Contents: (1) equivalence of the two models where their physics is identical; "
      << "(2) where the physics differ; (3) the papers' tables; (4) the analytic two-rotor check "
      << "of Dyomin (two rotors)";
  if (!r_.motor.empty()) md_ << "; (5) the induction-motor laws";
  for (std::size_t i = 0; i < r_.sections.size(); ++i)
    md_ << "; (" << i + firstItemNumber() << ") " << r_.sections[i].title();
  md_ << ".\n";
}

void ReportWriter::equivalence() {
  section("(1) Equivalence: identical physics in both models");
  equivalenceSetup(md_, r_.quick);
  equivalenceTable(md_, r_.equivalence);
  if (!r_.convergence.empty()) convergence();
  out_.tables.push_back({"equivalence.csv", equivalenceCsv(r_.equivalence)});
  md_ << "\nCommands:\n\n";
  for (const auto& c : r_.equivalence) md_ << "- " << c.label << ": `" << c.command << "`\n";
  equivalenceSpeed(md_, r_.equivalence);
  if (!r_.equivalence_example.rows.empty())
    figure("equivalence_E0", equivalencePlot(r_.equivalence_example),
           "E0: relative difference of crank speed and coupling torque over the run");
}

// Claim: what is left is integration error, i.e. the differences fall as the accuracy
// tightens: on average at least threefold per decade from the loosest to the tightest run of
// each case (a modelling difference would not fall at all).
void ReportWriter::convergence() {
  md_ << "\n**Convergence.** The same comparisons at other accuracies (both models). A modelling difference "
      << "would stay as the accuracy tightens; integration error falls with it. Claim: from the loosest to the "
      << "tightest accuracy each difference falls on average at least threefold per decade.\n\n";
  std::map<std::string, std::vector<const ComparisonCase*>> by_label;
  for (const auto& c : r_.convergence) by_label[c.label].push_back(&c);
  for (const auto& [label, cs] : by_label) convergenceClaim(label, cs);
  convergenceNote(md_, r_.convergence);
  convergenceTable(md_, r_.convergence);
}

// One case's convergence claim, from its loosest to its tightest run.
void ReportWriter::convergenceClaim(const std::string& label, const std::vector<const ComparisonCase*>& cs) {
  const ComparisonCase *lo = cs.front(), *hi = cs.front();
  for (const ComparisonCase* c : cs) {
    if (c->accuracy > lo->accuracy) lo = c;
    if (c->accuracy < hi->accuracy) hi = c;
  }
  const double decades = std::log10(lo->accuracy / hi->accuracy);
  const double fw = std::pow(lo->max_rel_omega / hi->max_rel_omega, 1.0 / decades);
  const double fm = std::pow(lo->max_rel_torque / hi->max_rel_torque, 1.0 / decades);
  const bool holds = decades > 0 && fw >= 3.0 && fm >= 3.0;
  const std::string text = "from " + g(lo->accuracy) + " to " + g(hi->accuracy) + " the crank-speed difference " +
                           "falls by " + g(fw, 2) + "x and the coupling-torque difference by " + g(fm, 2) +
                           "x per decade (at least 3x required)";
  md_ << "- " << label << ": " << text << ": "
      << verdict(label + " convergence", holds ? Verdict::Holds : Verdict::Fails, text) << ".\n";
}

void ReportWriter::perCart() {
  if (r_.per_cart.empty()) return;
  md_ << "\n### Carts of their own\n\n"
      << "The E1 scene with one cart changed (scene keys given per cart as lists, docs/per-cart.md), same physics "
      << "settings and accuracy. Each case claims (a) the models stay equivalent and (b) the change shows as "
      << "orders of the crank speed the uniform layout cancels (4 equal carts at 90°: only 4, 8, ... survive). "
      << "Order amplitudes A_k of the coupling torque M over the last whole crank revolutions, in crank angle.\n\n";
  for (const auto& c : r_.per_cart) {
    md_ << "- **" << c.label << "** " << c.description << ". " << c.explanation;
    // Every case makes its claims (a) and (b): one without a verdict (no result) counts as FAILED.
    const Verdict v = c.verdict == Verdict::Holds ? Verdict::Holds : Verdict::Fails;
    md_ << " " << verdict(c.label, v, c.description + ". " + c.explanation) << ".";
    caseDetails(md_, c);
  }
}

void ReportWriter::differences() {
  section("(2) Where the physics differ");
  differencesSetup(md_);
  differencesTable(md_, r_.differences);
  md_ << "\n";
  for (const auto& c : r_.differences) {
    md_ << "- **" << c.label << "** " << c.explanation;
    if (c.verdict != Verdict::Measurement) md_ << " " << verdict(c.label, c.verdict, c.explanation) << ".";
    caseDetails(md_, c);
  }
  if (!r_.distributed_example.rows.empty())
    figure("reactions_D1", reactionsD1Plot(r_.distributed_example),
           "D1: guide reaction of cart 1 over the last revolution, three ways");
  if (!r_.friction_example.rows.empty())
    figure("friction_D3", frictionD3Plot(r_.friction_example),
           "D3: crank speed difference caused by friction from dynamic vs quasi-static reactions");
}

ValidationReport ReportWriter::build() {
  header();
  equivalence();
  perCart();
  differences();
  papers();
  sensitivity();
  analytic();
  motor();
  items();
  out_.markdown = md_.str();
  out_.results = resultsJson();
  return std::move(out_);
}

// results.json: every case, sweep point, sensitivity row and analytic number of the run, and the
// claims of the report with their count (so it must follow the markdown).
nlohmann::json ReportWriter::resultsJson() const {
  nlohmann::json j;
  j["quick"] = r_.quick;
  j["cpu_seconds"] = jsonNumber(r_.cpu_seconds);
  j["equivalence_target"] = kEquivalenceTarget;
  j["equivalence"] = casesJson(r_.equivalence);
  j["per_cart"] = casesJson(r_.per_cart);
  j["convergence"] = casesJson(r_.convergence);
  j["differences"] = casesJson(r_.differences);
  j["motor"] = motorReportJson(r_.motor);
  j["papers"] = nlohmann::json::object();
  for (const auto& p : r_.papers) j["papers"][p.id] = paperJson(p);
  j["sensitivity"] = sensitivityJson(r_.sensitivity);
  if (!r_.analytic.closed_forced.empty()) j["analytic_dyomin"] = analyticJson(r_.analytic);
  j["claims"] = nlohmann::json::array();
  for (const Claim& c : out_.claims)
    j["claims"].push_back({{"id", c.id}, {"section", c.section}, {"verdict", verdictKey(c.verdict)}, {"text", c.text}});
  const ClaimCount n = countClaims(out_.claims);
  j["claim_count"] = {{"holds", n.holds}, {"gap_explained", n.gaps}, {"failed", n.failed}};
  j["equivalence_failed"] = failedEquivalenceCases(r_);
  return j;
}

// Section (5): each induction-motor claim (M1, ...) is a claim of the report like any other, so it is
// counted in the summary and decides the exit status.
void ReportWriter::motor() {
  md_ << motorReportMarkdown(r_.motor);
  for (const MotorClaim& c : r_.motor) {
    if (c.verdict == Verdict::Measurement) continue;
    std::string text = c.title;
    for (const std::string& l : c.lines) text += "; " + l;
    out_.claims.push_back({c.id, "(5) The induction-motor laws", text, c.verdict});
  }
}

int ReportWriter::firstItemNumber() const { return r_.motor.empty() ? 5 : 6; }

void ReportWriter::items() {
  for (std::size_t i = 0; i < r_.sections.size(); ++i) {
    const ValidationSection& s = r_.sections[i];
    md_ << "\n## (" << i + firstItemNumber() << ") " << s.title() << "\n\n" << s.markdown();
    for (const Claim& c : s.claims()) out_.claims.push_back(c);
  }
}

}  // namespace report_detail

ValidationReport buildValidationReport(const ValidationResults& results, const std::string& figure_dir) {
  return report_detail::ReportWriter(results, figure_dir).build();
}

int failedEquivalenceCases(const ValidationResults& results) {
  int failed = 0;
  for (const auto& c : results.equivalence)
    if (!c.pass) ++failed;
  return failed;
}

int validationExitStatus(const ValidationResults& results, const ValidationReport& report) {
  return failedEquivalenceCases(results) == 0 && countClaims(report.claims).failed == 0 ? 0 : 1;
}

std::string validationSummary(const ValidationResults& results, const ValidationReport& report) {
  const ClaimCount n = countClaims(report.claims);
  std::ostringstream o;
  o << n.total() << " claims: " << n.holds << " hold, " << n.gaps << " gap(s) explained, " << n.failed << " FAILED; "
    << results.equivalence.size() << " equivalence cases, " << failedEquivalenceCases(results) << " failed\n";
  for (const Claim& c : report.claims)
    if (c.verdict == Verdict::Fails) {
      std::string head = c.text.substr(0, 160);
      if (head.size() < c.text.size()) head += " ...";
      o << "  FAILED " << c.id << " (" << c.section << "): " << head << "\n";
    }
  return o.str();
}

}  // namespace rollerdyn::validation
