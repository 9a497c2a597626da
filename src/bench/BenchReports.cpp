// The reports of `rollerdyn bench` (BenchStudies.h): bench.md, carts.md, effects.md and
// motors.md, from the rows the studies measured (their files and figures: BenchWriters.cpp).
#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "bench/BenchStudies.h"
#include "bench/BenchText.h"
#include "io/AtomicFile.h"
#include "report/Gnuplot.h"

namespace rollerdyn::bench {

namespace {

std::string settingText(const SolverSetting& s) {
  if (s.integrator == "baranov") return "baranov, Δφ = " + num(s.baranov_step * 180.0 / M_PI) + "°";
  return s.integrator + ", accuracy " + num(s.accuracy, 2);
}

std::string timingNote(const Scene& scene, const BenchOptions& opt) {
  std::ostringstream os;
  os << (scene.simulation.reactions
             ? "Every output row includes the joint reactions (the multibody model's minimal formulation takes "
               "them from its O(n) inverse-dynamics pass and checks them against Simbody's constrained solve "
               "every simulation.self_check_interval rows). "
             : "Runs without joint reactions (simulation.reactions: false): the rows hold the motion and the "
               "drive torques only (the minimal formulation still checks its accelerations against Simbody's "
               "constrained solve every simulation.self_check_interval rows). ")
     << "Guide friction: the multibody model's constrained formulation runs the lagged normal-force law (the only "
        "one it can carry), its minimal formulation the scene's ("
     << toString(scene.loads.guide_normal_force) << "), the reduced model " << toString(scene.reduced.guide_normals)
     << " normal forces. "
     << "CPU times are process CPU seconds of the integration loop (RunStats.cpu_seconds; model "
        "building excluded), "
     << (opt.repeats > 1 ? "median of " + std::to_string(opt.repeats) + " repetitions"
                         : std::string("one run each (use --repeat N for medians)"))
     << ", on a machine that may be shared: treat differences under ~20 % as noise. CPU budget "
     << num(opt.budget) << " s per run.";
  return os.str();
}

}  // namespace

const BenchRow* findRow(const std::vector<BenchRow>& rows, const std::string& variant, const std::string& model) {
  for (const BenchRow& r : rows)
    if (r.variant == variant && r.m.setting.model == model) return &r;
  return nullptr;
}

namespace {

// A model's reference run and the closest any other run of that model comes to it: its relative
// error in ω (NaN when no other run succeeded) and setting.
struct ReferenceAgreement {
  const BenchRow* ref = nullptr;
  double agree = NAN;
  std::string who;
};

ReferenceAgreement referenceAgreement(const std::vector<BenchRow>& rows, const char* model) {
  ReferenceAgreement a;
  for (const BenchRow& r : rows) {
    if (r.m.setting.model != model) continue;
    if (r.reference) a.ref = &r;
    else if (r.m.outcome == Outcome::Ok && std::isfinite(r.error_omega) && !(a.agree <= r.error_omega)) {
      a.agree = r.error_omega;
      a.who = settingText(r.m.setting);
    }
  }
  return a;
}

std::string referenceCheck(const std::vector<BenchRow>& rows) {
  std::ostringstream os;
  // Reference check: the closest any other run of the same model comes to the reference (an
  // estimate of the reference's own error when that run is an independent integrator).
  for (const char* model : {kMultibody, kMinimal, kReduced}) {
    const ReferenceAgreement a = referenceAgreement(rows, model);
    if (!a.ref) {
      os << "- " << model << ": no usable reference run; errors not measured.\n";
      continue;
    }
    os << "- " << model << " reference: " << settingText(a.ref->m.setting) << ", "
       << num(a.ref->m.cpu_seconds) << " s CPU, status " << a.ref->m.status;
    if (std::isfinite(a.agree))
      os << "; closest other run (" << a.who << ") differs by " << num(a.agree, 2)
         << " in ω (when it is another integrator, the reference's own error is of this order or less)";
    os << ".\n";
  }
  return os.str();
}

// Per model, error target and criterion: the cheapest run that reaches it.
std::string recommendedSettings(const std::vector<BenchRow>& rows) {
  std::ostringstream os;
  os << "\n## Recommended settings (cheapest run that reaches the error)\n\n"
     << "| model | target | criterion | setting | CPU [s] | real-time factor | error ω | error coupling |\n"
     << "|---|---|---|---|---|---|---|---|\n";
  for (const char* model : {kMultibody, kMinimal, kReduced})
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
  return os.str();
}

// The minimal formulation's real-time target at a crank-angle error: its row of the targets' table.
std::string angleTargetRow(const Scene& scene, const std::vector<BenchRow>& rows) {
  std::ostringstream os;
  const BenchRow* r = cheapestReachingAngle(rows, kMinimal, kTargetAngleError);
  os << "| " << kMinimal << " | crank angle " << num(kTargetAngleError, 1) << " rad"
     << (scene.simulation.reactions ? ", with reactions" : ", without reactions") << " | "
     << (r ? settingText(r->m.setting) + " (" + num(r->error_angle, 2) + " rad)" : "none reached") << " | "
     << (r ? num(r->m.real_time_factor) : "—") << " | ≥ " << num(kTargetRealTimeAngle) << "× | "
     << (r ? (r->m.real_time_factor >= kTargetRealTimeAngle ? "yes" : "no") : "no") << " |\n";
  return os.str();
}

// The real-time targets of each model at its error, and of the minimal formulation at a crank-angle error.
std::string performanceTargets(const Scene& scene, const std::vector<BenchRow>& rows) {
  std::ostringstream os;
  os << "\n## Performance targets (relative crank-speed error)\n\n"
     << "| model | error | cheapest setting | real-time factor | target | met |\n|---|---|---|---|---|---|\n";
  struct Target {
    const char* model;
    double error, real_time;
  };
  for (const Target& t : {Target{kMultibody, 1e-6, kTargetRealTimeMultibody},
                          Target{kMultibody, 1e-3, kTargetRealTimeMultibodyLoose},
                          Target{kMinimal, 1e-6, kTargetRealTimeMultibody},
                          Target{kMinimal, 1e-3, kTargetRealTimeMultibodyLoose},
                          Target{kReduced, 1e-6, kTargetRealTimeReduced}}) {
    const BenchRow* r = cheapestReaching(rows, t.model, t.error, false);
    os << "| " << t.model << " | " << num(t.error, 1) << " | " << (r ? settingText(r->m.setting) : "none reached")
       << " | " << (r ? num(r->m.real_time_factor) : "—") << " | ≥ " << num(t.real_time) << "× | "
       << (r ? (r->m.real_time_factor >= t.real_time ? "yes" : "no") : "no") << " |\n";
  }
  os << angleTargetRow(scene, rows);
  os << "\nThe targets are stated for model/balanced-4cart.yaml over 10 s; on other scenes or with "
        "--quick (shorter run, start-up transient only) they are indicative.\n";
  return os.str();
}

// One row per run: setting, outcome, cost and errors.
std::string allRunsTable(const std::vector<BenchRow>& rows) {
  std::ostringstream os;
  os << "\n## All runs\n\n| model | integrator | accuracy / step | outcome | CPU [s] | steps | RHS evals | "
        "error ω | error coupling | error angle [rad] | energy residual | constraint error |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const BenchRow& r : rows) {
    const SolverSetting& s = r.m.setting;
    os << "| " << s.model << " | " << s.integrator << (r.reference ? " (ref)" : "") << " | "
       << (s.integrator == "baranov" ? num(s.baranov_step * 180.0 / M_PI) + "°" : num(s.accuracy, 1)) << " | "
       << toString(r.m.outcome) << " | " << num(r.m.cpu_seconds) << " | " << r.m.steps << " | "
       << r.m.realizations << " | " << num(r.error_omega, 2) << " | " << num(r.error_coupling, 2) << " | "
       << num(r.error_angle, 2) << " | " << num(r.m.energy_residual_rel, 2) << " | "
       << num(r.m.constraint_error_max, 2) << " |\n";
  }
  return os.str();
}

}  // namespace

std::string integratorReport(const Scene& scene, const std::vector<BenchRow>& rows, const BenchOptions& opt) {
  std::ostringstream os;
  const double T = scene.simulation.t_end;
  os << "# Integrator benchmark: " << scene.name << "\n\n"
     << "Simulated time " << num(T) << " s (output step " << num(scene.simulation.output_step)
     << " s)" << (opt.quick ? ", --quick" : "") << ". " << timingNote(scene, opt) << "\n\n"
     << "**Error measure.** For each run, over the output grid it shares with the reference run of the "
        "SAME model: error_omega = max_i |ω_i − ω_ref,i| / max_i |ω_ref,i| (crank speed), "
        "error_coupling = the same for the coupling torque, error angle = max_i |φ_i − φ_ref,i| (crank angle, "
        "rad). References: multibody (constrained) RungeKuttaMerson, multibody-minimal CVODE Adams, reduced "
        "CVODE, all at accuracy "
     << num(kReferenceAccuracy, 2)
     << " (Merson rather than the 5th-order Feldberg: at equal accuracy it takes ~3x smaller steps, the "
        "safer reference for anything not fully under error control; the minimal formulation has its own "
        "reference because it runs the scene's friction law). Baranov's scheme is compared with "
        "the reduced CVODE reference.\n\n";

  os << referenceCheck(rows);
  os << recommendedSettings(rows);
  os << performanceTargets(scene, rows);
  os << allRunsTable(rows);
  os << "\nFigures: work_precision_omega.png/.svg, work_precision_coupling.png/.svg (error vs CPU time, "
        "log-log, one line per integrator). Data: bench.csv.\n";
  return os.str();
}

namespace {

// Every run of the carts study: its cost in total, per cart, with set-up and per RHS evaluation.
std::string cartsTable(const std::vector<BenchRow>& rows) {
  std::ostringstream os;
  os << "| n | model | outcome | CPU [s] | CPU per cart [s] | CPU with set-up [s] | steps | RHS evals | "
        "µs per RHS eval per cart | real-time factor |\n|---|---|---|---|---|---|---|---|---|---|\n";
  for (const BenchRow& r : rows) {
    const Measurement& m = r.m;
    const double us = m.realizations > 0 ? 1e6 * m.cpu_seconds / m.realizations / r.x : NAN;
    os << "| " << r.x << " | " << m.setting.model << " | " << toString(m.outcome) << " | " << num(m.cpu_seconds)
       << " | " << num(m.cpu_seconds / r.x) << " | " << num(m.cpu_with_setup) << " | " << m.steps << " | "
       << m.realizations << " | " << num(us) << " | " << num(m.real_time_factor) << " |\n";
  }
  return os.str();
}

// A cart count whose per-cart cost is held against 4 carts', and its target.
struct PerCartRatio {
  int n;
  double target;
  bool setup;  // the target counts the set-up
};

// The model's per-cart cost at q.n carts over its cost at 4 (empty when either run is missing);
// the target applies to the minimal formulation.
std::string perCartRatioRow(const std::vector<BenchRow>& rows, const char* model, const PerCartRatio& q) {
  const BenchRow* a = findRow(rows, "n=4", model);
  const BenchRow* b = findRow(rows, "n=" + std::to_string(q.n), model);
  if (!a || !b || !usable(a->m.outcome) || !usable(b->m.outcome)) return "";
  const double run_ratio = (b->m.cpu_seconds / q.n) / (a->m.cpu_seconds / 4);
  const double setup_ratio = (b->m.cpu_with_setup / q.n) / (a->m.cpu_with_setup / 4);
  const double rhs_ratio = (b->m.cpu_seconds / b->m.realizations / q.n) / (a->m.cpu_seconds / a->m.realizations / 4);
  const double judged = q.setup ? setup_ratio : run_ratio;
  std::ostringstream os;
  os << "| " << model << " | " << q.n << " | " << num(run_ratio) << " | " << num(setup_ratio) << " | "
     << num(rhs_ratio) << " | ";
  if (model == std::string(kMinimal))
    os << "≤ " << num(q.target) << (q.setup ? " with set-up" : " per run") << " | "
       << (judged <= q.target ? "yes" : "no") << " |\n";
  else
    os << "— | — |\n";
  return os.str();
}

std::string perCartRatios(const std::vector<BenchRow>& rows) {
  std::ostringstream os;
  os << "\n## Per-cart cost relative to 4 carts\n\n"
     << "| model | n | per run (CPU/n) | with set-up (CPU/n) | per RHS evaluation (CPU/RHS/n) | target | met |\n"
     << "|---|---|---|---|---|---|---|\n";
  for (const char* model : {kMultibody, kMinimal, kReduced})
    for (const PerCartRatio& q : {PerCartRatio{32, kTargetPerCartCostRatio32, false},
                                  PerCartRatio{64, kTargetPerCartCostRatio64, false},
                                  PerCartRatio{256, kTargetPerCartCostRatio256, true}})
      os << perCartRatioRow(rows, model, q);
  return os.str();
}

}  // namespace

std::string cartsReport(const Scene& scene, const std::vector<BenchRow>& rows, const BenchOptions& opt) {
  std::ostringstream os;
  os << "# Cost vs number of carts: " << scene.name << "\n\n"
     << "carts.count = n, carts.sides = same, crank.offset_deg = 360/n (0 for n = 1); motor breakdown "
        "torque × n/" << scene.carts.count << " for n > " << scene.carts.count
     << " so the drive carries the load. Each model at the scene's integrator and accuracy ("
     << scene.simulation.integrator << " / cvode, " << num(scene.simulation.accuracy, 2) << "), "
     << num(benchScene(scene, opt).simulation.t_end) << " s simulated. " << timingNote(scene, opt) << "\n\n"
     << "The multibody model's constrained formulation runs up to 32 carts (its evaluation is O(n²)). "
        "CPU with set-up: the model's construction, initial state and run, in the process that runs it.\n\n"
     << cartsTable(rows) << perCartRatios(rows);
  os << "\nPer run includes any change in the number of steps the dynamics of n carts needs; per RHS "
        "evaluation isolates the cost of evaluating the model. Targets: the multibody model's minimal "
        "formulation with guide friction and joint reactions (the scene's). Figure: carts_cost.png/.svg. "
        "Data: carts.csv.\n";
  return os.str();
}

namespace {

// One row per effect study run: its variant's number, outcome and cost relative to the baseline.
std::string effectsTable(const std::vector<BenchRow>& rows) {
  std::ostringstream os;
  os << "| # | variant | model | outcome | CPU [s] | relative cost | steps | RHS evals | µs per RHS eval |\n"
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
  return os.str();
}

// One row per motor study run: its cost and right-hand-side evaluations relative to the static
// Kloss law's run of the same model.
std::string motorsTable(const std::vector<BenchRow>& rows) {
  std::ostringstream os;
  os << "| motor model | model | outcome | CPU [s] | relative cost | steps | RHS evals | relative RHS evals | µs per "
        "RHS eval |\n"
     << "|---|---|---|---|---|---|---|---|---|\n";
  for (const BenchRow& r : rows) {
    const BenchRow* base = findRow(rows, "motor.model kloss", r.m.setting.model);
    const bool ok = base && usable(base->m.outcome) && usable(r.m.outcome);
    const double rel = ok ? r.m.cpu_seconds / base->m.cpu_seconds : NAN;
    const double rel_rhs = ok && base->m.realizations > 0 ? double(r.m.realizations) / base->m.realizations : NAN;
    const double us = r.m.realizations > 0 ? 1e6 * r.m.cpu_seconds / r.m.realizations : NAN;
    os << "| " << r.variant.substr(std::string("motor.model ").size()) << " | " << r.m.setting.model << " | "
       << toString(r.m.outcome)
       << (usable(r.m.outcome) ? "" : " (" + r.m.status + ")") << " | " << num(r.m.cpu_seconds) << " | " << num(rel)
       << " | " << r.m.steps << " | " << r.m.realizations << " | " << num(rel_rhs) << " | " << num(us) << " |\n";
  }
  return os.str();
}

}  // namespace

std::string effectsReport(const Scene& scene, const std::vector<BenchRow>& rows, const BenchOptions& opt) {
  std::ostringstream os;
  os << "# Cost of each effect: " << scene.name << "\n\n"
     << "Each variant changes one thing of the scene (--set) and runs both models at the scene's "
        "integrator and accuracy ("
     << scene.simulation.integrator << " / cvode, " << num(scene.simulation.accuracy, 2) << "), "
     << num(benchScene(scene, opt).simulation.t_end) << " s simulated. Relative cost = CPU / CPU of the "
        "baseline of the same model. " << timingNote(scene, opt) << "\n\n"
     << effectsTable(rows);
  if (!scene.hasGuideFriction() && !(scene.carts.geometry.b > 0))
    os << "\nGuide friction: not applicable (the scene has no guide geometry, carts.geometry.b = 0).\n";
  os << "\nFigures: effects_stiffness.png/.svg (CPU vs coupling stiffness, rigid coupling drawn as a flat "
        "line), effects_relative.png/.svg (relative cost by variant number). Data: effects.csv.\n";
  return os.str();
}

std::string motorsReport(const Scene& scene, const std::vector<BenchRow>& rows, const BenchOptions& opt) {
  std::ostringstream os;
  os << "# Cost of each motor model: " << scene.name << "\n\n"
     << "The same scene and starting method with each motor model (motor.model: kloss = static Kloss "
        "formula, kloss_dynamic = dynamic Kloss characteristic (one state), circuit = quasi-static "
        "equivalent circuit fitted to the catalogue, park = space-phasor machine, 4-6 flux states), both "
        "models at the scene's integrator and accuracy ("
     << scene.simulation.integrator << " / cvode, " << num(scene.simulation.accuracy, 2) << "), "
     << num(benchScene(scene, opt).simulation.t_end)
     << " s simulated from the scene's initial state. Relative cost = CPU / CPU of motor.model kloss for the "
        "same model; the step and right-hand-side counts do not depend on the machine's load. "
     << timingNote(scene, opt) << "\n\n"
     << motorsTable(rows);
  os << "\nThe space-phasor machine adds its electrical transient after every switching (supply-frequency "
        "oscillation, time constants of ms) and 4 (single cage) or 6 (double cage) states; the static laws add "
        "no state. Whether a law makes the equations stiff and the integrators switch to BDF: docs/startup.md. "
        "Data: motors.csv.\n";
  return os.str();
}

}  // namespace rollerdyn::bench
