// Parameter identification (`rollerdyn identify`): the scene values (coupling stiffness and
// damping, guide friction, a motor parameter, ...) that make the model reproduce measured signals,
// each with its standard uncertainty, their correlations, and warnings where the data cannot tell
// keys apart.
//
// The model runs from the scene's initial state (t = 0) to the last measured time; its output rows
// are interpolated linearly onto the measured times. A candidate is the scene with each free key
// applied as a --set override (validated like a scene file, as sweeps and optimize do). Weighted
// least squares: r_i = (model_s(t_i) − data_s(t_i)) / σ_s per signal s, minimised by
// Levenberg–Marquardt (Levenberg 1944, Marquardt 1963) in scaled parameters (each key mapped to
// [0, 1] by its bounds, logarithmically when the bounds span a factor of 100 or more) with a
// forward-difference Jacobian; σ_s given or estimated (Identify.cpp, docs/identify.md). At the
// optimum: central-difference Jacobian J in scene units, σ̂² = RSS/(N − p),
// Cov = σ̂²·(JᵀJ)⁻¹, standard uncertainties and the correlation matrix. The fit uses the first
// (1 − holdout) of the measured span; the rest is predicted and its error reported.
#pragma once

#include <atomic>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "scene/SceneParser.h"
#include "studies/MeasuredData.h"

namespace rollerdyn {

struct IdentifyOptions {
  std::string scene_path;                          // the scene file (names it in the outputs)
  std::shared_ptr<const SceneInput> scene_input;   // the scene in memory (Python); else scene_path is read
  std::vector<std::string> base_overrides;         // --set applied to every run, before the free keys
  MeasuredData data;                               // the measurements
  std::vector<std::string> signals;                // the measured columns to fit; empty: every one in the data
  std::vector<std::string> free_keys;              // scene keys to identify (Number keys)
  std::map<std::string, std::pair<double, double>> bounds;  // key -> (lower, upper) [key's unit]; else the schema's range
  std::map<std::string, double> noise;             // signal -> σ [signal's unit]; others estimated
  std::string model = "multibody";                 // multibody | reduced
  double holdout = 0.3;                            // fraction of the span predicted, not fitted [-]; 0: none
  bool global = false;                             // a global search (NLopt DIRECT-L) before Levenberg–Marquardt
  int max_iterations = 30;                         // Levenberg–Marquardt iterations per fit at most
  int threads = 2;                                 // runs of one Jacobian side by side
  // Integrator accuracy of every run [-]: the scene's simulation.accuracy unless tighter; 0: 1e-8
  // (the finite differences need the integration's noise far below a 1e-3 relative change, Identify.cpp).
  double accuracy = 0;
  const std::atomic<bool>* interrupt = nullptr;    // stops between runs (and inside multibody runs)
  std::function<void(const std::string& line)> on_progress;  // one line per iteration, for the console
};

struct IdentifiedKey {
  std::string key;          // scene key path, e.g. coupling.stiffness
  std::string unit;         // the key's unit (schema), e.g. N·m/rad
  double lower = 0, upper = 0;  // bounds of the search [unit]
  std::string bounds_from;  // "--bounds" or "schema"
  bool log_scale = false;   // searched in log(value): the bounds span a factor >= 100
  double start = 0;         // starting value: the scene's value (or the middle of the bounds) [unit]
  double value = 0;         // estimate [unit]
  std::string text;         // the estimate as applied (--set), 12 significant digits
  double std = 0;           // standard uncertainty [unit] (infinite when the data do not determine it)
  double relative_std = 0;  // std / |value| [-]
  bool at_bound = false;    // the estimate lies on a bound (its std then means little)
};

struct SignalFit {
  std::string name;          // column, e.g. omega_crank
  std::string unit;          // its unit
  double sigma = 0;          // σ_s of the final fit [unit]
  std::string sigma_from;    // "given" or "estimated" (RMS residual of the first fit)
  std::size_t samples_fit = 0, samples_holdout = 0;  // samples in the fitted part and the held-out part
  double rms_fit = 0;        // RMS of model − data over the fitted part [unit]
  double rms_holdout = 0;    // the same over the held-out part [unit] (NaN without one)
  double data_rms = 0;       // RMS of the data's deviation from its mean over the whole span [unit]
  double integration_error = std::numeric_limits<double>::quiet_NaN();  // RMS of the run at the estimate
                             // minus the same run at 1/100 of the accuracy [unit]: the integration's own error
};

struct IdentifyWarning {
  std::string kind;               // correlated | undetermined | weak_direction | at_bound | integration | holdout
  std::vector<std::string> keys;  // the keys concerned
  double value = 0;               // correlation (correlated), relative std (undetermined), the bound (at_bound)
  std::string text;               // the warning in words for the console and the JSON
};

struct IdentifyResult {
  std::string scene;                      // the scene as named
  std::string model;                      // multibody | reduced
  std::string data_file;                  // the measurements' file
  std::vector<IdentifiedKey> keys;        // per free key, in the order given
  std::vector<SignalFit> signals;         // per measured signal, in file order
  std::vector<std::vector<double>> correlation;  // p×p correlation matrix of the estimates [-]
  std::vector<double> weakest_direction;  // unit vector over the keys (scaled by their std) of JᵀJ's
                                          // smallest singular value: the combination the data determine worst
  double condition = 0;                   // largest / smallest singular value of J with columns normalised [-]
  std::size_t residuals = 0;              // N, weighted residuals of the fit
  double rss = 0;                         // Σ r_i² at the optimum (weighted) [-]
  double sigma_hat2 = 0;                  // RSS/(N − p) [-]: 1 when the σ_s describe the residuals
  double t_fit_end = 0;                   // end of the fitted part of the span [s]
  double t_end = 0;                       // last measured time [s]
  bool converged = false;                 // Levenberg–Marquardt stopped on a small step or cost change
  std::string convergence;                // why it stopped, in words
  int iterations = 0;                     // Levenberg–Marquardt iterations (both fits)
  int runs = 0;                           // model runs in all
  int failed_runs = 0;                    // runs that failed or did not reach the end of the span
  double accuracy = 0;                    // integrator accuracy of the runs [-]
  double output_step = 0;                 // output step of the runs [s]
  double wall_seconds = 0;                // wall time of the identification [s]
  std::vector<IdentifyWarning> warnings;  // correlated pairs, undetermined keys, estimates on a bound
  // The run at the estimate over the whole span on the measured times (figures, Python).
  std::vector<double> t;                          // measured times [s]
  std::vector<std::vector<double>> data_values;   // per signal, the measured values at t [signal's unit]
  std::vector<std::vector<double>> model_values;  // per signal, the model at t [signal's unit]
};

// Throws std::invalid_argument for an unknown key or model, a key without bounds, bad bounds, a
// σ for a signal not measured, a --signals column not in the data, a measured column the model does not write (naming the data file
// and the column), or a holdout outside [0, 0.9]; a run that fails during the search counts as a
// rejected step, and a search that cannot go on is reported as not converged with the reason.
IdentifyResult runIdentify(const IdentifyOptions& options);

}  // namespace rollerdyn
