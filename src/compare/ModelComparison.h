// Runs the multibody model and the reduced model on one Scene and measures how far apart they
// are: `rollerdyn compare` (src/cli/CompareCommand.cpp) and the validation suite use this.
//
// Both models write their rows on the same output grid (0, h, 2h, ..., t_end with
// h = simulation.output_step, RunResult.h), so the comparison is row by row. For robustness the
// reduced model's columns are still interpolated linearly onto the multibody time grid (exact
// when the grids coincide, which is checked and reported as `grid_max_time_offset`), and only
// the time span both runs reached is compared (a run may end early, e.g. a stalled motor).
//
// Statistics of a quantity a(t) (multibody) against b(t) (reduced) over the compared rows:
//   max_abs_diff = max |a - b|
//   rms_diff     = sqrt( ∫(a - b)² dt / T )   (trapezoidal rule; on the uniform output grid
//                                               this is the sample RMS up to the end points)
//   max_rel_diff = max |a - b| / max |a|     (multibody as the reference; NaN when a ≡ 0)
#pragma once

#include <atomic>
#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/RunResult.h"
#include "compare/ModelDifferences.h"
#include "io/Table.h"
#include "scene/Scene.h"

namespace rollerdyn {

struct DifferenceStats {
  double max_abs_diff = 0;  // max |a - b|, units of the quantity
  double rms_diff = 0;      // time-RMS of a - b, units of the quantity
  double max_rel_diff = 0;  // max|a - b| / max|a| [-]
  double max_abs_a = 0;     // max |a| (the reference scale) 
  double t_at_max = 0;      // time of the largest |a - b| [s]
  std::size_t samples = 0;  // rows compared
};

// Statistics of a (reference) against b on the time grid t (all three the same length, t
// ascending). Non-finite samples make every field NaN.
DifferenceStats differenceStats(const std::vector<double>& t, const std::vector<double>& a,
                                const std::vector<double>& b);

// Linear interpolation of y(t_src) at the times t_dst (t_src ascending). Times outside
// [t_src.front(), t_src.back()] give NaN. A time equal to a source time returns that sample
// exactly.
std::vector<double> resampleLinear(const std::vector<double>& t_src, const std::vector<double>& y_src,
                                   const std::vector<double>& t_dst);

struct QuantityComparison {
  std::string name;   // column name, e.g. "omega_crank", "N_front_2"
  DifferenceStats stats;
};

// One steady-state answer of both models, each over its own steady window (SteadyState.h).
struct SteadyMetricComparison {
  std::string name;        // delta, coupling_torque_swing, coupling_torque_rms, coupling_torque_mean, ...
  std::string unit;
  double multibody = 0, reduced = 0;
  double rel_diff = 0;     // (reduced - multibody)/|multibody| [-]
};

// The two models' steady running compared at the same crank angle rather than at the same time:
// the time series of a quantity over each run's steady window, folded onto one revolution
// (72 crank angles 5° apart, interpolated in φ between rows, averaged over the revolutions), so a model that runs a little faster or slower (its crank
// a few degrees ahead after many revolutions: phase drift) does not read as a different shape.
struct ShapeComparison {
  std::string name;            // omega_crank, coupling_torque
  double max_abs_diff = 0;     // max over the bins of |a(φ) - b(φ)|
  double rel_diff = 0;         // max_abs_diff / (max - min of a(φ)): against the quantity's swing [-]
};

struct ModelComparison {
  std::string scene_name;
  RunResult multibody;   // the two runs as they came back
  RunResult reduced;
  // comparison.csv: t, then for each quantity <name>_multibody, <name>_reduced, and for the
  // reaction quantities also <name>_reduced_kinetostatic (reduced model's cart statics with
  // each cart's d'Alembert force added, ReducedModel::cartReactions(..., true)).
  Table table;
  // multibody vs the reduced model's own output: omega_crank, coupling_torque, then per cart
  // N_front_j, N_rear_j, F_rod_j.
  std::vector<QuantityComparison> quantities;
  // multibody reactions vs the reduced model's kinetostatic reactions (same names).
  std::vector<QuantityComparison> kinetostatic;
  std::vector<SteadyMetricComparison> steady;  // the headline: steady-window answers of both
  std::vector<ShapeComparison> shapes;          // same crank angle, steady windows
  double phase_drift = 0;  // φ_multibody - φ_reduced at the end of the compared span [rad]
  double speed_difference = 0;  // ω_mean reduced - multibody over the steady windows [rad/s]
  std::vector<ModelDifference> differences;   // modelDifferences(scene)
  std::vector<std::string> identical;         // identicalPhysics(scene)
  bool motion_equivalent = false;             // motionEquivalent(scene)
  double t_begin = 0, t_end = 0;              // compared time span [s]
  std::size_t rows = 0;                       // compared rows
  double grid_max_time_offset = 0;            // max distance of a multibody row time from the
                                              // nearest reduced row time [s] (0: same grid)

  // The comparison of `name` in `quantities` (nullptr when absent).
  const QuantityComparison* find(const std::string& name) const;
  const QuantityComparison* findKinetostatic(const std::string& name) const;
  // CPU seconds of each model's integration (RunStats::cpu_seconds).
  double cpuMultibody() const { return multibody.stats.cpu_seconds; }
  double cpuReduced() const { return reduced.stats.cpu_seconds; }
};

// The quantities compared for a scene with `carts` carts, in output order: crank speed, coupling
// torque and, when the runs computed reactions (simulation.reactions), each cart's guide and rod forces.
std::vector<std::string> comparedQuantities(int carts, bool reactions = true);

// Compares two finished runs of `scene` (pure: runs nothing but the reduced model's
// kinetostatic cart statics on the reduced run's own rows).
ModelComparison compareRuns(const Scene& scene, RunResult multibody, RunResult reduced);

struct CompareControl {
  const std::atomic<bool>* interrupt = nullptr;  // passed to the multibody run
};

// Runs both models on `scene` and compares them.
ModelComparison runComparison(const Scene& scene, const CompareControl& control = {});

// comparison.json: scene, compared span, quantities {name: {max_abs_diff, rms_diff,
// max_rel_diff, max_abs_multibody, t_at_max_abs_diff, samples}}, kinetostatic_reactions (same
// keys), differences (sentences), differences_detail [{topic, affects_motion, numerical,
// sentence}], identical_physics, motion_equivalent, speed {cpu_seconds_multibody,
// cpu_seconds_reduced, cpu_ratio_reduced_to_multibody, speedup_reduced_over_multibody}, runs
// {multibody|reduced: {integrator, status, complete, steps, realizations, cpu_seconds}}.
// Non-finite numbers are written as null.
nlohmann::json comparisonJson(const ModelComparison& comparison);

// A few lines for the terminal.
std::string comparisonText(const ModelComparison& comparison);

}  // namespace rollerdyn
