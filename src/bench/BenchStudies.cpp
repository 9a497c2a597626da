#include "bench/BenchStudies.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "io/AtomicFile.h"
#include "multibody/IntegratorFactory.h"
#include "report/Gnuplot.h"
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

namespace {

constexpr const char* kMultibody = "multibody";
constexpr const char* kReduced = "reduced";

bool usable(Outcome o) { return o == Outcome::Ok || o == Outcome::Stalled; }
bool stopRequested(const BenchOptions& o) { return o.interrupt && o.interrupt->load(); }

std::string num(double v, int precision = 3) {
  if (!std::isfinite(v)) return "—";
  std::ostringstream os;
  os.precision(precision);
  os << v;
  return os.str();
}

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
  r.error_omega = r.error_coupling = NAN;
  if (ref && usable(r.m.outcome)) {
    r.error_omega = relativeMaxError(r.m.run.timeseries, *ref, "omega_crank");
    r.error_coupling = relativeMaxError(r.m.run.timeseries, *ref, "coupling_torque");
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
  r.error_omega = r.error_coupling = NAN;
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

}  // namespace

std::vector<BenchRow> runIntegratorStudy(const SceneSource& source, const BenchOptions& opt) {
  const Scene scene = benchScene(source.load(), opt);
  const std::vector<double> grid = accuracyGrid(opt.quick);
  std::vector<BenchRow> rows;

  // Multibody reference: RungeKuttaMerson at kReferenceAccuracy (fallbacks RungeKuttaFeldberg,
  // CPodes). Merson rather than the 5th-order Feldberg because at the same accuracy it takes
  // about 3x more, smaller steps, so whatever in the model is not fully under error control
  // (e.g. an O(h) lag, as the guide friction had before it became a state) is resolved best; the
  // reference check in bench.md shows how closely the other integrators agree with it.
  {
    BenchRow ref;
    Table ref_table;
    std::vector<SolverSetting> cands;
    for (const char* n : {"RungeKuttaMerson", "RungeKuttaFeldberg", "CPodes"})
      cands.push_back({kMultibody, n, kReferenceAccuracy, 0});
    const bool have_ref = runReference(scene, cands, opt, ref, ref_table);
    if (have_ref) {
      rows.push_back(ref);
      logRow(opt, rows.back(), rows.size());
    }
    for (const std::string& name : integratorNames()) {
      std::vector<SolverSetting> series;
      for (double a : grid) series.push_back({kMultibody, name, a, 0});
      runSeries(scene, series, have_ref ? &ref : nullptr, have_ref ? &ref_table : nullptr, opt, rows);
    }
  }
  // Reduced: CVODE at kReferenceAccuracy is the reference of both reduced integrators.
  {
    BenchRow ref;
    Table ref_table;
    const bool have_ref =
        runReference(scene, {{kReduced, "cvode", kReferenceAccuracy, 0}}, opt, ref, ref_table);
    if (have_ref) {
      rows.push_back(ref);
      logRow(opt, rows.back(), rows.size());
    }
    std::vector<SolverSetting> series;
    for (double a : grid) series.push_back({kReduced, "cvode", a, 0});
    runSeries(scene, series, have_ref ? &ref : nullptr, have_ref ? &ref_table : nullptr, opt, rows);
    if (scene.coupling.type == CouplingType::Rigid) {
      std::vector<SolverSetting> bar;
      for (double h : baranovSteps(opt.quick)) bar.push_back({kReduced, "baranov", 0, h});
      runSeries(scene, bar, nullptr, have_ref ? &ref_table : nullptr, opt, rows);
    }
  }
  return rows;
}

namespace {

// Runs both models on one scene variant at the scene's own integrator and accuracy.
void runBothModels(const std::string& study, const std::string& variant, double x, const Scene& scene,
                   const BenchOptions& opt, std::vector<BenchRow>& rows) {
  const SolverSetting settings[] = {
      {kMultibody, scene.simulation.integrator, scene.simulation.accuracy, 0},
      {kReduced, "cvode", scene.simulation.accuracy, 0}};
  for (const SolverSetting& s : settings) {
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
                const std::vector<std::string>& extra, const BenchOptions& opt, std::vector<BenchRow>& rows) {
  Scene scene;
  try {
    scene = benchScene(source.load(extra), opt);
  } catch (const std::exception& ex) {
    for (const char* model : {kMultibody, kReduced}) {
      Measurement m;
      m.setting = {model, "", 0, 0};
      m.outcome = Outcome::Failed;
      m.status = std::string("failed: scene rejected: ") + ex.what();
      m.cpu_seconds = m.cpu_min = m.cpu_max = m.real_time_factor = NAN;
      BenchRow r = makeRow(study, variant, x, Scene{}, std::move(m));
      r.error_omega = r.error_coupling = NAN;
      rows.push_back(std::move(r));
      logRow(opt, rows.back(), rows.size());
    }
    return;
  }
  runBothModels(study, variant, x, scene, opt, rows);
}

}  // namespace

std::vector<BenchRow> runCartsStudy(const SceneSource& source, const BenchOptions& opt) {
  const Scene base = source.load();
  std::vector<BenchRow> rows;
  for (int n : {1, 2, 4, 8, 16, 32}) {
    if (stopRequested(opt)) break;
    // The motor grows with the machine (breakdown torque × n / n_scene for n above the scene's
    // count), so an installation with more carts still carries its load instead of stalling
    // and ending the run early, which would make its cost incomparable.
    const double scale = std::max(1.0, double(n) / base.carts.count);
    const std::vector<std::string> extra = {
        "carts.count=" + std::to_string(n), "carts.sides=same",
        "crank.offset_deg=" + setValue(n == 1 ? 0.0 : 360.0 / n),
        "motor.breakdown_torque=" + setValue(base.motor.breakdown_torque * scale)};
    runVariant("carts", "n=" + std::to_string(n), n, source, extra, opt, rows);
  }
  return rows;
}

std::vector<BenchRow> runEffectsStudy(const SceneSource& source, const BenchOptions& opt) {
  const Scene base = source.load();
  struct Variant {
    std::string name;
    double x;
    std::vector<std::string> extra;
  };
  std::vector<Variant> v;
  v.push_back({"baseline", 0, {}});
  const bool elastic = base.coupling.type == CouplingType::Elastic;
  if (elastic) {
    v.push_back({"rigid coupling", 0, {"coupling.type=rigid"}});
    if (base.coupling.damping > 0) v.push_back({"coupling damping off (k = 0)", 0, {"coupling.damping=0"}});
  }
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
    Variant var{std::string("rods ") + toString(rm), 0, {std::string("rods.model=") + toString(rm)}};
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

  std::vector<BenchRow> rows;
  for (const Variant& var : v) {
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
        "us_per_realization\n";
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
       << r.carts << ',' << f(per_cart) << ',' << f(us) << '\n';
  }
  return os.str();
}

namespace {

std::string settingText(const SolverSetting& s) {
  if (s.integrator == "baranov") return "baranov, Δφ = " + num(s.baranov_step * 180.0 / M_PI) + "°";
  return s.integrator + ", accuracy " + num(s.accuracy, 2);
}

std::string timingNote(const BenchOptions& opt) {
  std::ostringstream os;
  os << "CPU times are process CPU seconds of the integration loop (RunStats.cpu_seconds; model "
        "building excluded), "
     << (opt.repeats > 1 ? "median of " + std::to_string(opt.repeats) + " repetitions"
                         : std::string("one run each (use --repeat N for medians)"))
     << ", on a machine that may be shared: treat differences under ~20 % as noise. CPU budget "
     << num(opt.budget) << " s per run.";
  return os.str();
}

const BenchRow* findRow(const std::vector<BenchRow>& rows, const std::string& variant, const std::string& model) {
  for (const BenchRow& r : rows)
    if (r.variant == variant && r.m.setting.model == model) return &r;
  return nullptr;
}

}  // namespace

std::string integratorReport(const Scene& scene, const std::vector<BenchRow>& rows, const BenchOptions& opt) {
  std::ostringstream os;
  const double T = scene.simulation.t_end;
  os << "# Integrator benchmark: " << scene.name << "\n\n"
     << "Simulated time " << num(T) << " s (output step " << num(scene.simulation.output_step)
     << " s)" << (opt.quick ? ", --quick" : "") << ". " << timingNote(opt) << "\n\n"
     << "**Error measure.** For each run, over the output grid it shares with the reference run of the "
        "SAME model: error_omega = max_i |ω_i − ω_ref,i| / max_i |ω_ref,i| (crank speed), "
        "error_coupling = the same for the coupling torque. References: multibody "
     << "RungeKuttaMerson, reduced CVODE, both at accuracy " << num(kReferenceAccuracy, 2)
     << " (Merson rather than the 5th-order Feldberg: at equal accuracy it takes ~3x smaller steps, the "
        "safer reference for anything not fully under error control). Baranov's scheme is compared with "
        "the reduced CVODE reference.\n\n";

  // Reference check: the closest any other run of the same model comes to the reference (an
  // estimate of the reference's own error when that run is an independent integrator).
  for (const char* model : {kMultibody, kReduced}) {
    const BenchRow* ref = nullptr;
    double agree = NAN;
    std::string who;
    for (const BenchRow& r : rows) {
      if (r.m.setting.model != model) continue;
      if (r.reference) ref = &r;
      else if (r.m.outcome == Outcome::Ok && std::isfinite(r.error_omega) && !(agree <= r.error_omega)) {
        agree = r.error_omega;
        who = settingText(r.m.setting);
      }
    }
    if (!ref) {
      os << "- " << model << ": no usable reference run; errors not measured.\n";
      continue;
    }
    os << "- " << model << " reference: " << settingText(ref->m.setting) << ", "
       << num(ref->m.cpu_seconds) << " s CPU, status " << ref->m.status;
    if (std::isfinite(agree))
      os << "; closest other run (" << who << ") differs by " << num(agree, 2)
         << " in ω (when it is another integrator, the reference's own error is of this order or less)";
    os << ".\n";
  }

  os << "\n## Recommended settings (cheapest run that reaches the error)\n\n"
     << "| model | target | criterion | setting | CPU [s] | real-time factor | error ω | error coupling |\n"
     << "|---|---|---|---|---|---|---|---|\n";
  for (const char* model : {kMultibody, kReduced})
    for (double target : {1e-3, 1e-6})
      for (bool both : {false, true}) {
        const BenchRow* r = cheapestReaching(rows, model, target, both);
        os << "| " << model << " | " << num(target, 1) << " | " << (both ? "ω and coupling torque" : "ω") << " | ";
        if (!r) {
          os << "none reached | | | | |\n";
          continue;
        }
        os << settingText(r->m.setting) << " | " << num(r->m.cpu_seconds) << " | "
           << num(r->m.real_time_factor) << " | " << num(r->error_omega, 2) << " | "
           << num(r->error_coupling, 2) << " |\n";
      }

  os << "\n## Performance targets (1e-6 relative crank-speed error)\n\n"
     << "| model | cheapest setting at 1e-6 | real-time factor | target | met |\n|---|---|---|---|---|\n";
  for (const char* model : {kMultibody, kReduced}) {
    const double target = std::string(model) == kMultibody ? kTargetRealTimeMultibody : kTargetRealTimeReduced;
    const BenchRow* r = cheapestReaching(rows, model, 1e-6, false);
    os << "| " << model << " | " << (r ? settingText(r->m.setting) : "none reached") << " | "
       << (r ? num(r->m.real_time_factor) : "—") << " | ≥ " << num(target) << "× | "
       << (r ? (r->m.real_time_factor >= target ? "yes" : "no") : "no") << " |\n";
  }
  os << "\nThe targets are stated for model/balanced-4cart.yaml over 10 s; on other scenes or with "
        "--quick (shorter run, start-up transient only) they are indicative.\n";

  os << "\n## All runs\n\n| model | integrator | accuracy / step | outcome | CPU [s] | steps | RHS evals | "
        "error ω | error coupling | energy residual | constraint error |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const BenchRow& r : rows) {
    const SolverSetting& s = r.m.setting;
    os << "| " << s.model << " | " << s.integrator << (r.reference ? " (ref)" : "") << " | "
       << (s.integrator == "baranov" ? num(s.baranov_step * 180.0 / M_PI) + "°" : num(s.accuracy, 1)) << " | "
       << toString(r.m.outcome) << " | " << num(r.m.cpu_seconds) << " | " << r.m.steps << " | "
       << r.m.realizations << " | " << num(r.error_omega, 2) << " | " << num(r.error_coupling, 2) << " | "
       << num(r.m.energy_residual_rel, 2) << " | " << num(r.m.constraint_error_max, 2) << " |\n";
  }
  os << "\nFigures: work_precision_omega.png/.svg, work_precision_coupling.png/.svg (error vs CPU time, "
        "log-log, one line per integrator). Data: bench.csv.\n";
  return os.str();
}

std::string cartsReport(const Scene& scene, const std::vector<BenchRow>& rows, const BenchOptions& opt) {
  std::ostringstream os;
  os << "# Cost vs number of carts: " << scene.name << "\n\n"
     << "carts.count = n, carts.sides = same, crank.offset_deg = 360/n (0 for n = 1); motor breakdown "
        "torque × n/" << scene.carts.count << " for n > " << scene.carts.count
     << " so the drive carries the load. Each model at the scene's integrator and accuracy ("
     << scene.simulation.integrator << " / cvode, " << num(scene.simulation.accuracy, 2) << "), "
     << num(benchScene(scene, opt).simulation.t_end) << " s simulated. " << timingNote(opt) << "\n\n"
     << "| n | model | outcome | CPU [s] | CPU per cart [s] | steps | RHS evals | µs per RHS eval per cart | "
        "real-time factor |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const BenchRow& r : rows) {
    const Measurement& m = r.m;
    const double us = m.realizations > 0 ? 1e6 * m.cpu_seconds / m.realizations / r.x : NAN;
    os << "| " << r.x << " | " << m.setting.model << " | " << toString(m.outcome) << " | " << num(m.cpu_seconds)
       << " | " << num(m.cpu_seconds / r.x) << " | " << m.steps << " | " << m.realizations << " | " << num(us)
       << " | " << num(m.real_time_factor) << " |\n";
  }
  os << "\n## Per-cart cost at 32 carts relative to 4 carts (target ≤ " << num(kTargetPerCartCostRatio)
     << ")\n\n| model | per run (CPU/n) | per RHS evaluation (CPU/RHS/n) | met (per run) |\n|---|---|---|---|\n";
  for (const char* model : {kMultibody, kReduced}) {
    const BenchRow* a = findRow(rows, "n=4", model);
    const BenchRow* b = findRow(rows, "n=32", model);
    if (!a || !b || !usable(a->m.outcome) || !usable(b->m.outcome)) {
      os << "| " << model << " | — | — | not measured |\n";
      continue;
    }
    const double run_ratio = (b->m.cpu_seconds / 32) / (a->m.cpu_seconds / 4);
    const double rhs_ratio = (b->m.cpu_seconds / b->m.realizations / 32) / (a->m.cpu_seconds / a->m.realizations / 4);
    os << "| " << model << " | " << num(run_ratio) << " | " << num(rhs_ratio) << " | "
       << (run_ratio <= kTargetPerCartCostRatio ? "yes" : "no") << " |\n";
  }
  os << "\nPer run includes any change in the number of steps the dynamics of n carts needs; per RHS "
        "evaluation isolates the cost of evaluating the model. Figure: carts_cost.png/.svg. Data: carts.csv.\n";
  return os.str();
}

std::string effectsReport(const Scene& scene, const std::vector<BenchRow>& rows, const BenchOptions& opt) {
  std::ostringstream os;
  os << "# Cost of each effect: " << scene.name << "\n\n"
     << "Each variant changes one thing of the scene (--set) and runs both models at the scene's "
        "integrator and accuracy ("
     << scene.simulation.integrator << " / cvode, " << num(scene.simulation.accuracy, 2) << "), "
     << num(benchScene(scene, opt).simulation.t_end) << " s simulated. Relative cost = CPU / CPU of the "
        "baseline of the same model. " << timingNote(opt) << "\n\n"
     << "| # | variant | model | outcome | CPU [s] | relative cost | steps | RHS evals | µs per RHS eval |\n"
     << "|---|---|---|---|---|---|---|---|---|\n";
  std::map<std::string, int> index;
  for (const BenchRow& r : rows) {
    if (!index.count(r.variant)) {
      const int k = int(index.size());
      index[r.variant] = k;
    }
    const BenchRow* base = findRow(rows, "baseline", r.m.setting.model);
    const double rel = base && usable(base->m.outcome) ? r.m.cpu_seconds / base->m.cpu_seconds : NAN;
    const double us = r.m.realizations > 0 ? 1e6 * r.m.cpu_seconds / r.m.realizations : NAN;
    os << "| " << index[r.variant] << " | " << r.variant << " | " << r.m.setting.model << " | "
       << toString(r.m.outcome) << (usable(r.m.outcome) ? "" : " (" + r.m.status + ")") << " | "
       << num(r.m.cpu_seconds) << " | " << num(rel) << " | " << r.m.steps << " | " << r.m.realizations << " | "
       << num(us) << " |\n";
  }
  if (!scene.hasGuideFriction() && !(scene.carts.geometry.b > 0))
    os << "\nGuide friction: not applicable (the scene has no guide geometry, carts.geometry.b = 0).\n";
  os << "\nFigures: effects_stiffness.png/.svg (CPU vs coupling stiffness, rigid coupling drawn as a flat "
        "line), effects_relative.png/.svg (relative cost by variant number). Data: effects.csv.\n";
  return os.str();
}

namespace {

PlotSeries series(const std::string& title, const std::string& style) {
  PlotSeries s;
  s.title = title;
  s.style = style;
  return s;
}

// Draws a figure; a missing or failing gnuplot is reported in the returned note, not thrown, so
// the CSV and markdown are still written.
std::string tryPlot(const PlotSpec& spec, const std::string& base, std::vector<std::string>& written) {
  try {
    renderPlot(spec, base);
    written.push_back(base + ".png");
    written.push_back(base + ".svg");
    return "";
  } catch (const std::exception& ex) {
    return std::string("\nFigure not drawn: ") + ex.what() + "\n";
  }
}

}  // namespace

std::vector<std::string> writeIntegratorStudy(const std::string& dir, const Scene& scene,
                                              const std::vector<BenchRow>& rows, const BenchOptions& opt) {
  std::vector<std::string> written;
  writeFileAtomic(dir + "/bench.csv", rowsCsv(rows));
  written.push_back(dir + "/bench.csv");
  std::string notes;
  for (bool coupling : {false, true}) {
    PlotSpec spec;
    spec.title = scene.name + ": work-precision, " + (coupling ? "coupling torque" : "crank speed");
    spec.xlabel = "CPU time [s]";
    spec.ylabel = coupling ? "max |M_{c} - M_{c,ref}| / max |M_{c,ref}| [-]" : "max |ω - ω_{ref}| / max |ω_{ref}| [-]";
    spec.logx = spec.logy = true;
    std::map<std::string, size_t> line_of;
    for (const BenchRow& r : rows) {
      const double e = coupling ? r.error_coupling : r.error_omega;
      if (r.reference || !usable(r.m.outcome) || !std::isfinite(e)) continue;
      const std::string title = r.m.setting.model + " " + r.m.setting.integrator;
      if (!line_of.count(title)) {
        line_of[title] = spec.series.size();
        spec.series.push_back(series(title, "linespoints"));
      }
      PlotSeries& s = spec.series[line_of[title]];
      s.x.push_back(r.m.cpu_seconds);
      s.y.push_back(e);
    }
    notes += tryPlot(spec, dir + (coupling ? "/work_precision_coupling" : "/work_precision_omega"), written);
  }
  writeFileAtomic(dir + "/bench.md", integratorReport(scene, rows, opt) + notes);
  written.push_back(dir + "/bench.md");
  return written;
}

std::vector<std::string> writeCartsStudy(const std::string& dir, const Scene& scene,
                                         const std::vector<BenchRow>& rows, const BenchOptions& opt) {
  std::vector<std::string> written;
  writeFileAtomic(dir + "/carts.csv", rowsCsv(rows));
  written.push_back(dir + "/carts.csv");
  PlotSpec spec;
  spec.title = scene.name + ": CPU time per cart vs number of carts";
  spec.xlabel = "carts n [-]";
  spec.ylabel = "CPU time / n [s]";
  spec.logx = spec.logy = true;
  for (const char* model : {kMultibody, kReduced}) {
    PlotSeries s = series(std::string(model) + " (per run)", "linespoints");
    PlotSeries e = series(std::string(model) + " (per RHS evaluation × 1000)", "linespoints");
    for (const BenchRow& r : rows)
      if (r.m.setting.model == model && usable(r.m.outcome)) {
        s.x.push_back(r.x);
        s.y.push_back(r.m.cpu_seconds / r.x);
        if (r.m.realizations > 0) {
          e.x.push_back(r.x);
          e.y.push_back(1000.0 * r.m.cpu_seconds / r.m.realizations / r.x);
        }
      }
    spec.series.push_back(s);
    spec.series.push_back(e);
  }
  const std::string notes = tryPlot(spec, dir + "/carts_cost", written);
  writeFileAtomic(dir + "/carts.md", cartsReport(scene, rows, opt) + notes);
  written.push_back(dir + "/carts.md");
  return written;
}

std::vector<std::string> writeEffectsStudy(const std::string& dir, const Scene& scene,
                                           const std::vector<BenchRow>& rows, const BenchOptions& opt) {
  std::vector<std::string> written;
  writeFileAtomic(dir + "/effects.csv", rowsCsv(rows));
  written.push_back(dir + "/effects.csv");
  std::string notes;
  {
    PlotSpec spec;
    spec.title = scene.name + ": CPU time vs coupling stiffness";
    spec.xlabel = "coupling stiffness c [N·m/rad]";
    spec.ylabel = "CPU time [s]";
    spec.logx = spec.logy = true;
    for (const char* model : {kMultibody, kReduced}) {
      PlotSeries s = series(std::string(model) + " elastic", "linespoints");
      for (const BenchRow& r : rows)
        if (r.m.setting.model == model && r.x > 0 && usable(r.m.outcome)) {
          s.x.push_back(r.x);
          s.y.push_back(r.m.cpu_seconds);
        }
      spec.series.push_back(s);
      const BenchRow* rigid = findRow(rows, "rigid coupling", model);
      if (!rigid && scene.coupling.type == CouplingType::Rigid) rigid = findRow(rows, "baseline", model);
      if (rigid && usable(rigid->m.outcome) && !s.x.empty()) {
        const auto [lo, hi] = std::minmax_element(s.x.begin(), s.x.end());
        PlotSeries r = series(std::string(model) + " rigid", "lines");
        r.x = {*lo, *hi};
        r.y = {rigid->m.cpu_seconds, rigid->m.cpu_seconds};
        spec.series.push_back(r);
      }
    }
    notes += tryPlot(spec, dir + "/effects_stiffness", written);
  }
  {
    PlotSpec spec;
    spec.title = scene.name + ": relative cost of each variant (numbers as in effects.md)";
    spec.xlabel = "variant # [-]";
    spec.ylabel = "CPU time / baseline CPU time [-]";
    spec.logy = true;
    for (const char* model : {kMultibody, kReduced}) {
      PlotSeries s = series(model, "points");
      const BenchRow* base = findRow(rows, "baseline", model);
      std::map<std::string, int> index;
      for (const BenchRow& r : rows) {
        if (!index.count(r.variant)) {
          const int k = int(index.size());
          index[r.variant] = k;
        }
        if (r.m.setting.model == model && usable(r.m.outcome) && base && usable(base->m.outcome)) {
          s.x.push_back(index[r.variant]);
          s.y.push_back(r.m.cpu_seconds / base->m.cpu_seconds);
        }
      }
      spec.series.push_back(s);
    }
    notes += tryPlot(spec, dir + "/effects_relative", written);
  }
  writeFileAtomic(dir + "/effects.md", effectsReport(scene, rows, opt) + notes);
  written.push_back(dir + "/effects.md");
  return written;
}

}  // namespace rollerdyn::bench
