// Flow of a periodic system of ODEs over one period, with its monodromy matrix, and the periodic
// orbit (fixed point of the period map) found by Newton's method on it: the numerical core of the
// Floquet analysis (Floquet.h). Nothing here knows about drives: the Mathieu equation of the
// tests and the drive of DriveOrbit.h feed the same code.
//
//   dx/ds = f(s, x),  f(s + S, x) = f(s, x),  x ∈ R^n
//   variational equations  dΦ/ds = A(s)·Φ,  A = ∂f/∂x along the solution,  Φ(0) = I
//   monodromy  Φ(S): the linearized period map; its eigenvalues are the Floquet multipliers.
//
// Integration: Dormand-Prince 5(4) with local error control on x and Φ together (an explicit
// method: the systems here have a few states and are not stiff; the period is known). A is
// supplied by the system or formed by central differences of f (steps 1e-6 of each state's
// scale: truncation ~1e-12·f''', round-off ~1e-10·|f|, both far below the 1e-8 integration
// tolerance). Quadratures (states that grow, e.g. time along a crank revolution) ride along
// without entering the variational equations or the periodicity condition.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace rollerdyn::modes {

struct PeriodicSystem {
  int n = 0;            // periodic states
  int quadratures = 0;  // extra states integrated alongside (their own f), not periodic
  double period = 0;    // S, in the independent variable s
  // f(s, x) for the n states followed by the quadratures' rates; x has n + quadratures entries.
  std::function<void(double s, const Eigen::VectorXd& x, Eigen::VectorXd& f)> rhs;
  // Optional exact A(s, x) = ∂f/∂x (n×n, periodic states only); central differences otherwise.
  std::function<void(double s, const Eigen::VectorXd& x, Eigen::MatrixXd& A)> jacobian;
  Eigen::VectorXd scale;  // typical magnitude of each periodic state (absolute tolerance, FD steps)
};

struct FlowOptions {
  double rtol = 1e-9;       // relative local error per step
  double atol_scale = 1e-9; // absolute tolerance = atol_scale·scale_i (Φ: atol_scale)
  int max_steps = 200000;
  bool monodromy = true;    // integrate the variational equations too
  int samples = 0;          // > 0: also return x at `samples` equally spaced s in [0, S) (dense output)
};

struct FlowResult {
  bool ok = false;
  std::string failure;           // why not ok
  Eigen::VectorXd x_end;         // x(S) (periodic states and quadratures)
  Eigen::MatrixXd monodromy;     // Φ(S) (n×n) when asked
  long steps = 0, rejected = 0, evaluations = 0;
  std::vector<double> s_samples;           // when samples > 0
  std::vector<Eigen::VectorXd> x_samples;  // periodic states and quadratures at s_samples
};

// Integrates from s = 0 over one period.
FlowResult flowOverPeriod(const PeriodicSystem& sys, const Eigen::VectorXd& x0, const FlowOptions& o = {});

struct OrbitOptions {
  FlowOptions flow;
  int max_newton = 30;
  double tolerance = 1e-10;   // on max_i |x(S) - x(0)|_i / scale_i
  int warmup_periods = 0;     // plain periods integrated before Newton (pull a rough guess in)
  // Accepted as converged when no Newton step lowers the residual any more and it is below this
  // (the period map is only known to the integration tolerance).
  double accept_stagnation = 1e-6;
};

struct PeriodicOrbit {
  bool found = false;
  std::string failure;
  Eigen::VectorXd x0;            // periodic states at s = 0 (quadratures start at 0)
  Eigen::MatrixXd monodromy;     // at the orbit
  Eigen::VectorXd quadratures;   // their values after one period
  int newton_iterations = 0;
  long evaluations = 0;          // right-hand sides, all flows together
  double residual = 0;           // final scaled periodicity error
  std::vector<double> s_samples;
  std::vector<Eigen::VectorXd> x_samples;
};

// Newton's method on x(S; x0) - x0 = 0 with the Jacobian Φ(S) - I, damped by halving when the
// residual grows; then, when samples are asked for, one more flow at the solution for them (without
// samples the monodromy is the last Newton flow's, which started at the solution).
PeriodicOrbit findPeriodicOrbit(const PeriodicSystem& sys, const Eigen::VectorXd& guess, const OrbitOptions& o = {});

}  // namespace rollerdyn::modes
