// One bounded, measured run of either model for `rollerdyn bench`: a solver setting
// applied to a scene, a CPU-time budget that turns a slow combination into a "timeout" row
// instead of a hang, repeated timing (median), and the error of a run against a reference run
// of the same model.
//
// Error measure (the one every bench table reports): over the output rows both runs share
// (same time t, both tables use the scene's simulation.output_step grid),
//   error_X = max_i |X_i - X_ref,i| / max_i |X_ref,i|,
// X = omega_crank (crank speed φ̇2, rad/s) or coupling_torque (N·m at the crank axis,
// RunResult.h). It is a relative error against the signal's own scale, so 1e-6 means "one
// millionth of the largest crank speed / coupling torque of the reference run".
#pragma once

#include <atomic>
#include <string>
#include <vector>

#include "analysis/RunResult.h"
#include "scene/Scene.h"

namespace rollerdyn::bench {

// The multibody model in its minimal formulation (simulation.formulation = minimal) is a model
// of its own in bench tables, with its one integrator.
constexpr const char* kMultibodyMinimal = "multibody-minimal";
constexpr const char* kMinimalIntegrator = "cvode-adams";

// One solver setting of one model.
struct SolverSetting {
  std::string model;          // "multibody" (constrained formulation) | "multibody-minimal" | "reduced"
  std::string integrator;     // Simbody name (integratorNames()) | "cvode" | "baranov"
  double accuracy = 0;        // relative accuracy (multibody, cvode); 0 for baranov
  double baranov_step = 0;    // crank-angle step of the Baranov scheme [rad]; 0 otherwise
  std::string label() const;  // e.g. "multibody RungeKuttaMerson 1e-06", "reduced baranov 1 deg"
};

// How a bench run ended.
enum class Outcome {
  Ok,           // reached t_end
  Stalled,      // the model reported "motor stalled" (physical end of the run, still comparable)
  Timeout,      // CPU budget exceeded: stopped through RunControl.interrupt
  Failed,       // integrator failure, non-finite values, or an exception (scene rejected, ...)
  Interrupted,  // the user pressed Ctrl-C
};
const char* toString(Outcome o);

struct Measurement {
  SolverSetting setting;
  Outcome outcome = Outcome::Failed;
  std::string status;         // the run's own status line or the exception text
  int repeats = 0;            // timed repetitions that finished (median over these)
  double cpu_seconds = 0;     // median process CPU time of the integration [s] (RunStats); a run
                              // under 0.2 s is timed as the mean of back-to-back repetitions
                              // filling 0.2 s (CPU time is accounted in ms ticks)
  double cpu_min = 0, cpu_max = 0;
  double cpu_with_setup = 0;  // median process CPU of building the model and running it [s]
  long steps = 0, realizations = 0;
  double simulated_time = 0;  // time reached [s]
  double real_time_factor = 0;  // simulated_time / cpu_seconds [-]
  double energy_residual_rel = 0;
  double constraint_error_max = 0;
  RunResult run;              // of the first repetition (tables used for errors)
};

// The scene with the setting applied: formulation (multibody; the constrained one with the lagged
// guide-friction law, the only one it can carry), integrator, accuracy and constraint tolerance
// (= accuracy, the scene schema's own default), reduced.integrator and baranov_step.
Scene applySetting(const Scene& base, const SolverSetting& setting);

struct Budget {
  double cpu_seconds = 20;                          // per repetition
  const std::atomic<bool>* interrupt = nullptr;     // Ctrl-C of the caller
};

// Runs `setting` on `scene` up to `repeats` times (only repeated while the run succeeds) and
// reports the median CPU time. Never throws for a run that fails: the exception text goes into
// status with outcome Failed. Bounded twice: the multibody model checks its CPU time in
// RunControl.progress (after every output row) and sets RunControl.interrupt (a graceful stop
// that keeps the time reached); and every repetition runs in a fork()ed child process under a
// hard CPU limit of 1.5·budget + 2 s (RLIMIT_CPU), which also stops an integrator stuck inside
// one output interval and the reduced model (which has no progress hook), and contains crashes.
// Either way the row reads "timeout" (or "failed" for a crash), never a hang.
Measurement measure(const Scene& scene, const SolverSetting& setting, const Budget& budget,
                    int repeats = 1);

// max_i |X_i - X_ref,i| / max_i |X_ref,i| over the rows of `run` whose time equals a row of
// `ref` (to 1e-9 s). NaN when the column is missing in either table, no rows match, or the
// reference is identically zero.
double relativeMaxError(const Table& run, const Table& ref, const std::string& column);

// max_i |X_i - X_ref,i| over the same rows [unit of X]; NaN as above.
double absoluteMaxError(const Table& run, const Table& ref, const std::string& column);

// Median of a non-empty list (mean of the two middle values for an even count).
double median(std::vector<double> v);

}  // namespace rollerdyn::bench
