#include "bench/BenchStudies.h"
#include "bench/BenchRows.h"
#include "bench/BenchText.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "io/AtomicFile.h"
#include "multibody/IntegratorFactory.h"
#include "scene/SceneParser.h"

namespace rollerdyn::bench {

Scene SceneSource::load(const std::vector<std::string>& extra) const {
  std::vector<std::string> all = overrides;
  all.insert(all.end(), extra.begin(), extra.end());
  return parseSceneFile(path, all);
}

std::vector<double> accuracyGrid(bool quick) {
  if (quick) return {1e-2, 1e-4, 1e-6, 1e-8};
  // Two points per decade (1 and 3): error is not a smooth function of the accuracy setting
  // near a target (balanced-4cart: Merson at 1e-4 gives 6e-7 in ω, at 2e-4 1.3e-6; the reduced
  // CVODE at 1e-7 1.5e-6, at 3e-8 6e-7), so decades alone can miss the cheapest setting that
  // reaches 1e-6 by a factor of ~2 in CPU time.
  std::vector<double> g;
  for (int e = -2; e >= -10; --e) {
    g.push_back(std::pow(10.0, e));
    if (e > -10) g.push_back(0.3 * std::pow(10.0, e));
  }
  return g;
}

std::vector<double> baranovSteps(bool quick) {
  const double deg = M_PI / 180.0;
  if (quick) return {4 * deg, 1 * deg, 0.25 * deg};
  std::vector<double> s;
  for (double d = 8.0; d >= 1.0 / 32.0 - 1e-12; d /= 2) s.push_back(d * deg);
  return s;
}

Scene benchScene(const Scene& scene, const BenchOptions& options) {
  Scene s = scene;
  if (options.quick) s.simulation.t_end = std::min(s.simulation.t_end, options.quick_t_end);
  return s;
}

bool stopRequested(const BenchOptions& o) { return o.interrupt && o.interrupt->load(); }

void logRow(const BenchOptions& opt, const BenchRow& r, size_t index) {
  if (!opt.log) return;
  std::ostringstream os;
  os << "[" << r.study << " " << index << "] " << (r.variant.empty() ? "" : r.variant + ": ")
     << r.m.setting.label() << (r.reference ? " (reference)" : "") << ": " << toString(r.m.outcome)
     << ", " << num(r.m.cpu_seconds) << " s CPU";
  if (r.m.repeats > 1) os << " (median of " << r.m.repeats << ")";
  if (std::isfinite(r.error_omega)) os << ", error omega " << num(r.error_omega) << ", coupling " << num(r.error_coupling);
  if (!usable(r.m.outcome)) os << " — " << r.m.status;
  opt.log(os.str());
}

// Fills the errors against `ref` (a usable reference timeseries, or nullptr) and drops the
// row's tables.
void finishRow(BenchRow& r, const Table* ref) {
  r.error_omega = r.error_coupling = r.error_angle = NAN;
  if (ref && usable(r.m.outcome)) {
    r.error_omega = relativeMaxError(r.m.run.timeseries, *ref, "omega_crank");
    r.error_coupling = relativeMaxError(r.m.run.timeseries, *ref, "coupling_torque");
    r.error_angle = absoluteMaxError(r.m.run.timeseries, *ref, "phi_crank");
  }
  r.m.run.timeseries = Table{};
  r.m.run.reactions = Table{};
}

BenchRow makeRow(const std::string& study, const std::string& variant, double x, const Scene& scene,
                 Measurement m) {
  BenchRow r;
  r.study = study;
  r.variant = variant;
  r.x = x;
  r.carts = scene.carts.count;
  r.m = std::move(m);
  return r;
}

namespace {

// A row for a setting that was not run because a looser setting of the same integrator
// already exceeded the budget.
BenchRow skippedRow(const std::string& study, const Scene& scene, const SolverSetting& s,
                    const std::string& why) {
  Measurement m;
  m.setting = s;
  m.outcome = Outcome::Timeout;
  m.status = why;
  m.cpu_seconds = m.cpu_min = m.cpu_max = NAN;
  m.real_time_factor = m.energy_residual_rel = m.constraint_error_max = NAN;
  BenchRow r = makeRow(study, "", 0, scene, std::move(m));
  r.error_omega = r.error_coupling = r.error_angle = NAN;
  return r;
}

// Runs one integrator over its settings, loosest first; once it times out, the rest are
// recorded as not run. `reference` (if usable) is reused for its own setting.
void runSeries(const Scene& scene, const std::vector<SolverSetting>& settings, const BenchRow* reference,
               const Table* ref_table, const BenchOptions& opt, std::vector<BenchRow>& rows) {
  std::string skip_reason;
  for (const SolverSetting& s : settings) {
    if (stopRequested(opt)) return;
    if (reference && s.integrator == reference->m.setting.integrator &&
        s.accuracy == reference->m.setting.accuracy && s.baranov_step == reference->m.setting.baranov_step) {
      continue;  // the reference row is already in the table
    }
    if (!skip_reason.empty()) {
      rows.push_back(skippedRow("integrators", scene, s, skip_reason));
      logRow(opt, rows.back(), rows.size());
      continue;
    }
    Budget b{opt.budget, opt.interrupt};
    BenchRow r = makeRow("integrators", "", 0, scene, measure(scene, s, b, opt.repeats));
    finishRow(r, ref_table);
    if (r.m.outcome == Outcome::Timeout)
      skip_reason = "timeout (not run: " + s.label() + " already exceeded the CPU budget)";
    rows.push_back(std::move(r));
    logRow(opt, rows.back(), rows.size());
  }
}

// The reference of one model: the first candidate setting whose run is usable.
bool runReference(const Scene& scene, const std::vector<SolverSetting>& candidates, const BenchOptions& opt,
                  BenchRow& ref, Table& ref_table) {
  for (const SolverSetting& s : candidates) {
    if (stopRequested(opt)) return false;
    Budget b{opt.budget * opt.reference_budget_factor, opt.interrupt};
    ref = makeRow("integrators", "", 0, scene, measure(scene, s, b, opt.repeats));
    ref.reference = true;
    if (usable(ref.m.outcome)) {
      ref_table = ref.m.run.timeseries;
      finishRow(ref, &ref_table);
      return true;
    }
    if (opt.log) opt.log("reference candidate " + s.label() + " unusable: " + ref.m.status);
  }
  return false;
}

// A model's reference run: the other runs of the model get their errors against its table.
struct ModelReference {
  bool found = false;
  BenchRow row;
  Table table;
  const BenchRow* rowIfFound() const { return found ? &row : nullptr; }
  const Table* tableIfFound() const { return found ? &table : nullptr; }
};

// Runs the model's reference (the first usable candidate) and, when found, adds it to the rows.
ModelReference referenceRun(const Scene& scene, const std::vector<SolverSetting>& candidates, const BenchOptions& opt,
                            std::vector<BenchRow>& rows) {
  ModelReference ref;
  ref.found = runReference(scene, candidates, opt, ref.row, ref.table);
  if (ref.found) {
    rows.push_back(ref.row);
    logRow(opt, rows.back(), rows.size());
  }
  return ref;
}

// One integrator of one model at every accuracy of the grid, loosest first.
std::vector<SolverSetting> accuracySeries(const std::string& model, const std::string& integrator,
                                          const std::vector<double>& grid) {
  std::vector<SolverSetting> series;
  for (double a : grid) series.push_back({model, integrator, a, 0});
  return series;
}

// Multibody reference: RungeKuttaMerson at kReferenceAccuracy (fallbacks RungeKuttaFeldberg,
// CPodes). Merson rather than the 5th-order Feldberg because at the same accuracy it takes
// about 3x more, smaller steps, so whatever in the model is not fully under error control
// (e.g. an O(h) lag, as the guide friction had before it became a state) is resolved best; the
// reference check in bench.md shows how closely the other integrators agree with it.
void runMultibodyIntegrators(const Scene& scene, const std::vector<double>& grid, const BenchOptions& opt,
                             std::vector<BenchRow>& rows) {
  std::vector<SolverSetting> cands;
  for (const char* n : {"RungeKuttaMerson", "RungeKuttaFeldberg", "CPodes"})
    cands.push_back({kMultibody, n, kReferenceAccuracy, 0});
  const ModelReference ref = referenceRun(scene, cands, opt, rows);
  for (const std::string& name : integratorNames())
    runSeries(scene, accuracySeries(kMultibody, name, grid), ref.rowIfFound(), ref.tableIfFound(), opt, rows);
}

// The minimal formulation of the same multibody model against its own reference at
// kReferenceAccuracy: it runs the scene's guide-friction law, which the constrained
// formulation cannot when it is the algebraic one (GuideFriction.h).
void runMinimalFormulation(const Scene& scene, const std::vector<double>& grid, const BenchOptions& opt,
                           std::vector<BenchRow>& rows) {
  const ModelReference ref =
      referenceRun(scene, {{kMinimal, kMinimalIntegrator, kReferenceAccuracy, 0}}, opt, rows);
  runSeries(scene, accuracySeries(kMinimal, kMinimalIntegrator, grid), ref.rowIfFound(), ref.tableIfFound(), opt,
            rows);
}

// Reduced: CVODE at kReferenceAccuracy is the reference of both reduced integrators (Baranov's
// scheme on a rigid drive, at its crank-angle steps).
void runReducedIntegrators(const Scene& scene, const std::vector<double>& grid, const BenchOptions& opt,
                           std::vector<BenchRow>& rows) {
  const ModelReference ref = referenceRun(scene, {{kReduced, "cvode", kReferenceAccuracy, 0}}, opt, rows);
  runSeries(scene, accuracySeries(kReduced, "cvode", grid), ref.rowIfFound(), ref.tableIfFound(), opt, rows);
  if (scene.coupling.type == CouplingType::Rigid) {
    std::vector<SolverSetting> bar;
    for (double h : baranovSteps(opt.quick)) bar.push_back({kReduced, "baranov", 0, h});
    runSeries(scene, bar, nullptr, ref.tableIfFound(), opt, rows);
  }
}

}  // namespace

std::vector<BenchRow> runIntegratorStudy(const SceneSource& source, const BenchOptions& opt) {
  const Scene scene = benchScene(source.load(), opt);
  const std::vector<double> grid = accuracyGrid(opt.quick);
  std::vector<BenchRow> rows;
  runMultibodyIntegrators(scene, grid, opt, rows);
  runMinimalFormulation(scene, grid, opt, rows);
  runReducedIntegrators(scene, grid, opt, rows);
  return rows;
}

const BenchRow* cheapestReaching(const std::vector<BenchRow>& rows, const std::string& model, double target,
                                 bool with_coupling) {
  const BenchRow* best = nullptr;
  for (const BenchRow& r : rows) {
    if (r.reference || r.m.setting.model != model || r.m.outcome != Outcome::Ok) continue;
    const double e = with_coupling ? std::max(r.error_omega, r.error_coupling) : r.error_omega;
    if (!(e <= target) || !std::isfinite(r.m.cpu_seconds)) continue;
    if (!best || r.m.cpu_seconds < best->m.cpu_seconds) best = &r;
  }
  return best;
}

const BenchRow* cheapestReachingAngle(const std::vector<BenchRow>& rows, const std::string& model, double target) {
  const BenchRow* best = nullptr;
  for (const BenchRow& r : rows) {
    if (r.reference || r.m.setting.model != model || r.m.outcome != Outcome::Ok) continue;
    if (!(r.error_angle <= target) || !std::isfinite(r.m.cpu_seconds)) continue;
    if (!best || r.m.cpu_seconds < best->m.cpu_seconds) best = &r;
  }
  return best;
}

namespace {

// A number of the CSV (6 digits), empty when not finite.
std::string csvNumber(double v) {
  if (!std::isfinite(v)) return "";
  std::ostringstream os;
  os.precision(6);
  os << v;
  return os.str();
}

// A text field of the CSV, quoted, its quotes doubled.
std::string csvQuoted(const std::string& s) {
  std::string o = "\"";
  for (char c : s) o += (c == '"') ? std::string("\"\"") : std::string(1, c);
  return o + "\"";
}

std::string rowCsv(const BenchRow& r) {
  const auto f = csvNumber;
  const auto q = csvQuoted;
  const Measurement& m = r.m;
  const bool bar = m.setting.integrator == "baranov";
  const double per_cart = r.carts > 0 ? m.cpu_seconds / r.carts : NAN;
  const double us = m.realizations > 0 ? 1e6 * m.cpu_seconds / m.realizations : NAN;
  std::ostringstream os;
  os << r.study << ',' << q(r.variant) << ',' << f(r.x) << ',' << m.setting.model << ','
     << m.setting.integrator << ',' << (bar ? "" : f(m.setting.accuracy)) << ','
     << (bar ? f(m.setting.baranov_step * 180.0 / M_PI) : "") << ',' << (r.reference ? 1 : 0) << ','
     << toString(m.outcome) << ',' << q(m.status) << ',' << m.repeats << ',' << f(m.cpu_seconds) << ','
     << f(m.cpu_min) << ',' << f(m.cpu_max) << ',' << m.steps << ',' << m.realizations << ','
     << f(m.simulated_time) << ',' << f(m.real_time_factor) << ',' << f(r.error_omega) << ','
     << f(r.error_coupling) << ',' << f(m.energy_residual_rel) << ',' << f(m.constraint_error_max) << ','
     << r.carts << ',' << f(per_cart) << ',' << f(us) << ',' << f(r.error_angle) << ',' << f(m.cpu_with_setup)
     << '\n';
  return os.str();
}

}  // namespace

std::string rowsCsv(const std::vector<BenchRow>& rows) {
  std::ostringstream os;
  os << "study,variant,x,model,integrator,accuracy,baranov_step_deg,reference,outcome,status,repeats,"
        "cpu_seconds,cpu_seconds_min,cpu_seconds_max,steps,realizations,simulated_time,real_time_factor,"
        "error_omega,error_coupling,energy_residual_rel,constraint_error_max,carts,cpu_per_cart,"
        "us_per_realization,error_angle_rad,cpu_with_setup\n";
  for (const BenchRow& r : rows) os << rowCsv(r);
  return os.str();
}

}  // namespace rollerdyn::bench
