#include "numerics/EigenSundials.h"

#include <cmath>
#include <new>

#include <Eigen/Dense>
#include <sunmatrix/sunmatrix_dense.h>

namespace rollerdyn {
namespace {

using Vec = Eigen::Map<Eigen::VectorXd>;

Vec map(N_Vector v) { return Vec(NV_DATA_S(v), NV_LENGTH_S(v)); }

void linearSum(realtype a, N_Vector x, realtype b, N_Vector y, N_Vector z) {
  map(z) = a * map(x) + b * map(y);  // z may alias x or y: Eigen evaluates element-wise
}
void constant(realtype c, N_Vector z) { map(z).setConstant(c); }
void scale(realtype c, N_Vector x, N_Vector z) { map(z) = c * map(x); }
realtype wSqrSumLocal(N_Vector x, N_Vector w) { return map(x).cwiseProduct(map(w)).squaredNorm(); }
realtype wrmsNorm(N_Vector x, N_Vector w) {
  return std::sqrt(wSqrSumLocal(x, w) / realtype(NV_LENGTH_S(x)));
}

// ---------------------------------------------------------------------------------------------
// Dense direct solver

struct DenseLu {
  Eigen::PartialPivLU<Eigen::MatrixXd> lu;
  sunindextype last_flag = SUNLS_SUCCESS;
};

DenseLu* content(SUNLinearSolver S) { return static_cast<DenseLu*>(S->content); }

SUNLinearSolver_Type type(SUNLinearSolver) { return SUNLINEARSOLVER_DIRECT; }
SUNLinearSolver_ID id(SUNLinearSolver) { return SUNLINEARSOLVER_CUSTOM; }

int setup(SUNLinearSolver S, SUNMatrix A) {
  const sunindextype n = SM_ROWS_D(A);
  const Eigen::Map<const Eigen::MatrixXd> M(SM_DATA_D(A), n, SM_COLUMNS_D(A));  // column-major
  DenseLu* c = content(S);
  c->lu.compute(M);
  // PartialPivLU does not report singularity; a zero pivot makes the iteration matrix
  // unusable, which CVODE treats as recoverable (it retries with a smaller step).
  const double pivot_min = c->lu.matrixLU().diagonal().cwiseAbs().minCoeff();
  c->last_flag = (pivot_min == 0.0 || !std::isfinite(pivot_min)) ? SUNLS_LUFACT_FAIL : SUNLS_SUCCESS;
  return int(c->last_flag);
}

int solve(SUNLinearSolver S, SUNMatrix, N_Vector x, N_Vector b, realtype) {
  map(x) = content(S)->lu.solve(map(b));
  return SUNLS_SUCCESS;
}

sunindextype lastFlag(SUNLinearSolver S) { return content(S)->last_flag; }

int freeSolver(SUNLinearSolver S) {
  if (!S) return SUNLS_SUCCESS;
  delete content(S);
  S->content = nullptr;
  SUNLinSolFreeEmpty(S);
  return SUNLS_SUCCESS;
}

}  // namespace

void useEigenVectorOps(N_Vector v) {
  v->ops->nvlinearsum = linearSum;
  v->ops->nvconst = constant;
  v->ops->nvscale = scale;
  v->ops->nvwrmsnorm = wrmsNorm;
  v->ops->nvwsqrsumlocal = wSqrSumLocal;
}

SUNLinearSolver makeEigenDenseSolver(int n, SUNContext ctx) {
  SUNLinearSolver S = SUNLinSolNewEmpty(ctx);
  if (!S) throw std::bad_alloc();
  S->ops->gettype = type;
  S->ops->getid = id;
  S->ops->setup = setup;
  S->ops->solve = solve;
  S->ops->lastflag = lastFlag;
  S->ops->free = freeSolver;
  auto* c = new DenseLu;
  c->lu = Eigen::PartialPivLU<Eigen::MatrixXd>(n);
  S->content = c;
  return S;
}

}  // namespace rollerdyn
