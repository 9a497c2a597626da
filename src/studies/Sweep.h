// Parameter sweeps (`rollerdyn sweep`): one simulation per point of a grid of scene values, each
// value applied as a --set override (so it passes the same validation as a scene file), every
// run to the scene's t_end, on a pool of worker threads (each run builds its own model: Simbody
// systems and the reduced model's CVODE context are independent objects). A point that fails
// (bad value, exception, stall) is recorded with its status and the sweep goes on.
//
// Outputs (writeSweepOutputs): sweep.csv, one row per point: the parameter values under their key
// paths, then delta, H, k_p, omega_crank_mean, coupling_torque_swing, twist_swing,
// eps_crank_abs_max, energy_residual_rel, steady_state_reached, motion, status, cpu_seconds, then
// extra columns omega_crank_min, omega_crank_max, omega_crank_midrange, twist_rate_swing,
// twist_accel_swing, resonance_warnings and the drive-sizing metrics (analysis/SizingSummary.h);
// headers carry units as name[unit] (io/Table.h); sweep.json (the same plus the optimum and the resonance
// warnings of each point); plots: each metric against the parameter (one parameter) or a heat
// map over the grid (two parameters), through src/report/Gnuplot.h, where points that are not
// turning at steady state are marked and never set the colour scale (SweepPlots.h).
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/SceneParser.h"

namespace rollerdyn {

struct SweepParameter {
  std::string key;                 // scene key path, e.g. crank.offset_deg
  std::vector<std::string> texts;  // each value as given to --set
  std::vector<double> values;      // the same as numbers (NaN for words such as `rigid`)
  bool numeric() const;
};

// "a:b:step" (a, a+step, ... up to b within 1e-9·|step|; step != 0 and pointing from a to b) or
// "v1,v2,..." (numbers or words). Throws std::invalid_argument with the reason.
SweepParameter parseSweepValues(const std::string& key, const std::string& spec);

// Metric columns of sweep.csv, in order (status is text; steady_state_reached is 0/1).
const std::vector<std::string>& sweepMetricColumns();
// The numeric metrics that can be plotted and minimised.
const std::vector<std::string>& sweepNumericMetrics();

struct SweepPoint {
  std::vector<std::string> texts;        // parameter values of this point (per parameter)
  std::vector<double> values;
  std::vector<double> metrics;           // sweepNumericMetrics() order; NaN when not computed
  bool ran = false;                      // the model ran (whatever its outcome)
  bool complete = false;                 // the run reached t_end
  bool steady = false;                   // summary: steady_state.reached
  std::string motion = "not run";        // summary: motion (stalled, rocking, turning, ...)
  std::string status = "not run";        // run status, or "invalid: ...", "error: ..."
  double cpu_seconds = 0;                // CPU time of this point's thread [s]
  nlohmann::json warnings = nlohmann::json::array();  // resonance warnings (ResonanceCheck.h)
  double metric(const std::string& name) const;
};

// The point of a design before it is run: its values, every metric NaN, status "not run".
SweepPoint pointNotRun(const std::vector<std::string>& texts, const std::vector<double>& values);

struct SweepOptions {
  std::string scene_path;
  // The scene when it is kept in memory (the Python interface): parsed from it at each point
  // instead of reading scene_path, which then only names it in the outputs.
  std::shared_ptr<const SceneInput> scene_input;
  std::vector<std::string> base_overrides;  // --set given to the sweep itself, applied first
  std::vector<SweepParameter> params;
  std::string model = "multibody";          // multibody | reduced
  std::string minimize;                     // a sweepNumericMetrics() name, or empty
  int threads = 2;
  const std::atomic<bool>* interrupt = nullptr;
  // Large and distributed sweeps (SweepExecution.h): explicit designs, saved rows, MPI, budget.
  std::vector<std::vector<std::string>> designs;  // one text per parameter each; empty: the grid
  std::string progress_path;                 // rows appended here as they finish; empty: not saved
  bool resume = false;                       // reuse the rows saved in progress_path
  double point_budget = 0;                   // CPU seconds per point in a child process [s]; 0: none
  bool mpi = false;                          // distribute over the MPI ranks (SweepMpi.h)
  bool dispatcher_computes = true;           // under MPI, rank 0 computes points too
  // Called (serialised) after each point; done counts finished points. The run at the parabola's
  // vertex (SweepVertex) comes last, as done = total + 1.
  std::function<void(const SweepPoint&, std::size_t done, std::size_t total)> on_point;
  // The run of one point; empty: the scene's model (runSweepPoint). A study of a metric whose shape
  // is known beforehand (a test's V-shaped minimum) puts its own here.
  std::function<SweepPoint(const std::vector<std::string>& texts, const std::vector<double>& values)> run_point;
};

// The --set list of the sweep's first point: the sweep's own --set, then each parameter at its first
// value. The base scene is checked with it, so a key that every point sets (coupling.stiffness
// swept under a --set coupling.type=elastic) counts as given.
std::vector<std::string> firstPointOverrides(const SweepOptions& o);

// One numeric parameter, the best grid point inside the grid: the vertex of the parabola through it
// and its two neighbours. A prediction only; runSweep runs it (same model, overrides and settings
// as the grid's points) before anything calls it an optimum, and judgeVertexRun compares.
struct SweepVertex {
  bool available = false;   // the parabola exists and opens upwards
  std::string text;         // its parameter value as applied (--set), 12 significant digits
  double parameter = 0;     // the same as a number: exactly what the run uses
  double predicted = 0;     // the parabola's value there
  double refine_lower = 0, refine_upper = 0, refine_step = 0;  // a finer grid: the two neighbours, spacing / 10
  bool ran = false;         // run (not when interrupted)
  SweepPoint point;         // that run
  bool usable = false;      // the run counts as a grid point would (completed, turning, steady where the grid was)
  double value = 0;         // the run's metric (NaN unless usable)
  double tolerance = 0;     // simulation.accuracy × the largest |metric| of the three grid points
  bool holds = false;       // usable and |value − predicted| ≤ tolerance
  bool lower = false;       // usable and value < predicted − tolerance: the metric is no parabola
                            // there, but the estimate errs on the safe side (not holding: value above)
  std::string note;         // the outcome in words (why not run, not usable, or not holding)
};

// The optimum is always a run: the best grid point, or the run at the parabola's vertex where that
// run is better still.
struct SweepOptimum {
  bool found = false;
  std::string metric;
  std::size_t index = 0;          // the best grid point, into SweepResult::points
  double grid_value = 0;          // its metric
  bool at_vertex = false;         // the vertex run beats the best grid point: it is the optimum
  double value = 0;               // the optimum's metric (grid point's or vertex run's)
  bool steady = false;            // whether the optimum's run reached steady state
  std::string note;               // how it was chosen / why none
  SweepVertex vertex;             // one numeric parameter, best point inside the grid
};

struct SweepResult {
  std::vector<SweepPoint> points;  // grid order: the last parameter varies fastest
  SweepOptimum optimum;
  bool output_rank = true;                       // false on MPI worker ranks: they write nothing
  nlohmann::json execution = nlohmann::json::object();  // how it ran (ranks, ...): into sweep.json
};

// Throws std::invalid_argument for an empty grid, an unknown model or metric; every per-point
// failure is recorded in the point instead.
// Throws std::invalid_argument "WHAT: unknown metric 'X' (did you mean 'Y'?); expected one of ..."
// unless `metric` is a sweepNumericMetrics() name.
void requireSweepMetric(const std::string& what, const std::string& metric);

SweepResult runSweep(const SweepOptions& options);

// One point: the scene with base_overrides and KEY=texts[k] applied, run, summarised (used by
// the schedulers of SweepExecution.h and by the optimizer).
SweepPoint runSweepPoint(const SweepOptions& options, const std::vector<std::string>& texts,
                         const std::vector<double>& values);

// The optimum of `metric` over the points that completed, preferring those at steady state, and
// (one numeric parameter, best point inside the grid) the parabola's vertex, predicted, not yet run.
SweepOptimum findOptimum(const std::vector<SweepParameter>& params,
                         const std::vector<SweepPoint>& points, const std::string& metric);

// Takes the run at the vertex into `optimum` (which findOptimum made from `points`): whether it is
// usable by the grid's rules, whether the parabola's prediction holds within the integration
// tolerance (accuracy: simulation.accuracy, relative), and whether it is the optimum.
void judgeVertexRun(SweepOptimum& optimum, const std::vector<SweepPoint>& points, const SweepPoint& run,
                    double accuracy);

// One column of a study's table (sweep.csv, history.csv of optimize): a parameter (key path,
// schema unit), a metric (sweepMetricColumns()) or a text column.
struct StudyColumn {
  std::string name;                // key path or metric name
  std::string unit;                // ASCII unit of the CSV header, e.g. N*m ("" for none)
  bool parameter = false;          // a parameter column: its texts are the values as applied (--set)
  bool is_text = false;            // text cells (status, motion; a parameter with words such as rigid)
  std::vector<double> numbers;     // one per point (NaN where not computed; empty for metric text columns)
  std::vector<std::string> texts;  // one per point for text columns and parameters
};

// sweep.csv as columns, one cell per point in grid order: what writeSweepOutputs writes and the
// Python interface returns as a table.
std::vector<StudyColumn> sweepTable(const SweepOptions& options, const SweepResult& result);

// sweep.json's "optimum": metric, found, note, and where found: at, value, steady_state_reached
// and source (the optimum's run: "grid point" or "run at the parabola's vertex"), index and
// grid_value (the best grid point), parabola {parameter, predicted, run {value, usable, status,
// motion, steady_state_reached, cpu_seconds} | null, holds, run_lower, tolerance, is_optimum,
// refine, note} where the vertex exists; null when no metric was minimised.
nlohmann::json sweepOptimumJson(const SweepOptions& options, const SweepResult& result);

// sweep.csv, sweep.json and the plots (skipped with a note in sweep.json when gnuplot is
// missing or there are more than two parameters). Returns the files written; `plot_note`
// receives why plots are missing ("" when all were drawn), for the console.
std::vector<std::string> writeSweepOutputs(const SweepOptions& options, const SweepResult& result,
                                           const std::string& out_dir, std::string* plot_note = nullptr);

// The optimum for the terminal, e.g. "minimum of delta = 0.151 at crank.offset_deg=90 (steady
// state reached)", then the parabola's vertex: its prediction beside its run's value, and plainly
// when the prediction does not hold.
std::string describeOptimum(const SweepOptions& options, const SweepResult& result);

}  // namespace rollerdyn
