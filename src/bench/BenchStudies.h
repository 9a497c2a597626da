// The studies of `rollerdyn bench` and the files they publish:
//
//   integrators  every Simbody integrator (integratorNames()) of the multibody model's constrained
//                formulation, its minimal formulation (model "multibody-minimal", CVODE Adams,
//                errors against the same multibody reference) and the reduced model's CVODE
//                (plus Baranov's scheme on rigid-drive scenes) at accuracies 1e-2, 3e-3 ... 1e-10;
//                errors against a reference run of the SAME model (see BenchRun.h for the error
//                measure): multibody RungeKuttaMerson (why not Feldberg: BenchStudies.cpp),
//                reduced CVODE, both at accuracy kReferenceAccuracy = 1e-10 (also with --quick).
//                -> bench.csv, work_precision_omega.{png,svg},
//                work_precision_coupling.{png,svg}, bench.md (cheapest setting reaching 1e-3
//                and 1e-6, real-time factors against the targets).
//   carts        cost vs number of carts n = 1, 2, 4, 8, 16, 32, 64, 256 for both models (the
//                multibody model in both formulations; the constrained one up to 32 carts, its
//                O(n²) evaluation makes more a matter of minutes) at the scene's own integrator
//                and accuracy (carts.count=n, carts.sides=same, crank.offset_deg=360/n); loop CPU
//                and CPU with the model's set-up. -> carts.csv, carts_cost.{png,svg}, carts.md.
//   reactions    the minimal formulation with and without the joint reactions at every
//                accuracy of the grid down to 1e-8, the two timed alternately (--repeat N pairs):
//                what the O(n) reaction columns cost. -> reactions.csv, reactions.md.
//   effects      cost of each effect at the scene's integrator and accuracy: rigid vs elastic
//                coupling, coupling damping off, reducer backlash 0.1° on (or off), coupling
//                stiffness 2e5 ... 1e9 N·m/rad, guide friction on/off, each
//                rod model, gravity on/off. -> effects.csv, effects_stiffness.{png,svg},
//                effects_relative.{png,svg}, effects.md.
//   motors       cost of each motor model (motor.model kloss, kloss_dynamic, circuit, park) on the
//                same scene and starting method, both models (the multibody model in both
//                formulations) at the scene's integrator and accuracy; relative cost against
//                static Kloss. -> motors.csv, motors.md.
//
// Every run has a CPU-time budget (BenchRun.h): a slow or failing combination becomes a
// "timeout" or "failed" row, never a hang. Once an integrator exceeds the budget at some
// accuracy, the tighter accuracies of the same integrator are recorded as timeouts without
// being run (their cost can only be higher).
#pragma once

#include <atomic>
#include <functional>
#include <string>
#include <vector>

#include "bench/BenchRun.h"
#include "scene/Scene.h"

namespace rollerdyn::bench {

// A scene file plus the user's --set overrides; each variant re-parses it with extra overrides,
// so every variant passes the same validation as a scene file.
struct SceneSource {
  std::string path;
  std::vector<std::string> overrides;
  Scene load(const std::vector<std::string>& extra = {}) const;
};

struct BenchOptions {
  bool quick = false;       // fewer accuracies, t_end cut to quick_t_end, smaller budget
  double budget = 20.0;     // CPU seconds per run (the reference run gets reference_budget_factor×)
  double reference_budget_factor = 10.0;
  double quick_t_end = 1.0; // simulated time of --quick runs [s] (never more than the scene's)
  int repeats = 1;          // timed repetitions of each successful run; median reported
  const std::atomic<bool>* interrupt = nullptr;        // Ctrl-C
  std::function<void(const std::string&)> log;         // one line per run (may be empty)
};

// One row of bench.csv / carts.csv / effects.csv.
struct BenchRow {
  std::string study;        // "integrators" | "carts" | "effects" | "motors"
  std::string variant;      // "" (integrators), "n=8", "coupling stiffness 1e+07 N·m/rad", ...
  double x = 0;             // numeric value of the variant: carts n, stiffness c; 0 otherwise
  int carts = 0;            // number of carts of the scene run
  bool reference = false;   // this run is the reference of its model
  Measurement m;            // tables are dropped once the errors are computed
  double error_omega = 0;   // see BenchRun.h; NaN when not measured (no reference or no result)
  double error_coupling = 0;
  double error_angle = 0;   // max_i |φ2_i - φ2_ref,i|, the crank angle's absolute error [rad]; NaN as above
};

// Accuracy of the reference runs of the integrator study.
constexpr double kReferenceAccuracy = 1e-10;

// Accuracies of the integrator study: 1e-2, 3e-3, 1e-3, ... 3e-10, 1e-10 (two per decade);
// quick: 1e-2, 1e-4, 1e-6, 1e-8.
std::vector<double> accuracyGrid(bool quick);
// Crank-angle steps of the Baranov scheme [rad]: 8° halved down to 1/32° (quick: 4°, 1°, 1/4°).
std::vector<double> baranovSteps(bool quick);
// The scene with the bench's time span (quick: min(t_end, quick_t_end)).
Scene benchScene(const Scene& scene, const BenchOptions& options);

std::vector<BenchRow> runIntegratorStudy(const SceneSource& source, const BenchOptions& options);
std::vector<BenchRow> runCartsStudy(const SceneSource& source, const BenchOptions& options);
std::vector<BenchRow> runEffectsStudy(const SceneSource& source, const BenchOptions& options);
std::vector<BenchRow> runMotorsStudy(const SceneSource& source, const BenchOptions& options);
// Variant "reactions" / "no reactions" at each accuracy, x = the accuracy.
std::vector<BenchRow> runReactionsStudy(const SceneSource& source, const BenchOptions& options);

// The cheapest (median CPU time) non-reference row of `model` with outcome ok whose error is at
// most `target`: error_omega, or max(error_omega, error_coupling) when with_coupling. nullptr
// when no row reaches it.
const BenchRow* cheapestReaching(const std::vector<BenchRow>& rows, const std::string& model,
                                 double target, bool with_coupling);
// The same for the crank angle's absolute error error_angle <= target [rad].
const BenchRow* cheapestReachingAngle(const std::vector<BenchRow>& rows, const std::string& model, double target);

// The row of `variant` run by `model`, nullptr when there is none.
const BenchRow* findRow(const std::vector<BenchRow>& rows, const std::string& variant, const std::string& model);

// The CSV text of rows (header + one line per row; NaN written as an empty field).
std::string rowsCsv(const std::vector<BenchRow>& rows);

// Markdown reports (the content of bench.md, carts.md, effects.md).
std::string integratorReport(const Scene& scene, const std::vector<BenchRow>& rows,
                             const BenchOptions& options);
std::string cartsReport(const Scene& scene, const std::vector<BenchRow>& rows,
                        const BenchOptions& options);
std::string effectsReport(const Scene& scene, const std::vector<BenchRow>& rows,
                          const BenchOptions& options);
std::string motorsReport(const Scene& scene, const std::vector<BenchRow>& rows, const BenchOptions& options);

// Write the CSV, the figures (when gnuplot is available; otherwise a note in the .md) and the
// markdown of one study to out_dir. Returns the paths written.
std::vector<std::string> writeIntegratorStudy(const std::string& out_dir, const Scene& scene,
                                              const std::vector<BenchRow>& rows,
                                              const BenchOptions& options);
std::vector<std::string> writeCartsStudy(const std::string& out_dir, const Scene& scene,
                                         const std::vector<BenchRow>& rows,
                                         const BenchOptions& options);
std::vector<std::string> writeEffectsStudy(const std::string& out_dir, const Scene& scene,
                                           const std::vector<BenchRow>& rows,
                                           const BenchOptions& options);
std::vector<std::string> writeMotorsStudy(const std::string& out_dir, const Scene& scene,
                                          const std::vector<BenchRow>& rows, const BenchOptions& options);
std::vector<std::string> writeReactionsStudy(const std::string& out_dir, const Scene& scene,
                                             const std::vector<BenchRow>& rows, const BenchOptions& options);

// Performance targets (real-time factors) at 1e-6 relative crank-speed error, and for the
// multibody model also at 1e-3 (a fixed-step soft-constraint engine's accuracy on the same
// machine, MuJoCo 2.2.2: 200x real time).
constexpr double kTargetRealTimeMultibody = 50.0;
constexpr double kTargetRealTimeMultibodyLoose = 200.0;
constexpr double kTargetRealTimeReduced = 1000.0;
// The multibody model with joint reactions at a crank-angle error of at most 1e-5 rad.
constexpr double kTargetAngleError = 1e-5;  // [rad]
constexpr double kTargetRealTimeAngle = 150.0;
// Per-cart cost of the minimal formulation with guide friction and reactions against 4 carts:
// loop CPU at 32 and 64 carts, CPU with the model's set-up at 256 carts.
constexpr double kTargetPerCartCostRatio32 = 1.3;
constexpr double kTargetPerCartCostRatio64 = 1.5;
constexpr double kTargetPerCartCostRatio256 = 2.0;
// Minimal formulation: CPU with reactions / CPU without, at every accuracy 1e-2 ... 1e-8.
constexpr double kTargetReactionsCostRatio = 1.3;

}  // namespace rollerdyn::bench
