#include "bench/BenchStudies.h"
#include "bench/BenchText.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "io/AtomicFile.h"
#include "multibody/IntegratorFactory.h"
#include "scene/SceneParser.h"
#include "scene/SceneSchema.h"

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

namespace {

bool stopRequested(const BenchOptions& o) { return o.interrupt && o.interrupt->load(); }

// A value for --set that round-trips exactly.
std::string setValue(double v) {
  std::ostringstream os;
  os.precision(17);
  os << v;
  return os.str();
}

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

namespace {

// Runs both models on one scene variant at the scene's own integrator and accuracy (the
// constrained formulation only while `constrained` is true).
void runBothModels(const std::string& study, const std::string& variant, double x, const Scene& scene,
                   const BenchOptions& opt, std::vector<BenchRow>& rows, bool constrained = true) {
  const SolverSetting settings[] = {
      {kMultibody, scene.simulation.integrator, scene.simulation.accuracy, 0},
      {kMinimal, kMinimalIntegrator, scene.simulation.accuracy, 0},
      {kReduced, "cvode", scene.simulation.accuracy, 0}};
  for (const SolverSetting& s : settings) {
    if (!constrained && s.model == kMultibody) continue;
    if (stopRequested(opt)) return;
    Budget b{opt.budget, opt.interrupt};
    BenchRow r = makeRow(study, variant, x, scene, measure(scene, s, b, opt.repeats));
    finishRow(r, nullptr);
    rows.push_back(std::move(r));
    logRow(opt, rows.back(), rows.size());
  }
}

// A variant whose scene does not parse becomes a failed row for each model.
void runVariant(const std::string& study, const std::string& variant, double x, const SceneSource& source,
                const std::vector<std::string>& extra, const BenchOptions& opt, std::vector<BenchRow>& rows,
                bool constrained = true) {
  Scene scene;
  try {
    scene = benchScene(source.load(extra), opt);
  } catch (const std::exception& ex) {
    for (const char* model : {kMultibody, kMinimal, kReduced}) {
      Measurement m;
      m.setting = {model, "", 0, 0};
      m.outcome = Outcome::Failed;
      m.status = std::string("failed: scene rejected: ") + ex.what();
      m.cpu_seconds = m.cpu_min = m.cpu_max = m.real_time_factor = NAN;
      BenchRow r = makeRow(study, variant, x, Scene{}, std::move(m));
      r.error_omega = r.error_coupling = r.error_angle = NAN;
      rows.push_back(std::move(r));
      logRow(opt, rows.back(), rows.size());
    }
    return;
  }
  runBothModels(study, variant, x, scene, opt, rows, constrained);
}

}  // namespace

std::vector<BenchRow> runMotorsStudy(const SceneSource& source, const BenchOptions& opt) {
  std::vector<BenchRow> rows;
  for (const std::string& model : findSceneKey("motor.model")->choices) {  // every motor law
    if (stopRequested(opt)) break;
    runVariant("motors", "motor.model " + model, 0, source, {"motor.model=" + model}, opt, rows);
  }
  return rows;
}

std::vector<BenchRow> runCartsStudy(const SceneSource& source, const BenchOptions& opt) {
  const Scene base = source.load();
  std::vector<BenchRow> rows;
  // The constrained formulation's evaluation is O(n²) (Simbody's G·M⁻¹·Gᵀ): 32 carts take
  // ~40 s at 1e-6, 64 would take minutes, so it stops at 32.
  const std::vector<int> counts = opt.quick ? std::vector<int>{1, 2, 4, 8} : std::vector<int>{1, 2, 4, 8, 16, 32, 64, 256};
  for (int n : counts) {
    if (stopRequested(opt)) break;
    // The motor grows with the machine (breakdown torque × n / n_scene for n above the scene's
    // count), so an installation with more carts still carries its load instead of stalling
    // and ending the run early, which would make its cost incomparable.
    const double scale = std::max(1.0, double(n) / base.carts.count);
    const std::vector<std::string> extra = {
        "carts.count=" + std::to_string(n), "carts.sides=same",
        "crank.offset_deg=" + setValue(n == 1 ? 0.0 : 360.0 / n),
        "motor.breakdown_torque=" + setValue(base.motor.breakdown_torque * scale)};
    runVariant("carts", "n=" + std::to_string(n), n, source, extra, opt, rows, n <= 32);
  }
  return rows;
}

namespace {

// One run of the effects table: its name, its x value (the coupling stiffness, else 0) and the
// scene values it sets.
struct EffectVariant {
  std::string name;
  double x;
  std::vector<std::string> extra;
};

// The drive's own parts switched or changed one at a time: coupling, reducer, main bearings and
// the crankshaft.
void driveVariants(const Scene& base, std::vector<EffectVariant>& v) {
  const bool elastic = base.coupling.type == CouplingType::Elastic;
  if (elastic) {
    v.push_back({"rigid coupling", 0, {"coupling.type=rigid"}});
    if (base.coupling.damping > 0) v.push_back({"coupling damping off (k = 0)", 0, {"coupling.damping=0"}});
    // The reducer's backlash: its contacts' cost in steps (docs/models.md, backlash of the reducer).
    if (base.hasBacklash())
      v.push_back({"reducer backlash off", 0, {"reducer.backlash=0"}});
    else
      v.push_back({"reducer backlash 0.1° (0.0017453 rad)", 0, {"reducer.backlash=0.0017453"}});
  }
  // The reducer's losses by the direction of the power flow (docs/models.md): the blend's cost.
  if (base.motor.enabled) {
    if (base.reducer.losses == ReducerLossModel::Papers)
      v.push_back({"reducer losses by power flow (η_r = η)", 0, {"reducer.losses=power_flow"}});
    else
      v.push_back({"reducer losses as the papers (constant η)", 0, {"reducer.losses=papers"}});
  }
  // Main bearings along the crankshaft: beam statics on the output rows, after the integration
  // (its cost is in the whole process, not in the loop this table times).
  if (base.crankshaft.throw_positions.empty() && base.simulation.reactions) {
    std::ostringstream throws, bearings;
    const int n = base.carts.count;
    for (int j = 0; j < n; ++j) throws << (j ? ", " : "") << 0.2 + 0.3 * j;
    for (int j = 0; j <= n; ++j) bearings << (j ? ", " : "") << (j == 0 ? 0.0 : 0.35 + 0.3 * (j - 1));
    v.push_back({"main bearings along the crankshaft (" + std::to_string(n + 1) + " bearings)", 0,
                 {"crankshaft.throw_positions=[" + throws.str() + "]",
                  "crankshaft.bearing_positions=[" + bearings.str() + "]"}});
  }
  // The crankshaft as a torsional chain (docs/models.md): built by the constrained formulation only,
  // so it is timed beside the same formulation with the rigid shaft; a 100 mm steel shaft, G·I_p =
  // 80 GPa·π·(0.1 m)⁴/32 = 7.85e5 N·m², throws 0.3 m apart.
  if (base.carts.count > 1 && !base.hasCamDrive() && !base.crankshaft.torsionalChain()) {
    std::vector<std::string> constrained = {"simulation.formulation=constrained"};
    if (base.hasGuideFriction()) constrained.push_back("loads.guide_friction.normal_force=lagged");
    v.push_back({"constrained formulation, rigid crankshaft", 0, constrained});
    std::ostringstream throws;
    for (int j = 0; j < base.carts.count; ++j) throws << (j ? ", " : "") << 0.2 + 0.3 * j;
    std::vector<std::string> chain = constrained;
    chain.push_back("crankshaft.throw_positions=[" + throws.str() + "]");
    chain.push_back("crankshaft.torsional_stiffness=7.85e5");
    v.push_back({"constrained formulation, crankshaft as a torsional chain (G·I_p = 7.85e5 N·m²)", 0, chain});
  }
}

// The model's choices one at a time: coupling stiffness, guide friction, rod model and gravity.
void modelVariants(const Scene& base, std::vector<EffectVariant>& v) {
  const bool elastic = base.coupling.type == CouplingType::Elastic;
  for (double c : {2e5, 1e6, 1e7, 1e8, 1e9}) {
    std::ostringstream name;
    name << "elastic coupling c = " << c << " N·m/rad" << (elastic ? "" : " (k = 0)");
    v.push_back({name.str(), c, {"coupling.type=elastic", "coupling.stiffness=" + setValue(c)}});
  }
  if (base.hasGuideFriction())
    v.push_back({"guide friction off", 0, {"loads.guide_friction.coefficient=0"}});
  else if (base.carts.geometry.b > 0)
    v.push_back({"guide friction on (f = 0.008)", 0, {"loads.guide_friction.coefficient=0.008"}});
  for (RodModel rm : {RodModel::Distributed, RodModel::Split, RodModel::Massless}) {
    if (rm == base.rods.model) continue;
    EffectVariant var{std::string("rods ") + toString(rm), 0, {std::string("rods.model=") + toString(rm)}};
    // Without rod masses and without any crankshaft inertia the multibody model refuses an
    // elastic drive (the crank's motion would be undetermined): give the shaft 1 kg·m².
    if (rm == RodModel::Massless && base.crankSideInertia() <= 0.0) {
      var.name += " (+ crank.shaft_inertia = 1 kg·m²)";
      var.extra.push_back("crank.shaft_inertia=1");
    }
    v.push_back(var);
  }
  if (base.hasGravity())
    v.push_back({"gravity off", 0, {"loads.gravity=0"}});
  else
    v.push_back({"gravity on (9.81 m/s²)", 0, {"loads.gravity=9.81"}});
}

}  // namespace

std::vector<BenchRow> runEffectsStudy(const SceneSource& source, const BenchOptions& opt) {
  const Scene base = source.load();
  std::vector<EffectVariant> v;
  v.push_back({"baseline", 0, {}});
  driveVariants(base, v);
  modelVariants(base, v);

  std::vector<BenchRow> rows;
  for (const EffectVariant& var : v) {
    if (stopRequested(opt)) break;
    runVariant("effects", var.name, var.x, source, var.extra, opt, rows);
  }
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

std::string rowsCsv(const std::vector<BenchRow>& rows) {
  auto f = [](double v) -> std::string {
    if (!std::isfinite(v)) return "";
    std::ostringstream os;
    os.precision(6);
    os << v;
    return os.str();
  };
  auto q = [](const std::string& s) {
    std::string o = "\"";
    for (char c : s) o += (c == '"') ? std::string("\"\"") : std::string(1, c);
    return o + "\"";
  };
  std::ostringstream os;
  os << "study,variant,x,model,integrator,accuracy,baranov_step_deg,reference,outcome,status,repeats,"
        "cpu_seconds,cpu_seconds_min,cpu_seconds_max,steps,realizations,simulated_time,real_time_factor,"
        "error_omega,error_coupling,energy_residual_rel,constraint_error_max,carts,cpu_per_cart,"
        "us_per_realization,error_angle_rad,cpu_with_setup\n";
  for (const BenchRow& r : rows) {
    const Measurement& m = r.m;
    const bool bar = m.setting.integrator == "baranov";
    const double per_cart = r.carts > 0 ? m.cpu_seconds / r.carts : NAN;
    const double us = m.realizations > 0 ? 1e6 * m.cpu_seconds / m.realizations : NAN;
    os << r.study << ',' << q(r.variant) << ',' << f(r.x) << ',' << m.setting.model << ','
       << m.setting.integrator << ',' << (bar ? "" : f(m.setting.accuracy)) << ','
       << (bar ? f(m.setting.baranov_step * 180.0 / M_PI) : "") << ',' << (r.reference ? 1 : 0) << ','
       << toString(m.outcome) << ',' << q(m.status) << ',' << m.repeats << ',' << f(m.cpu_seconds) << ','
       << f(m.cpu_min) << ',' << f(m.cpu_max) << ',' << m.steps << ',' << m.realizations << ','
       << f(m.simulated_time) << ',' << f(m.real_time_factor) << ',' << f(r.error_omega) << ','
       << f(r.error_coupling) << ',' << f(m.energy_residual_rel) << ',' << f(m.constraint_error_max) << ','
       << r.carts << ',' << f(per_cart) << ',' << f(us) << ',' << f(r.error_angle) << ',' << f(m.cpu_with_setup)
       << '\n';
  }
  return os.str();
}

}  // namespace rollerdyn::bench
