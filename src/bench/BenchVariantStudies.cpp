// The studies of `rollerdyn bench` that vary the scene (BenchStudies.h): carts, effects and
// motors. Each variant re-parses the scene file with its own --set values and runs both models
// (the multibody model in both formulations) at the scene's integrator and accuracy.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "bench/BenchRows.h"
#include "bench/BenchStudies.h"
#include "bench/BenchText.h"
#include "scene/SceneSchema.h"

namespace rollerdyn::bench {

namespace {

// A value for --set that round-trips exactly.
std::string setValue(double v) {
  std::ostringstream os;
  os.precision(17);
  os << v;
  return os.str();
}

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

// The crank throws' positions along the shaft for n carts, 0.3 m apart from 0.2 m: "0.2, 0.5, ...".
std::string throwPositionList(int n) {
  std::ostringstream throws;
  for (int j = 0; j < n; ++j) throws << (j ? ", " : "") << 0.2 + 0.3 * j;
  return throws.str();
}

// An elastic coupling rigid, without its damping; the reducer's backlash off, or on where it is
// off (its contacts' cost in steps, docs/models.md, backlash of the reducer).
void couplingVariants(const Scene& base, std::vector<EffectVariant>& v) {
  if (base.coupling.type != CouplingType::Elastic) return;
  v.push_back({"rigid coupling", 0, {"coupling.type=rigid"}});
  if (base.coupling.damping > 0) v.push_back({"coupling damping off (k = 0)", 0, {"coupling.damping=0"}});
  if (base.hasBacklash())
    v.push_back({"reducer backlash off", 0, {"reducer.backlash=0"}});
  else
    v.push_back({"reducer backlash 0.1° (0.0017453 rad)", 0, {"reducer.backlash=0.0017453"}});
}

// Main bearings along the crankshaft: beam statics on the output rows, after the integration
// (its cost is in the whole process, not in the loop this table times).
void bearingsVariant(const Scene& base, std::vector<EffectVariant>& v) {
  if (!(base.crankshaft.throw_positions.empty() && base.simulation.reactions)) return;
  std::ostringstream bearings;
  const int n = base.carts.count;
  for (int j = 0; j <= n; ++j) bearings << (j ? ", " : "") << (j == 0 ? 0.0 : 0.35 + 0.3 * (j - 1));
  v.push_back({"main bearings along the crankshaft (" + std::to_string(n + 1) + " bearings)", 0,
               {"crankshaft.throw_positions=[" + throwPositionList(n) + "]",
                "crankshaft.bearing_positions=[" + bearings.str() + "]"}});
}

// The crankshaft as a torsional chain (docs/models.md): built by the constrained formulation only,
// so it is timed beside the same formulation with the rigid shaft; a 100 mm steel shaft, G·I_p =
// 80 GPa·π·(0.1 m)⁴/32 = 7.85e5 N·m², throws 0.3 m apart.
void crankshaftChainVariants(const Scene& base, std::vector<EffectVariant>& v) {
  if (!(base.carts.count > 1 && !base.hasCamDrive() && !base.crankshaft.torsionalChain())) return;
  std::vector<std::string> constrained = {"simulation.formulation=constrained"};
  if (base.hasGuideFriction()) constrained.push_back("loads.guide_friction.normal_force=lagged");
  v.push_back({"constrained formulation, rigid crankshaft", 0, constrained});
  std::vector<std::string> chain = constrained;
  chain.push_back("crankshaft.throw_positions=[" + throwPositionList(base.carts.count) + "]");
  chain.push_back("crankshaft.torsional_stiffness=7.85e5");
  v.push_back({"constrained formulation, crankshaft as a torsional chain (G·I_p = 7.85e5 N·m²)", 0, chain});
}

// The drive's own parts switched or changed one at a time: coupling, reducer, main bearings and
// the crankshaft.
void driveVariants(const Scene& base, std::vector<EffectVariant>& v) {
  couplingVariants(base, v);
  // The reducer's losses by the direction of the power flow (docs/models.md): the blend's cost.
  if (base.motor.enabled) {
    if (base.reducer.losses == ReducerLossModel::Papers)
      v.push_back({"reducer losses by power flow (η_r = η)", 0, {"reducer.losses=power_flow"}});
    else
      v.push_back({"reducer losses as the papers (constant η)", 0, {"reducer.losses=papers"}});
  }
  bearingsVariant(base, v);
  crankshaftChainVariants(base, v);
}

// The coupling's stiffness over four decades (N·m/rad): how stiff an elastic drive gets before it costs.
void couplingStiffnessVariants(const Scene& base, std::vector<EffectVariant>& v) {
  const bool elastic = base.coupling.type == CouplingType::Elastic;
  for (double c : {2e5, 1e6, 1e7, 1e8, 1e9}) {
    std::ostringstream name;
    name << "elastic coupling c = " << c << " N·m/rad" << (elastic ? "" : " (k = 0)");
    v.push_back({name.str(), c, {"coupling.type=elastic", "coupling.stiffness=" + setValue(c)}});
  }
}

// Each rod model other than the scene's.
void rodModelVariants(const Scene& base, std::vector<EffectVariant>& v) {
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
}

// The model's choices one at a time: coupling stiffness, guide friction, rod model and gravity.
void modelVariants(const Scene& base, std::vector<EffectVariant>& v) {
  couplingStiffnessVariants(base, v);
  if (base.hasGuideFriction())
    v.push_back({"guide friction off", 0, {"loads.guide_friction.coefficient=0"}});
  else if (base.carts.geometry.b > 0)
    v.push_back({"guide friction on (f = 0.008)", 0, {"loads.guide_friction.coefficient=0.008"}});
  rodModelVariants(base, v);
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

}  // namespace rollerdyn::bench
