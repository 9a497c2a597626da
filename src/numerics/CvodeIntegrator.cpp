#include "numerics/CvodeIntegrator.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>

#include <cvode/cvode.h>
#include <cvode/cvode_ls.h>
#include <nvector/nvector_serial.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include "numerics/CvodeStepByStep.h"
#include "numerics/EigenSundials.h"

namespace rollerdyn {

namespace {

// One tolerance and one absolute_only flag per state; a Jacobian structure (Newton only) with one
// entry per state and a finite diagonal wherever a column is known.
void checkProblem(const OdeProblem& problem) {
  const int n = int(problem.y0.size());
  if (problem.atol.size() != n || int(problem.absolute_only.size()) != n)
    throw std::invalid_argument("CvodeIntegrator: atol and absolute_only need one entry per state");
  const JacobianStructure& js = problem.jacobian;
  if (!js.given()) return;
  if (!problem.newton)
    throw std::invalid_argument("CvodeIntegrator: a Jacobian structure needs the Newton corrector");
  if (int(js.difference_quotient.size()) != n || js.diagonal.size() != n)
    throw std::invalid_argument("CvodeIntegrator: the Jacobian structure needs one entry per state (" +
                                std::to_string(n) + ")");
  for (int j = 0; j < n; ++j)
    if (!js.difference_quotient[j] && !std::isfinite(js.diagonal(j)))
      throw std::invalid_argument("CvodeIntegrator: known Jacobian column " + std::to_string(j) +
                                  " has a non-finite diagonal");
}

// The method's highest order unless the problem asks for less (std::invalid_argument beyond it,
// or for BDF without the Newton corrector).
int checkedMaxOrder(const OdeProblem& problem) {
  const int highest_order = problem.bdf ? 5 : 12;
  const int max_order = problem.max_order == 0 ? highest_order : problem.max_order;
  if (max_order < 1 || max_order > highest_order)
    throw std::invalid_argument(std::string("CvodeIntegrator: max_order must be 1 ... ") +
                                (problem.bdf ? "5 (BDF)" : "12 (Adams)") + ", got " +
                                std::to_string(problem.max_order));
  if (problem.bdf && !problem.newton)
    throw std::invalid_argument("CvodeIntegrator: BDF needs the Newton corrector (newton = true)");
  return max_order;
}

}  // namespace

struct CvodeIntegrator::Impl {
  OdeProblem problem;
  SUNContext ctx = nullptr;
  N_Vector y = nullptr;
  N_Vector ewt = nullptr;  // CVODE's error weights, copied for the structured Jacobian
  N_Vector scratch = nullptr;  // CVODE's interpolant at a time inside the last step
  void* cv = nullptr;
  SUNMatrix A = nullptr;
  SUNLinearSolver LS = nullptr;
  SUNNonlinearSolver NLS = nullptr;
  Eigen::VectorXd y_out;
  double t = 0;
  double t_failure = 0;  // where the last failed advanceTo gave up
  long rhs_evals = 0;
  long steps_before = 0, jacobians_before = 0, failures_before = 0;  // counted before the last restart
  long error_test_failures_before = 0;
  bool root_found = false;
  CvodeStepByStep stepper;  // with OdeProblem::on_step: the normal mode one step at a time
  double stop_time = 0;
  std::string error;
  std::string rhs_exception;  // what the right-hand side threw, if it did

  // OdeProblem::on_step at a (re)start: ẏ = f(t, y) evaluated here, all NaN where CVODE would
  // not accept it (f not evaluable, or not finite: Impl::rhs).
  void observeStart() {
    if (!problem.on_step) return;
    Eigen::VectorXd yd(y_out.size());
    if (!problem.rhs(t, y_out.data(), yd.data()) || !yd.allFinite())
      yd.setConstant(std::numeric_limits<double>::quiet_NaN());
    problem.on_step(t, y_out.data(), yd.data(), false);
  }
  // OdeProblem::on_step at the end of the internal step just taken (y holds y(t_step)).
  void observeStep(double t_step) {
    if (!scratch) scratch = N_VClone(y);
    if (CVodeGetDky(cv, t_step, 1, scratch) != CV_SUCCESS) N_VConst(std::numeric_limits<double>::quiet_NaN(), scratch);
    // A copy: the observer may call interpolate(), which writes the scratch vector.
    const Eigen::VectorXd yd = Eigen::Map<const Eigen::VectorXd>(NV_DATA_S(scratch), NV_LENGTH_S(scratch));
    problem.on_step(t_step, NV_DATA_S(y), yd.data(), true);
  }
  // The state vector at (t0, y0) and CVODE on it: Adams or BDF, our right-hand side, error
  // handler and error weights. CV_SUCCESS or the first failing flag.
  int createCvode() {
    const int n = int(problem.y0.size());
    if (SUNContext_Create(nullptr, &ctx) != 0) throw std::runtime_error("SUNContext_Create failed");
    y = N_VNew_Serial(n, ctx);
    useEigenVectorOps(y);  // before CVodeInit clones it (EigenSundials.h)
    Eigen::Map<Eigen::VectorXd>(NV_DATA_S(y), n) = problem.y0;
    y_out = problem.y0;
    t = problem.t0;
    cv = CVodeCreate(problem.bdf ? CV_BDF : CV_ADAMS, ctx);
    int flag = CVodeInit(cv, rhs, problem.t0, y);
    if (flag == CV_SUCCESS) flag = CVodeSetUserData(cv, this);
    if (flag == CV_SUCCESS) flag = CVodeSetErrHandlerFn(cv, errHandler, this);
    if (flag == CV_SUCCESS) flag = CVodeWFtolerances(cv, weights);
    return flag;
  }
  // The corrector: Newton with our dense solver (and the structured Jacobian when the problem
  // gives one), or fixed-point iteration. A failed flag passes through, its calls skipped.
  int attachCorrector(int flag) {
    const int n = int(problem.y0.size());
    if (problem.newton) {
      A = SUNDenseMatrix(n, n, ctx);
      LS = makeEigenDenseSolver(n, ctx);
      if (flag == CV_SUCCESS) flag = CVodeSetLinearSolver(cv, LS, A);
      if (problem.jacobian.given()) {
        ewt = N_VClone(y);
        if (flag == CV_SUCCESS) flag = CVodeSetJacFn(cv, jacobian);
      }
    } else {
      NLS = SUNNonlinSol_FixedPoint(y, 0, ctx);
      if (flag == CV_SUCCESS) flag = CVodeSetNonlinearSolver(cv, NLS);
    }
    return flag;
  }
  // The limits: steps, order, stop time and largest step. A failed flag passes through.
  int setLimits(int flag) {
    if (flag == CV_SUCCESS) flag = CVodeSetMaxNumSteps(cv, 1000000);
    const int max_order = checkedMaxOrder(problem);
    if (flag == CV_SUCCESS) flag = CVodeSetMaxOrd(cv, max_order);
    if (flag == CV_SUCCESS) flag = CVodeSetStopTime(cv, problem.stop_time);
    stop_time = problem.stop_time;
    if (flag == CV_SUCCESS && problem.max_step > 0) flag = CVodeSetMaxStep(cv, problem.max_step);
    return flag;
  }
  ~Impl() {
    stepper.release();
    if (cv) CVodeFree(&cv);
    if (NLS) SUNNonlinSolFree(NLS);
    if (LS) SUNLinSolFree(LS);
    if (A) SUNMatDestroy(A);
    if (ewt) N_VDestroy(ewt);
    if (scratch) N_VDestroy(scratch);
    if (y) N_VDestroy(y);
    if (ctx) SUNContext_Free(&ctx);
  }

  static int rhs(realtype t, N_Vector y, N_Vector ydot, void* user) {
    auto* self = static_cast<Impl*>(user);
    ++self->rhs_evals;
    const long n = NV_LENGTH_S(y);
    double* d = NV_DATA_S(ydot);
    // No C++ exception may cross CVODE's C frames: report it as an unrecoverable failure.
    try {
      if (!self->problem.rhs(t, NV_DATA_S(y), d)) return 1;
    } catch (const std::exception& ex) {
      self->rhs_exception = ex.what();
      return -1;
    }
    for (long i = 0; i < n; ++i)
      if (!std::isfinite(d[i])) return 1;  // recoverable: CVODE retries with a smaller step
    return 0;
  }

  // CVODE's weights 1/(rtol·|y_i| + atol_i), except atol_i alone for absolute_only states.
  static int weights(N_Vector y, N_Vector ewt, void* user) {
    auto* self = static_cast<Impl*>(user);
    const OdeProblem& p = self->problem;
    const long n = NV_LENGTH_S(y);
    const double* yv = NV_DATA_S(y);
    double* w = NV_DATA_S(ewt);
    for (long i = 0; i < n; ++i) {
      const double tol = p.absolute_only[i] ? p.atol(i) : p.rtol * std::abs(yv[i]) + p.atol(i);
      if (!(tol > 0.0)) return -1;
      w[i] = 1.0 / tol;
    }
    return 0;
  }

  // The Jacobian of a structured problem (OdeProblem::jacobian): difference-quotient columns
  // exactly as CVODE's own dense one forms them (cvLsDenseDQJac in SUNDIALS' cvode_ls.c), so
  // those columns are the same numbers, and the known columns from the problem.
  //   increment of y_j: max(sqrt(uround)·|y_j|, minInc/ewt_j),
  //   minInc = 1000·|h|·uround·n·‖f(y)‖_WRMS (1 when f(y) = 0).
  static int jacobian(realtype t, N_Vector y, N_Vector fy, SUNMatrix J, void* user, N_Vector tmp1,
                      N_Vector, N_Vector) {
    auto* self = static_cast<Impl*>(user);
    const long n = NV_LENGTH_S(y);
    double h = 0.0;
    if (CVodeGetErrWeights(self->cv, self->ewt) != CV_SUCCESS || !attemptedStep(self->cv, h)) return -1;
    const double uround = std::numeric_limits<double>::epsilon();  // SUNDIALS' UNIT_ROUNDOFF
    const Eigen::Map<const Eigen::VectorXd> f0(NV_DATA_S(fy), n), w(NV_DATA_S(self->ewt), n);
    const double f_norm = std::sqrt((f0.cwiseProduct(w)).squaredNorm() / double(n));
    const double min_inc = f_norm != 0.0 ? 1000.0 * std::abs(h) * uround * double(n) * f_norm : 1.0;
    Eigen::Map<Eigen::MatrixXd> jac(SUNDenseMatrix_Data(J), n, n);  // column-major, like SUNDIALS
    jac.setZero();
    const int flag = differenceQuotientColumns(t, y, fy, tmp1, user, min_inc, jac);
    return flag != 0 ? flag : self->addKnownEntries(t, NV_DATA_S(y), jac);
  }

  // The step h being attempted: CVODE's γ = h·rl1 with rl1 = 1/l1 of the current method.
  static bool attemptedStep(void* cv, double& h) {
    realtype t_cur, gamma, rl1;
    N_Vector y_pred, y_n, f_n, zn1;
    void* data;
    const int got = CVodeGetNonlinearSystemData(cv, &t_cur, &y_pred, &y_n, &f_n, &gamma, &rl1, &zn1, &data);
    if (got != CV_SUCCESS || !(rl1 != 0.0)) return false;
    h = gamma / rl1;
    return true;
  }

  // The columns of the states without a known column, (f(y + inc·e_j) − f(y))/inc, and the
  // known diagonal of the others; 0, or rhs's flag when an evaluation failed.
  static int differenceQuotientColumns(realtype t, N_Vector y, N_Vector fy, N_Vector tmp1, void* user,
                                       double min_inc, Eigen::Map<Eigen::MatrixXd>& jac) {
    auto* self = static_cast<Impl*>(user);
    const JacobianStructure& js = self->problem.jacobian;
    const long n = NV_LENGTH_S(y);
    const double uround = std::numeric_limits<double>::epsilon();
    const Eigen::Map<const Eigen::VectorXd> f0(NV_DATA_S(fy), n), w(NV_DATA_S(self->ewt), n),
        f1(NV_DATA_S(tmp1), n);
    double* yv = NV_DATA_S(y);
    for (long j = 0; j < n; ++j) {
      if (!js.difference_quotient[j]) {
        jac(j, j) = js.diagonal(j);
        continue;
      }
      const double y_saved = yv[j];
      const double inc = std::max(std::sqrt(uround) * std::abs(y_saved), min_inc / w(j));
      yv[j] += inc;
      const int flag = rhs(t, y, tmp1, user);
      yv[j] = y_saved;
      if (flag != 0) return flag;
      const double inc_inv = 1.0 / inc;
      jac.col(j) = inc_inv * f1 - inc_inv * f0;
    }
    return 0;
  }

  // The problem's known off-diagonal entries added to jac: 0, 1 (not evaluable at y, or not
  // finite: CVODE retries with a smaller step) or -1 (it threw).
  int addKnownEntries(realtype t, const double* y, Eigen::Map<Eigen::MatrixXd>& jac) {
    const JacobianStructure& js = problem.jacobian;
    if (!js.known_entries) return 0;
    try {
      if (!js.known_entries(t, y, jac)) return 1;
    } catch (const std::exception& ex) {
      rhs_exception = ex.what();
      return -1;
    }
    return jac.allFinite() ? 0 : 1;
  }

  static int rootFn(realtype t, N_Vector y, realtype* gout, void* user) {
    auto* self = static_cast<Impl*>(user);
    try {
      gout[0] = self->problem.root(t, NV_DATA_S(y));
    } catch (const std::exception& ex) {
      self->rhs_exception = ex.what();
      return -1;
    }
    return std::isfinite(gout[0]) ? 0 : -1;
  }

  static void errHandler(int, const char*, const char* function, char* msg, void* user) {
    static_cast<Impl*>(user)->error = std::string(function ? function : "") + ": " + (msg ? msg : "");
  }
};

CvodeIntegrator::CvodeIntegrator(const OdeProblem& problem) : impl_(new Impl) {
  Impl& m = *impl_;
  m.problem = problem;
  checkProblem(problem);
  int flag = m.createCvode();
  flag = m.attachCorrector(flag);
  flag = m.setLimits(flag);
  if (flag != CV_SUCCESS) throw std::runtime_error("CVODE setup failed: " + m.error);
  m.observeStart();
}

CvodeIntegrator::~CvodeIntegrator() = default;

bool CvodeIntegrator::advanceTo(double t_out) {
  Impl& m = *impl_;
  realtype t_ret = m.t;
  const int flag = m.problem.on_step
                       ? m.stepper.advance(m.cv, t_out, m.y, t_ret, [&m](double t_step) { m.observeStep(t_step); })
                       : CVode(m.cv, t_out, m.y, &t_ret, CV_NORMAL);
  m.root_found = flag == CV_ROOT_RETURN;
  if (flag < 0) {
    m.t_failure = t_ret;
    char* name = CVodeGetReturnFlagName(flag);
    m.error = std::string(name ? name : "?") + " " + m.error +
              (m.rhs_exception.empty() ? "" : " (right-hand side: " + m.rhs_exception + ")");
    std::free(name);
    return false;
  }
  m.t = t_ret;
  m.y_out = Eigen::Map<const Eigen::VectorXd>(NV_DATA_S(m.y), NV_LENGTH_S(m.y));
  return true;
}

bool CvodeIntegrator::rootFound() const { return impl_->root_found; }
double CvodeIntegrator::failureTime() const { return impl_->t_failure; }

void CvodeIntegrator::setStopTime(double t_stop) {
  Impl& m = *impl_;
  m.stop_time = std::min(t_stop, m.problem.stop_time);
  if (CVodeSetStopTime(m.cv, m.stop_time) != CV_SUCCESS) throw std::runtime_error("CVodeSetStopTime failed: " + m.error);
}

void CvodeIntegrator::enableRoot(bool on) {
  Impl& m = *impl_;
  if (on && !m.problem.root) throw std::logic_error("CvodeIntegrator: no event function to enable");
  int flag = CVodeRootInit(m.cv, on ? 1 : 0, on ? Impl::rootFn : nullptr);
  int rising = 1;
  if (flag == CV_SUCCESS && on) flag = CVodeSetRootDirection(m.cv, &rising);
  if (flag == CV_SUCCESS && on) flag = CVodeSetNoInactiveRootWarn(m.cv);
  if (flag != CV_SUCCESS) throw std::runtime_error("CVodeRootInit failed: " + m.error);
}

void CvodeIntegrator::restart(double t, const Eigen::VectorXd& y) {
  Impl& m = *impl_;
  // CVodeReInit zeroes CVODE's counters: keep what they counted so far.
  m.steps_before = steps();
  m.jacobians_before = jacobianEvaluations();
  m.failures_before = newtonConvergenceFailures();
  m.error_test_failures_before = errorTestFailures();
  Eigen::Map<Eigen::VectorXd>(NV_DATA_S(m.y), y.size()) = y;
  int flag = CVodeReInit(m.cv, t, m.y);
  // SUNDIALS 6.4 keeps a stop time once reached; set it again (it must lie ahead of t).
  if (flag == CV_SUCCESS && m.stop_time > t) flag = CVodeSetStopTime(m.cv, m.stop_time);
  if (flag != CV_SUCCESS) throw std::runtime_error("CVodeReInit failed: " + m.error);
  m.t = t;
  m.y_out = y;
  m.root_found = false;
  m.stepper.restarted();
  m.observeStart();
}

double CvodeIntegrator::interpolate(double t, int k, int i) const {
  Impl& m = *impl_;
  if (!m.scratch) m.scratch = N_VClone(m.y);
  return CVodeGetDky(m.cv, t, k, m.scratch) == CV_SUCCESS ? NV_Ith_S(m.scratch, i) : std::nan("");
}

double CvodeIntegrator::time() const { return impl_->t; }
const Eigen::VectorXd& CvodeIntegrator::y() const { return impl_->y_out; }
long CvodeIntegrator::steps() const {
  long n = 0;
  CVodeGetNumSteps(impl_->cv, &n);
  return impl_->steps_before + n;
}
long CvodeIntegrator::errorTestFailures() const {
  long n = 0;
  CVodeGetNumErrTestFails(impl_->cv, &n);
  return impl_->error_test_failures_before + n;
}
long CvodeIntegrator::rhsEvaluations() const { return impl_->rhs_evals; }
long CvodeIntegrator::jacobianEvaluations() const {
  long n = 0;
  if (impl_->LS) CVodeGetNumJacEvals(impl_->cv, &n);
  return impl_->jacobians_before + n;
}
long CvodeIntegrator::newtonConvergenceFailures() const {
  long n = 0;
  CVodeGetNumNonlinSolvConvFails(impl_->cv, &n);
  return impl_->failures_before + n;
}
const std::string& CvodeIntegrator::error() const { return impl_->error; }

}  // namespace rollerdyn
