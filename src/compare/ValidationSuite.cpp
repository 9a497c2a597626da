// Runs the validation suite (ValidationSuite.h): the runner, the equivalence section (1) and
// the analytic two-rotor check (4). Section (2) is in ValidationDifferences.cpp, section (3) in
// ValidationPapers.cpp and PaperFindings.cpp; the report text in ValidationReport.cpp.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "analysis/Metrics.h"
#include "analysis/SteadyState.h"
#include "compare/PaperFindings.h"
#include "compare/SuiteInternal.h"
#include "io/CsvTable.h"

namespace rollerdyn::validation {
namespace detail {

double Suite::timeForRevolutions(const std::string& file, const std::vector<std::string>& sets,
                                 double revs) const {
  // Probe with the reduced model (cheap), long enough for the crank at a quarter of its
  // synchronous speed, and read when the crank angle has advanced by 2π·revs.
  const Scene base = load(file, sets);
  const double w_ref = 0.25 * base.motor.omega_sync / base.reducer.ratio;
  const double t_probe = 2.0 + revs * 2.0 * M_PI / w_ref;
  const Scene probe = load(file, concat(sets, {"simulation.t_end=" + exact(t_probe)}));
  const RunResult run = runReducedModel(probe);
  const std::vector<double> t = run.timeseries.column("t"), phi = run.timeseries.column("phi_crank");
  const double target = phi.front() + 2.0 * M_PI * revs;
  for (std::size_t i = 1; i < t.size(); ++i)
    if (phi[i] >= target) {
      const double f = (target - phi[i - 1]) / (phi[i] - phi[i - 1]);
      const double tr = t[i - 1] + f * (t[i] - t[i - 1]);
      const double h = probe.simulation.output_step;
      return std::ceil(tr / h - 1e-9) * h;  // whole output steps, at or just past the target
    }
  throw std::runtime_error("the crank does not complete " + g(revs) + " revolutions within " + g(t_probe) +
                           " s (" + run.stats.status + ")");
}

namespace {

// What a case reports of its comparison: the largest differences, CPU times, whether both runs
// completed, the modelling topics that differ, and whether it meets the equivalence target.
void measureCase(const ModelComparison& c, ComparisonCase& cc) {
  cc.max_rel_omega = c.find("omega_crank")->stats.max_rel_diff;
  cc.max_rel_torque = c.find("coupling_torque")->stats.max_rel_diff;
  for (const auto& q : c.quantities)
    if (q.name != "omega_crank" && q.name != "coupling_torque")
      cc.max_rel_reactions_quasistatic = std::max(cc.max_rel_reactions_quasistatic, q.stats.max_rel_diff);
  for (const auto& q : c.kinetostatic)
    cc.max_rel_reactions_kinetostatic = std::max(cc.max_rel_reactions_kinetostatic, q.stats.max_rel_diff);
  cc.cpu_multibody = c.cpuMultibody();
  cc.cpu_reduced = c.cpuReduced();
  cc.complete = c.multibody.stats.complete && c.reduced.stats.complete;
  if (!cc.complete)
    cc.explanation = "run ended early: multibody " + c.multibody.stats.status + "; reduced " + c.reduced.stats.status;
  cc.motion_equivalent = c.motion_equivalent;
  for (const auto& d : c.differences)
    if (!d.numerical) cc.topics.push_back(d.topic);
  cc.pass = cc.complete && cc.max_rel_omega <= kEquivalenceTarget && cc.max_rel_torque <= kEquivalenceTarget;
}

}  // namespace

ComparisonCase Suite::compareCase(const std::string& label, const std::string& description,
                                  const std::string& file, const std::vector<std::string>& sets,
                                  double revs, ModelComparison* keep) {
  ComparisonCase cc;
  cc.label = label;
  cc.description = description;
  cc.revolutions = revs;
  try {
    runCase(cc, file, sets, revs, keep);
  } catch (const std::exception& e) {
    cc.complete = false;
    cc.explanation = std::string("failed: ") + e.what();
    cc.max_rel_omega = cc.max_rel_torque = kNaN;
    log(label + ": " + cc.explanation);
  }
  return cc;
}

// Both models on the case's scene (`revs` > 0: run for that many crank revolutions), measured
// into cc; the comparison kept in `keep` when given.
void Suite::runCase(ComparisonCase& cc, const std::string& file, std::vector<std::string> sets, double revs,
                    ModelComparison* keep) {
  if (revs > 0) sets.push_back("simulation.t_end=" + exact(timeForRevolutions(file, sets, revs)));
  const Scene sc = load(file, sets);
  cc.command = command("compare", file, sets);
  cc.t_end = sc.simulation.t_end;
  cc.accuracy = sc.simulation.accuracy;
  log(cc.label + ": " + cc.description + " (t_end = " + g(cc.t_end, 5) + " s)");
  CompareControl control;
  control.interrupt = o_.interrupt;
  ModelComparison c = runComparison(sc, control);
  measureCase(c, cc);
  if (keep) *keep = std::move(c);
}

// An equivalence case E1-E7: the scene, what it changes, and whether --quick runs it.
struct Suite::EquivalenceSpec {
  const char* description;
  const char* file;
  std::vector<std::string> sets;
  bool quick;
};

namespace {

// E1-E7 at accuracy 1e-11: at 1e-9 the rigid-drive scenes with loads opposing the velocity and
// the single cart reach a few 1e-6 in the coupling torque and at 1e-10 the single cart still
// ~1e-6, an integration error (the convergence study below shows it falling tenfold per decade
// of accuracy); 1e-11 leaves a margin of about ten.
std::vector<Suite::EquivalenceSpec> equivalenceSpecs() {
  return {
      {"4 carts, one side, Δφ = 90°, elastic coupling (Loveikin, Pochka, Romasevych (2018) scene)", "balanced-4cart.yaml", {}, false},
      {"4 carts, one side, Δφ = 90°, rigid drive", "balanced-4cart.yaml", {"coupling.type=rigid"}, false},
      {"1 cart, elastic coupling", "balanced-4cart.yaml", {"carts.count=1"}, false},
      {"2 carts on opposite sides, Δφ = 90°, rigid drive (Loveikin and Pochka (2007) scene)", "recuperative-2cart.yaml", {}, true},
      {"3 carts, one side, Δφ = 120°, rigid drive (the energy-balanced drive paper scene)", "energy-balanced-3cart.yaml", {}, false},
      {"2 carts on opposite sides, elastic coupling c = 2e5, k = 8000", "recuperative-2cart.yaml",
       {"coupling.type=elastic", "coupling.stiffness=200000", "coupling.damping=8000"}, false},
      {"4 carts on alternate sides, Δφ = 90°, elastic coupling", "balanced-4cart.yaml", {"carts.sides=alternate"}, false},
  };
}

}  // namespace

void Suite::equivalence(ValidationResults& r) {
  equivalenceE0(r);
  const std::vector<EquivalenceSpec> specs = equivalenceSpecs();
  if (equivalenceCases(r, specs)) convergence(r, specs);
}

// E0: the README's command, `rollerdyn compare model/balanced-4cart.yaml --set rods.model=split
// --set loads.guide_friction.coefficient=0 --set simulation.accuracy=1e-9`, over 20 revolutions.
void Suite::equivalenceE0(ValidationResults& r) {
  ModelComparison c;
  ComparisonCase cc =
      compareCase("E0", "4 carts, one side, Δφ = 90°, elastic coupling (Loveikin, Pochka, Romasevych (2018) scene), accuracy 1e-9",
                  "balanced-4cart.yaml",
                  {"rods.model=split", "loads.guide_friction.coefficient=0", "simulation.accuracy=1e-9"}, revolutions(), &c);
  r.equivalence_example = c.table;
  r.equivalence.push_back(cc);
}

// E1-E7 (--quick: E4 only); false when interrupted.
bool Suite::equivalenceCases(ValidationResults& r, const std::vector<EquivalenceSpec>& specs) {
  int k = 0;
  for (const EquivalenceSpec& s : specs) {
    ++k;
    if (o_.quick && !s.quick) continue;
    if (interrupted()) return false;
    ComparisonCase cc = compareCase("E" + std::to_string(k), s.description, s.file,
                                    concat(concat(kEquivalentPhysics, s.sets), {"simulation.accuracy=1e-11"}),
                                    revolutions(), nullptr);
    if (!cc.motion_equivalent && cc.complete)
      throw std::logic_error("validation: equivalence case " + cc.label + " is not motion-equivalent");
    r.equivalence.push_back(cc);
  }
  return true;
}

// Convergence: the same comparison at other accuracies. A modelling difference would stay put
// as the accuracy tightens; integration error falls with it.
void Suite::convergence(ValidationResults& r, const std::vector<EquivalenceSpec>& specs) {
  const std::vector<double> accs = o_.quick ? std::vector<double>{1e-9} : std::vector<double>{1e-8, 1e-9, 1e-10};
  for (int e : {4, 3}) {
    if (o_.quick && e != 4) continue;
    const EquivalenceSpec& s = specs[e - 1];
    for (double acc : accs) {
      if (interrupted()) return;
      char a[48];
      std::snprintf(a, sizeof a, "simulation.accuracy=%g", acc);
      r.convergence.push_back(compareCase("E" + std::to_string(e), s.description, s.file,
                                          concat(concat(kEquivalentPhysics, s.sets), {a}), revolutions(), nullptr));
    }
    for (const auto& c : r.equivalence)
      if (c.label == "E" + std::to_string(e)) r.convergence.push_back(c);
  }
  std::sort(r.convergence.begin(), r.convergence.end(), [](const ComparisonCase& a, const ComparisonCase& b) {
    return a.label != b.label ? a.label > b.label : a.accuracy > b.accuracy;
  });
}

void Suite::analytic(ValidationResults& r) {
  // Dyomin (two rotors) gives no numbers: the Loveikin, Pochka, Romasevych (2018) drive as two rotors (ASSUMED, loveikin2018Drive()).
  AnalyticResults& a = r.analytic;
  const TwoRotorParameters p = loveikin2018Drive();
  a.accuracy = 1e-10;
  a.forced = p;
  a.resonant = p;
  a.resonant.omega = naturalFrequency(p) / 3.0;  // third harmonic at p0: the paper's warning
  a.closed_forced = closedFormResponse(a.forced);
  a.closed_resonant = closedFormResponse(a.resonant);
  a.mean_twist_expected = meanTwist(p);
  // Transients decay as e^{-δ1·t}; δ1 = 23.6 1/s here, so 2 s leaves e^{-47}.
  const double settle = 2.0;
  log("Dyomin (two rotors): two rotors on the multibody coupling element");
  a.measured_forced = measureForcedResponse(a.forced, settle, 4, 256, a.accuracy);
  a.measured_resonant = measureForcedResponse(a.resonant, settle, 8, 256, a.accuracy);
  a.free_undamped = p;
  a.free_undamped.b = 0.0;
  a.free_damped = p;
  a.free_damped.b = 200.0;
  a.measured_undamped = measureFreeOscillation(a.free_undamped, 0.01, 40, 64, a.accuracy);
  a.measured_damped = measureFreeOscillation(a.free_damped, 0.01, 20, 64, a.accuracy);
}

// Section (3): the papers' sweeps, the sensitivity table, and the findings from both.
void Suite::papersSection(ValidationResults& r) {
  log("(3) papers");
  papers(r);
  if (!interrupted()) sensitivity(r);
  findings(r);
}

ItemContext Suite::itemContext() const {
  ItemContext ctx;
  ctx.model_dir = o_.model_dir;
  ctx.quick = o_.quick;
  ctx.interrupt = o_.interrupt;
  ctx.log_line = o_.log;
  return ctx;
}

ValidationResults Suite::run() {
  ValidationResults r;
  r.quick = o_.quick;
  const std::clock_t c0 = std::clock();
  log("(1) equivalence");
  equivalence(r);
  if (!interrupted()) perCart(r);
  if (!interrupted()) {
    log("(2) where the physics differ");
    differences(r);
  }
  if (!interrupted()) papersSection(r);
  if (!interrupted()) {
    log("(4) analytic, Dyomin (two rotors)");
    analytic(r);
  }
  if (!interrupted()) {
    log("(5) induction motor");
    r.motor = runMotorValidation(o_);
  }
  if (!interrupted()) r.sections = runValidationItems(itemContext(), o_.items);
  r.cpu_seconds = double(std::clock() - c0) / CLOCKS_PER_SEC;
  return r;
}

}  // namespace detail

using namespace detail;

RunMetrics runMetrics(const Scene& scene, const RunResult& run) {
  RunMetrics m;
  m.complete = run.stats.complete;
  m.status = run.stats.status;
  m.cpu_seconds = run.stats.cpu_seconds;
  const SteadyState ss = detectSteadyState(run, scene.simulation.steady_window_revolutions);
  const WindowMetrics w = computeMetrics(run, ss);
  m.steady = ss.reached;
  m.omega_min = w.omega_min;
  m.omega_max = w.omega_max;
  m.omega_mean = w.omega_mean;
  m.omega_midrange = w.omega_midrange;
  m.delta = w.coefficients.delta;
  m.eps_abs_max = w.eps_abs_max;
  m.H = w.coefficients.H;
  m.k_p = w.coefficients.k_p;
  m.torque_swing = w.coupling_torque_swing;
  m.twist_swing = w.twist_swing;
  m.twist_rate_swing = w.twist_rate_swing;
  m.twist_accel_swing = w.twist_accel_swing;
  const double sync = scene.motor.omega_sync / scene.reducer.ratio;
  m.rotating = m.complete && ss.revolutions_counted >= 2 && std::isfinite(m.omega_mean) && m.omega_mean > 0.25 * sync;
  return m;
}

ValidationResults runValidation(const ValidationOptions& options) { return Suite(options).run(); }

Table readPublishedTable(const std::string& path) { return readAnnotatedCsvFile(path, "published table"); }

}  // namespace rollerdyn::validation
