// CVODE's Adams-Moulton method (orders 1-12, variable step), or its BDF method (orders 1-5) for
// stiff problems, behind a small interface that knows nothing of SUNDIALS: the project's one
// CVODE driver, under both models (the reduced model, ReducedIntegrators.cpp; the multibody
// model's minimal formulation, MinimalSimulation.h) and any other ODE of the project.
//
// Why a separate shared library (CMakeLists.txt, rollerdyn_numerics): Simbody's SimTKmath exports
// the N_Vector functions of its own, older SUNDIALS; the static SUNDIALS 6 archives the project
// uses are therefore linked into this shared library and hidden there (--exclude-libs), and the
// vector operations and the dense LU are Eigen's (EigenSundials.h).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace rollerdyn {

// Structure of the Jacobian ∂f/∂y that the Newton corrector's matrix I - γ·∂f/∂y is built from.
// Empty (the default): CVODE's dense difference quotients over every state, one evaluation of f
// per state. Otherwise one entry per state: difference_quotient[j] true forms column j by a
// difference quotient with CVODE's own increment; false takes column j as known, with
// diagonal(j) on the diagonal and zeros elsewhere (e.g. a first-order lag dz/dt = (x - z)/τ:
// diagonal -1/τ; an integral of powers that do not depend on it: 0).
// Neglected entries only change the iteration matrix, not the equations being solved: the
// corrector still drives the residual of the implicit Adams formula to CVODE's tolerance and the
// local-error test still accepts or rejects each step, so accuracy is unchanged; a poor matrix
// shows as more corrector iterations or convergence failures (counted below).
struct JacobianStructure {
  std::vector<bool> difference_quotient;  // per state: column by difference quotient
  Eigen::VectorXd diagonal;               // per state: the known column's diagonal entry
                                          // [1/s] (read where difference_quotient is false)
  // Optional: adds state-dependent off-diagonal entries of the known columns at (t, y) to jac
  // (n×n, already holding the difference-quotient columns and the diagonal); it must write
  // nothing else. False: cannot be evaluated at y (CVODE then retries with a smaller step).
  std::function<bool(double t, const double* y, Eigen::Ref<Eigen::MatrixXd> jac)> known_entries;
  bool given() const { return !difference_quotient.empty(); }
};

struct OdeProblem {
  // ẏ = f(t, y); returns false when f cannot be evaluated at y (CVODE then retries with a
  // smaller step).
  std::function<bool(double t, const double* y, double* ydot)> rhs;
  double t0 = 0;              // initial time [s]
  double stop_time = 0;       // never integrate past this time [s]
  Eigen::VectorXd y0;         // initial state
  double rtol = 1e-6;         // relative tolerance [-]
  Eigen::VectorXd atol;       // absolute tolerance of each state, in its unit
  std::vector<bool> absolute_only;  // states held to atol alone (angles: an error of 1e-6 rad
                                    // means the same after one turn or a thousand)
  double max_step = 0;        // largest step [s]; 0: unbounded
  int max_order = 0;          // highest order CVODE may use (Adams 1 ... 12, BDF 1 ... 5);
                              // 0: the method's highest [-]
  bool bdf = false;           // backward differentiation formulas instead of Adams-Moulton: for
                              // stiff problems (electrical time constants of milliseconds under a
                              // mechanical motion of seconds); Newton corrector required
  bool newton = true;         // Newton corrector on a dense Jacobian (structure below);
                              // false: fixed-point (functional) iteration
  JacobianStructure jacobian; // Newton only; empty: difference quotients for every column
  // Optional event function: while enabled (CvodeIntegrator::enableRoot), advanceTo stops where
  // g(t, y) crosses zero upwards, located by CVODE's root finding on its interpolant (e.g. a rotor
  // speed reaching a switching speed: g = ω - ω_switch).
  std::function<double(double t, const double* y)> root;
  // Optional observer of the integrator's own steps: called with (t, y, ẏ, after_step) at the
  // initial point and at every restart (after_step false; ẏ = f itself, all NaN where f cannot be
  // evaluated or is not finite) and at the end of every internal step (after_step true; ẏ is the
  // derivative of CVODE's interpolating polynomial, and CvodeIntegrator::interpolate reaches
  // inside the step). advanceTo then steps one internal step at a time and interpolates the output
  // as CVODE's normal mode does: the same steps, the same output, and what happens between output
  // times seen (e.g. analysis/CrankSpeedExtrema.h).
  std::function<void(double t, const double* y, const double* ydot, bool after_step)> on_step;
};

class CvodeIntegrator {
 public:
  explicit CvodeIntegrator(const OdeProblem& problem);  // throws std::runtime_error on setup failure
  ~CvodeIntegrator();
  CvodeIntegrator(const CvodeIntegrator&) = delete;
  CvodeIntegrator& operator=(const CvodeIntegrator&) = delete;

  // Advances to t_out (interpolating within the last step, CVODE's normal mode) and leaves the
  // state at t_out in y(). False on an integrator failure (message in error()).
  bool advanceTo(double t_out);
  // After advanceTo: whether it stopped short of t_out at a zero of the event function.
  bool rootFound() const;
  // After advanceTo returned false: the time CVODE had reached when it gave up [s] (time() stays
  // at the last successful return).
  double failureTime() const;
  // Never integrate past t_stop (<= the problem's stop_time): a discontinuity there (an event of
  // the run) is then never stepped across. advanceTo returns at t_stop when t_out lies beyond.
  void setStopTime(double t_stop);
  // Event function on or off (needs OdeProblem::root).
  void enableRoot(bool on);
  // Continues from (t, y) as from a new initial value (after the run changed y or the equations
  // discontinuously at t): the method restarts at order 1. Counters keep counting.
  void restart(double t, const Eigen::VectorXd& y);
  // CVODE's interpolant of its last step (valid inside it, e.g. from OdeProblem::on_step).
  double interpolate(double t, int k, int i) const;
  double time() const;
  const Eigen::VectorXd& y() const;
  long steps() const;
  long errorTestFailures() const;  // steps rejected by the local error test and retried smaller
  long rhsEvaluations() const;  // including the difference-quotient Jacobian's
  long jacobianEvaluations() const;        // Jacobians formed for the Newton matrix (0: fixed point)
  long newtonConvergenceFailures() const;  // corrector convergence failures
  const std::string& error() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rollerdyn
