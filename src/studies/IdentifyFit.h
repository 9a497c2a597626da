// The numerics of `rollerdyn identify` on any residual function, apart from the model runs
// (Identify.cpp): Levenberg–Marquardt in scaled parameters (Levenberg 1944, Marquardt 1963; the
// damping λ·diag(JᵀJ) of Marquardt, box [0, 1] by projection of each step), the global search
// that can start it, and the covariance of a weighted least-squares estimate, σ̂²·(JᵀJ)⁻¹ with
// σ̂² = RSS/(N − p).
#pragma once

#include <atomic>
#include <functional>
#include <string>
#include <vector>

namespace rollerdyn {

// The residuals at one point, or why there are none.
struct ResidualEvaluation {
  bool ok = false;           // the model ran to the end of the span
  std::vector<double> r;     // weighted residuals (ok only) [-]
  std::string reason;        // why not ok
};

// Evaluates a batch of points (each a vector of scaled parameters in [0, 1]); the points of a
// Jacobian come as one batch so that they can run side by side.
using ResidualBatch = std::function<std::vector<ResidualEvaluation>(const std::vector<std::vector<double>>& points)>;

struct LmSettings {
  int max_iterations = 30;          // iterations at most (each: one Jacobian, then up to 8 trial steps)
  std::vector<double> fd_step;      // forward-difference step per parameter, in scaled units [-]
  // Stop when the cost falls (or the Gauss–Newton step would let it fall) by less than this
  // fraction of σ̂² = cost/(N − p): a change of χ² by 1e-4 moves an estimate by about 1e-2 of its
  // standard uncertainty, far below what it is known to.
  double cost_tolerance = 1e-4;
  double step_tolerance = 1e-9;     // or when a step moves no scaled parameter by more than this [-]
  const std::atomic<bool>* interrupt = nullptr;
  // After each accepted step: iteration, cost, the scaled parameters.
  std::function<void(int iteration, double cost, const std::vector<double>& u)> on_iteration;
};

struct LmOutcome {
  std::vector<double> u;        // scaled parameters at the end [-]
  std::vector<double> r;        // residuals there
  double cost = 0;              // Σ r² there
  int iterations = 0;           // Jacobians formed
  bool converged = false;
  std::string reason;           // why it stopped, in words
};

// Levenberg–Marquardt from u0 within [0, 1]^p. A point whose evaluation fails counts as a step
// that raised the cost (λ grows); a failure at u0, a Jacobian point that fails on both sides, an
// interrupt or the iteration limit end the search as not converged, with the reason.
LmOutcome levenbergMarquardt(const ResidualBatch& evaluate, const std::vector<double>& u0, const LmSettings& settings);

// The global stage: DIRECT-L (Gablonsky and Kelley 2001) over [0, 1]^p, 30 runs per parameter;
// its best point (u0 when nothing beats it) starts Levenberg–Marquardt. An interrupt or a failure
// inside NLopt ends it with the best point so far.
std::vector<double> globalStart(const ResidualBatch& evaluate, const std::vector<double>& u0,
                                const std::atomic<bool>* interrupt);

// The covariance of the estimate from J (N×p, row-major: J[i][k] = ∂r_i/∂x_k in the keys' own
// units) and the residual sum of squares.
struct CovarianceEstimate {
  double sigma_hat2 = 0;                         // RSS/(N − p) [-]
  std::vector<double> std;                       // standard uncertainty per key [key's unit]; inf where undetermined
  std::vector<std::vector<double>> correlation;  // p×p [-]; NaN in the rows of keys without effect
  std::vector<bool> no_effect;                   // the residuals do not change with the key (zero column)
  double condition = 0;                          // √(λ_max/λ_min) of JᵀJ with unit diagonal [-]
  bool singular = false;                         // a key without effect, or λ_min ≤ 1e-12·λ_max
  // The unit vector v over relative changes Δx_k/scale_k that changes the residuals least
  // (smallest eigenvalue of JᵀJ in those units): the combination the data determine worst.
  std::vector<double> weakest_direction;
};
// `scale`: per key, the size that makes a relative change (the value, or its range at 0).
CovarianceEstimate estimateCovariance(const std::vector<std::vector<double>>& J, double rss,
                                      const std::vector<double>& scale);

}  // namespace rollerdyn
