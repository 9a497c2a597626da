// CVODE's Adams-Moulton method (orders 1-12, variable step) behind a small interface that
// knows nothing of SUNDIALS, for the multibody model's minimal formulation
// (MinimalSimulation.h).
//
// Why a separate shared library (CMakeLists.txt, rollerdyn_cvode): Simbody's SimTKmath exports
// the N_Vector functions of its own, older SUNDIALS; the static SUNDIALS 6 archives the project
// uses are therefore linked into a shared library and hidden there (--exclude-libs), exactly as
// for the reduced model, and the vector operations are Eigen's (reduced/EigenSundials.h).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace rollerdyn {

struct AdamsProblem {
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
  bool newton = true;         // Newton corrector on a dense difference-quotient Jacobian;
                              // false: fixed-point (functional) iteration
};

class AdamsIntegrator {
 public:
  explicit AdamsIntegrator(const AdamsProblem& problem);  // throws std::runtime_error on setup failure
  ~AdamsIntegrator();
  AdamsIntegrator(const AdamsIntegrator&) = delete;
  AdamsIntegrator& operator=(const AdamsIntegrator&) = delete;

  // Advances to t_out (interpolating within the last step, CVODE's normal mode) and leaves the
  // state at t_out in y(). False on an integrator failure (message in error()).
  bool advanceTo(double t_out);
  double time() const;
  const Eigen::VectorXd& y() const;
  long steps() const;
  long rhsEvaluations() const;  // including the difference-quotient Jacobian's
  long jacobianEvaluations() const;        // Jacobians formed for the Newton matrix (0: fixed point)
  long newtonConvergenceFailures() const;  // corrector convergence failures
  const std::string& error() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rollerdyn
