#include "studies/IdentifyFit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include <Eigen/Dense>
#include <nlopt.hpp>

namespace rollerdyn {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double sumOfSquares(const std::vector<double>& r) {
  double s = 0;
  for (double v : r) s += v * v;
  return s;
}

std::string text(double v) {
  std::ostringstream o;
  o << v;
  return o.str();
}

bool interrupted(const LmSettings& s) { return s.interrupt && s.interrupt->load(); }

// A forward step of key k that failed, taken backwards (h[k] flips sign) when that stays in [0, 1].
// False (with the reason) when it does not or fails too.
bool stepToTheOtherSide(const ResidualBatch& evaluate, const std::vector<double>& u, std::size_t k,
                        std::vector<double>& h, ResidualEvaluation& e, std::string* reason) {
  std::vector<double> v = u;
  h[k] = -h[k];
  v[k] += h[k];
  if (v[k] < 0.0 || v[k] > 1.0) {
    *reason = "the run beside the current point failed: " + e.reason;
    return false;
  }
  e = evaluate({v})[0];
  if (!e.ok) {
    *reason = "the runs on both sides of the current point failed: " + e.reason;
    return false;
  }
  return true;
}

// Forward-difference Jacobian (N×p) at u; a step that leaves [0, 1] or fails is taken backwards.
// False (with the reason) when a column cannot be formed.
bool jacobian(const ResidualBatch& evaluate, const std::vector<double>& u, const std::vector<double>& r,
              const std::vector<double>& step, Eigen::MatrixXd* J, std::string* reason) {
  const std::size_t p = u.size();
  std::vector<std::vector<double>> points;
  std::vector<double> h(p);
  for (std::size_t k = 0; k < p; ++k) {
    h[k] = u[k] + step[k] <= 1.0 ? step[k] : -step[k];
    std::vector<double> v = u;
    v[k] += h[k];
    points.push_back(v);
  }
  std::vector<ResidualEvaluation> e = evaluate(points);
  J->resize(static_cast<Eigen::Index>(r.size()), static_cast<Eigen::Index>(p));
  for (std::size_t k = 0; k < p; ++k) {
    if (!e[k].ok && !stepToTheOtherSide(evaluate, u, k, h, e[k], reason)) return false;
    for (std::size_t i = 0; i < r.size(); ++i) (*J)(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)) = (e[k].r[i] - r[i]) / h[k];
  }
  return true;
}

Eigen::VectorXd asVector(const std::vector<double>& v) {
  return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
}

// How an iteration's damped steps ended: one lowered the cost, none did, or the fit ends here
// (converged or interrupted: out.reason says which).
enum class DampedStep { Lowered, NoneLowered, Finished };

// The point the damped normal equations (A + λ·diag D)·δ = −g lead to, clamped to [0, 1]; `step` the
// largest change of a key.
std::vector<double> dampedTrial(const Eigen::MatrixXd& A, const Eigen::VectorXd& g, const Eigen::VectorXd& D,
                                double lambda, const std::vector<double>& u, double* step) {
  Eigen::MatrixXd M = A;
  M.diagonal() += lambda * D;
  const Eigen::VectorXd delta = M.ldlt().solve(-g);
  std::vector<double> trial(u.size());
  *step = 0;
  for (std::size_t k = 0; k < u.size(); ++k) {
    trial[k] = std::clamp(u[k] + delta(static_cast<Eigen::Index>(k)), 0.0, 1.0);
    *step = std::max(*step, std::abs(trial[k] - u[k]));
  }
  return trial;
}

// A trial that lowered the cost becomes the estimate; false when the fall is below the tolerance
// (converged, out.reason says so).
bool takeLowerCost(const LmSettings& s, const std::vector<double>& trial, const ResidualEvaluation& e, double cost,
                   double sigma2, int it, LmOutcome& out) {
  const double fall = out.cost - cost;
  out.u = trial;
  out.r = e.r;
  out.cost = cost;
  if (s.on_iteration) s.on_iteration(it, cost, out.u);
  if (!(fall < s.cost_tolerance * sigma2)) return true;
  out.converged = true;
  out.reason = "converged: the cost fell by less than " + text(s.cost_tolerance) + "·σ̂² (iteration " +
               std::to_string(it) + ")";
  return false;
}

// Whether the damped step (in fractions of the keys' bounds) is below the step tolerance: then the
// estimate has converged, and out says so.
bool stepConverged(double step, const LmSettings& s, int it, LmOutcome& out) {
  if (step > s.step_tolerance) return false;
  out.converged = true;
  out.reason = "converged: the step moved no key by more than " + text(s.step_tolerance) +
               " of its bounds (iteration " + std::to_string(it) + ")";
  return true;
}

// Up to eight steps of the damped normal equations (A + λ·diag D)·δ = −g, λ raised after each that
// does not lower the cost and lowered after the one that does, which is taken into out.
DampedStep dampedStep(const ResidualBatch& evaluate, const LmSettings& s, const Eigen::MatrixXd& A,
                      const Eigen::VectorXd& g, const Eigen::VectorXd& D, double sigma2, int it, double& lambda,
                      LmOutcome& out) {
  bool accepted = false;
  for (int tries = 0; tries < 8 && !accepted; ++tries) {
    if (interrupted(s)) {
      out.reason = "interrupted";
      return DampedStep::Finished;
    }
    double step = 0;
    const std::vector<double> trial = dampedTrial(A, g, D, lambda, out.u, &step);
    if (stepConverged(step, s, it, out)) return DampedStep::Finished;
    const ResidualEvaluation e = evaluate({trial})[0];
    const double cost = e.ok ? sumOfSquares(e.r) : kInf;
    if (e.ok && cost < out.cost) {
      accepted = true;
      lambda = std::max(lambda / 3.0, 1e-9);
      if (!takeLowerCost(s, trial, e, cost, sigma2, it, out)) return DampedStep::Finished;
    } else {
      lambda *= e.ok ? 4.0 : 10.0;
    }
  }
  return accepted ? DampedStep::Lowered : DampedStep::NoneLowered;
}

// No step lowered the cost: converged or not by how far the undamped step would move the estimate.
void flatCostVerdict(double predicted, double sigma2, int it, LmOutcome& out) {
  // The cost is flat within the integration's own noise (or the runs beside the point fail).
  // The undamped step, measured in standard uncertainties of the estimate (√(gᵀA⁻¹g/σ̂²)),
  // says whether that matters: below 0.3 the estimate is settled well within what it is known to
  // (data with noise near the integration's own, e.g. a noise-free record of a model run, end here).
  const double shift = std::sqrt(std::max(predicted, 0.0) / sigma2);
  std::ostringstream why;
  why << "no step lowered the cost in 8 tries (the cost is flat within the integration's noise); the "
         "Gauss-Newton step would move the estimate by "
      << text(shift) << " of its standard uncertainty";
  out.converged = shift < 0.3;
  out.reason = (out.converged ? "converged within the integration's noise: " : "") + why.str() +
               (out.converged ? "" : "; tighten --accuracy or check the runs near the estimate") + " (iteration " +
               std::to_string(it) + ")";
}

// The normal equations of one iteration: A = JᵀJ, g = Jᵀr, and the damping's scale D (A's
// diagonal, each at least 1e-12 of its largest, dmax).
struct NormalEquations {
  Eigen::MatrixXd A;
  Eigen::VectorXd g;
  Eigen::VectorXd D;
  double dmax = 0;
};

NormalEquations normalEquations(const Eigen::MatrixXd& J, const std::vector<double>& residuals) {
  NormalEquations n;
  const Eigen::VectorXd r = asVector(residuals);
  n.A = J.transpose() * J;
  n.g = J.transpose() * r;
  n.D = n.A.diagonal();
  n.dmax = n.D.maxCoeff();
  if (!(n.dmax > 0)) return n;
  for (Eigen::Index k = 0; k < n.D.size(); ++k) n.D(k) = std::max(n.D(k), 1e-12 * n.dmax);
  return n;
}

// Predicted fall of the cost by the undamped (Gauss–Newton) step: gᵀA⁻¹g.
double gaussNewtonFall(const NormalEquations& n) {
  const Eigen::MatrixXd& A = n.A;
  const Eigen::VectorXd gn = (A + 1e-12 * n.dmax * Eigen::MatrixXd::Identity(A.rows(), A.cols())).ldlt().solve(-n.g);
  return -n.g.dot(gn);
}

// One search: the outcome so far, the damping λ and the residuals' degrees of freedom.
class LmSearch {
 public:
  LmSearch(const ResidualBatch& evaluate, const LmSettings& s) : evaluate_(evaluate), s_(s) {}

  // The run at the starting values; false when it failed.
  bool start(const std::vector<double>& u0) {
    out.u = u0;
    ResidualEvaluation start = evaluate_({u0})[0];
    if (!start.ok) {
      out.reason = "the run at the starting values failed: " + start.reason;
      return false;
    }
    out.r = start.r;
    out.cost = sumOfSquares(out.r);
    dof_ = std::max<double>(1.0, static_cast<double>(out.r.size()) - static_cast<double>(u0.size()));
    return true;
  }

  // Iteration `it`: a Jacobian, the normal equations and the damped steps; false when the search
  // ends here (out.reason says why).
  bool iterate(int it) {
    if (interrupted(s_)) {
      out.reason = "interrupted";
      return false;
    }
    Eigen::MatrixXd J;
    if (!jacobian(evaluate_, out.u, out.r, s_.fd_step, &J, &out.reason)) return false;
    out.iterations = it;
    const NormalEquations n = normalEquations(J, out.r);
    if (!(n.dmax > 0)) {
      out.reason = "the residuals do not change with any free key (the Jacobian is zero)";
      return false;
    }
    const double sigma2 = std::max(out.cost / dof_, std::numeric_limits<double>::min());
    const double predicted = gaussNewtonFall(n);
    if (std::isfinite(predicted) && predicted < s_.cost_tolerance * sigma2) {
      out.converged = true;
      out.reason = "converged: the next step would lower the cost by less than " + text(s_.cost_tolerance) +
                   "·σ̂² (iteration " + std::to_string(it) + ")";
      return false;
    }
    const DampedStep step = dampedStep(evaluate_, s_, n.A, n.g, n.D, sigma2, it, lambda_, out);
    if (step == DampedStep::NoneLowered) flatCostVerdict(predicted, sigma2, it, out);
    return step == DampedStep::Lowered;
  }

  LmOutcome out;

 private:
  const ResidualBatch& evaluate_;
  const LmSettings& s_;
  double dof_ = 1.0;
  double lambda_ = 1e-3;
};

}  // namespace

LmOutcome levenbergMarquardt(const ResidualBatch& evaluate, const std::vector<double>& u0, const LmSettings& s) {
  LmSearch search(evaluate, s);
  if (!search.start(u0)) return search.out;
  for (int it = 1; it <= s.max_iterations; ++it)
    if (!search.iterate(it)) return search.out;
  search.out.reason = "the iteration limit (" + std::to_string(s.max_iterations) + ") was reached before the cost settled";
  return search.out;
}

namespace {

// What the global stage's objective needs and what it has found so far.
struct GlobalSearch {
  const ResidualBatch* evaluate;
  std::vector<double> best;
  double best_cost = std::numeric_limits<double>::infinity();
  const std::atomic<bool>* interrupt = nullptr;
};

double globalObjective(const std::vector<double>& u, std::vector<double>&, void* data) {
  GlobalSearch& g = *static_cast<GlobalSearch*>(data);
  if (g.interrupt && g.interrupt->load()) throw nlopt::forced_stop();
  const ResidualEvaluation e = (*g.evaluate)({u})[0];
  if (!e.ok) return 1e300;
  double cost = 0;
  for (double v : e.r) cost += v * v;
  if (cost < g.best_cost) {
    g.best_cost = cost;
    g.best = u;
  }
  return cost;
}

}  // namespace

std::vector<double> globalStart(const ResidualBatch& evaluate, const std::vector<double>& u0,
                                const std::atomic<bool>* interrupt) {
  const unsigned p = static_cast<unsigned>(u0.size());
  GlobalSearch g{&evaluate, u0, std::numeric_limits<double>::infinity(), interrupt};
  std::vector<double> scratch;
  globalObjective(u0, scratch, &g);
  nlopt::opt opt(nlopt::GN_DIRECT_L, p);
  opt.set_lower_bounds(std::vector<double>(p, 0.0));
  opt.set_upper_bounds(std::vector<double>(p, 1.0));
  opt.set_maxeval(30 * static_cast<int>(p));
  opt.set_min_objective(globalObjective, &g);
  std::vector<double> u = u0;
  double f = 0;
  try {
    opt.optimize(u, f);
  } catch (const std::exception&) {
    // stopped (interrupt, a failure inside NLopt): the best point seen so far is kept
  }
  return g.best;
}

namespace {

Eigen::MatrixXd asMatrix(const std::vector<std::vector<double>>& rows, Eigen::Index p) {
  const Eigen::Index n = static_cast<Eigen::Index>(rows.size());
  Eigen::MatrixXd J(n, p);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index k = 0; k < p; ++k) J(i, k) = rows[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)];
  return J;
}

// Marks the keys without effect (a column of zero length against the longest, d: the columns'
// lengths) and returns the others.
std::vector<Eigen::Index> keysWithEffect(const Eigen::VectorXd& d, std::vector<bool>& no_effect) {
  const double dmax = d.maxCoeff();
  no_effect.assign(static_cast<std::size_t>(d.size()), false);
  std::vector<Eigen::Index> live;
  for (Eigen::Index k = 0; k < d.size(); ++k) {
    no_effect[static_cast<std::size_t>(k)] = !(d(k) > 1e-12 * dmax) || !(dmax > 0);
    if (!no_effect[static_cast<std::size_t>(k)]) live.push_back(k);
  }
  return live;
}

// The weakest direction over relative changes: J·diag(scale), smallest eigenvalue (its largest
// component positive).
std::vector<double> weakestDirection(const Eigen::MatrixXd& J, const std::vector<double>& scale) {
  Eigen::MatrixXd Jr = J;
  for (Eigen::Index k = 0; k < J.cols(); ++k) Jr.col(k) *= scale[static_cast<std::size_t>(k)];
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(Jr.transpose() * Jr);
  const Eigen::VectorXd v = es.eigenvectors().col(0);
  const Eigen::Index big = [&] { Eigen::Index b = 0; v.cwiseAbs().maxCoeff(&b); return b; }();
  const double sign = v(big) < 0 ? -1.0 : 1.0;
  std::vector<double> w;
  for (Eigen::Index k = 0; k < J.cols(); ++k) w.push_back(sign * v(k));
  return w;
}

// The information matrix of the keys with effect, columns normalised to unit length, and its
// eigen-decomposition (eigenvalues ascending).
struct NormalisedInformation {
  const std::vector<Eigen::Index>& live;
  const Eigen::VectorXd& d;
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es;
  double lmax = 0;
  bool resolved(Eigen::Index m) const { return es.eigenvalues()(m) > 1e-12 * lmax; }
};

Eigen::MatrixXd normalisedInformation(const Eigen::MatrixXd& A, const Eigen::VectorXd& d,
                                      const std::vector<Eigen::Index>& live) {
  const Eigen::Index q = static_cast<Eigen::Index>(live.size());
  Eigen::MatrixXd An(q, q);
  for (Eigen::Index a = 0; a < q; ++a)
    for (Eigen::Index b = 0; b < q; ++b) An(a, b) = A(live[a], live[b]) / (d(live[a]) * d(live[b]));
  return An;
}

// The pseudo-inverse over the resolved eigenvalues.
Eigen::MatrixXd pseudoInverse(const NormalisedInformation& info) {
  const Eigen::Index q = static_cast<Eigen::Index>(info.live.size());
  Eigen::MatrixXd inv = Eigen::MatrixXd::Zero(q, q);
  for (Eigen::Index m = 0; m < q; ++m) {
    const double l = info.es.eigenvalues()(m);
    if (l > 1e-12 * info.lmax) inv += info.es.eigenvectors().col(m) * info.es.eigenvectors().col(m).transpose() / l;
  }
  return inv;
}

// The keys in a null direction (a component above 1e-3 in an unresolved eigenvector): undetermined.
std::vector<bool> keysInNullDirection(const NormalisedInformation& info) {
  const Eigen::Index q = static_cast<Eigen::Index>(info.live.size());
  std::vector<bool> in_null(static_cast<std::size_t>(q), false);
  for (Eigen::Index m = 0; m < q; ++m)
    if (!info.resolved(m))
      for (Eigen::Index a = 0; a < q; ++a)
        if (std::abs(info.es.eigenvectors()(a, m)) > 1e-3) in_null[static_cast<std::size_t>(a)] = true;
  return in_null;
}

// Standard deviations and correlations of the keys with effect from the pseudo-inverse; the
// undetermined keys keep an infinite deviation and NaN correlations.
void putStdAndCorrelation(const NormalisedInformation& info, CovarianceEstimate& c) {
  const Eigen::MatrixXd inv = pseudoInverse(info);
  const std::vector<bool> in_null = keysInNullDirection(info);
  const std::vector<Eigen::Index>& live = info.live;
  const Eigen::Index q = static_cast<Eigen::Index>(live.size());
  for (Eigen::Index a = 0; a < q; ++a) {
    const std::size_t ka = static_cast<std::size_t>(live[a]);
    if (!in_null[static_cast<std::size_t>(a)]) c.std[ka] = std::sqrt(c.sigma_hat2 * inv(a, a)) / info.d(live[a]);
    for (Eigen::Index b = 0; b < q; ++b) {
      const std::size_t kb = static_cast<std::size_t>(live[b]);
      const bool undetermined = in_null[static_cast<std::size_t>(a)] || in_null[static_cast<std::size_t>(b)];
      c.correlation[ka][kb] = a == b ? 1.0 : undetermined ? kNaN : inv(a, b) / std::sqrt(inv(a, a) * inv(b, b));
    }
  }
}

// The condition number √(λmax/λmin) of the normalised information (infinite when λmin ≤ 0), its
// largest eigenvalue into info; singular when the smallest vanishes against the largest.
void putCondition(NormalisedInformation& info, CovarianceEstimate& c) {
  const Eigen::VectorXd& ev = info.es.eigenvalues();  // ascending
  info.lmax = ev(ev.size() - 1);
  const double lmin = std::max(ev(0), 0.0);
  c.condition = lmin > 0 ? std::sqrt(info.lmax / lmin) : kInf;
  // Keys in the null direction are undetermined; the others keep the pseudo-inverse's values.
  if (!(lmin > 1e-12 * info.lmax)) c.singular = true;
}

}  // namespace

CovarianceEstimate estimateCovariance(const std::vector<std::vector<double>>& Jrows, double rss,
                                      const std::vector<double>& scale) {
  CovarianceEstimate c;
  const Eigen::Index p = static_cast<Eigen::Index>(scale.size());
  const Eigen::MatrixXd J = asMatrix(Jrows, p);
  c.sigma_hat2 = rss / std::max<double>(1.0, static_cast<double>(J.rows() - p));
  const Eigen::MatrixXd A = J.transpose() * J;
  // Columns normalised to unit length: the information matrix as a correlation of sensitivities,
  // independent of the keys' units, so one threshold serves every key.
  const Eigen::VectorXd d = A.diagonal().cwiseSqrt();
  const std::vector<Eigen::Index> live = keysWithEffect(d, c.no_effect);
  c.std.assign(static_cast<std::size_t>(p), kInf);
  c.correlation.assign(static_cast<std::size_t>(p), std::vector<double>(static_cast<std::size_t>(p), kNaN));
  c.singular = live.size() < static_cast<std::size_t>(p);
  c.weakest_direction = weakestDirection(J, scale);
  if (live.empty()) {
    c.condition = kInf;
    return c;
  }
  NormalisedInformation info{live, d, Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(normalisedInformation(A, d, live))};
  putCondition(info, c);
  putStdAndCorrelation(info, c);
  return c;
}

}  // namespace rollerdyn
