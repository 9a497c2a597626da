#include "modes/PeriodicFlow.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <Eigen/LU>

namespace rollerdyn::modes {
namespace {

// Dormand-Prince 5(4) tableau (Hairer, Nørsett, Wanner, Solving ODEs I, table 5.2).
constexpr double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
constexpr double a21 = 1.0 / 5;
constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561, a54 = -212.0 / 729;
constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247, a64 = 49.0 / 176,
                 a65 = -5103.0 / 18656;
constexpr double b1 = 35.0 / 384, b3 = 500.0 / 1113, b4 = 125.0 / 192, b5 = -2187.0 / 6784, b6 = 11.0 / 84;
// error coefficients: b - b̂
constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920, e5 = -17253.0 / 339200,
                 e6 = 22.0 / 525, e7 = -1.0 / 40;

// The augmented system: z = [x (n + quadratures), vec(Φ) (n·n, column-major)].
class Augmented {
 public:
  Augmented(const PeriodicSystem& sys, bool variational, long& evaluations)
      : evaluations(evaluations), sys_(sys), var_(variational) {
    nx_ = sys.n + sys.quadratures;
    size_ = nx_ + (var_ ? sys.n * sys.n : 0);
    f_.resize(nx_);
    fp_.resize(nx_);
    fm_.resize(nx_);
    A_.resize(sys.n, sys.n);
  }
  int size() const { return size_; }
  long& evaluations;  // right-hand sides so far (the caller's counter)

  void operator()(double s, const Eigen::VectorXd& z, Eigen::VectorXd& dz) {
    dz.resize(size_);
    xs_ = z.head(nx_);
    sys_.rhs(s, xs_, f_);
    ++evaluations;
    dz.head(nx_) = f_;
    if (!var_) return;
    const int n = sys_.n;
    if (sys_.jacobian) {
      sys_.jacobian(s, xs_, A_);
    } else {
      differenceJacobian(s);
    }
    Eigen::Map<const Eigen::MatrixXd> Phi(z.data() + nx_, n, n);
    Eigen::Map<Eigen::MatrixXd> dPhi(dz.data() + nx_, n, n);
    dPhi.noalias() = A_ * Phi;
  }

 private:
  // A = ∂f/∂x at (s, xs_) by central differences, a step of 1e-6 of each state's scale.
  void differenceJacobian(double s) {
    const int n = sys_.n;
    Eigen::VectorXd xp = xs_;
    for (int j = 0; j < n; ++j) {
      const double h = 1e-6 * std::max(std::abs(xs_(j)), sys_.scale(j));
      xp(j) = xs_(j) + h;
      sys_.rhs(s, xp, fp_);
      xp(j) = xs_(j) - h;
      sys_.rhs(s, xp, fm_);
      xp(j) = xs_(j);
      evaluations += 2;
      A_.col(j) = (fp_.head(n) - fm_.head(n)) / (2 * h);
    }
  }

  const PeriodicSystem& sys_;
  bool var_;
  int nx_ = 0, size_ = 0;
  Eigen::VectorXd f_, fp_, fm_, xs_;
  Eigen::MatrixXd A_;
};

// The stages of one Dormand-Prince step; k1 holds f at the step's start (first same as last).
struct DormandPrinceStages {
  explicit DormandPrinceStages(int N) : k1(N), k2(N), k3(N), k4(N), k5(N), k6(N), k7(N), y(N), err(N) {}
  Eigen::VectorXd k1, k2, k3, k4, k5, k6, k7, y, err;
};

// One Dormand-Prince step of size h from (s, z): the fifth-order result in k.y, f there in k.k7,
// and the largest weighted error estimate (NaN: a stage left the region where f is defined).
double dormandPrinceStep(Augmented& F, double s, double h, const Eigen::VectorXd& z, const Eigen::VectorXd& atol,
                         double rtol, DormandPrinceStages& k) {
  k.y = z + h * a21 * k.k1;
  F(s + c2 * h, k.y, k.k2);
  k.y = z + h * (a31 * k.k1 + a32 * k.k2);
  F(s + c3 * h, k.y, k.k3);
  k.y = z + h * (a41 * k.k1 + a42 * k.k2 + a43 * k.k3);
  F(s + c4 * h, k.y, k.k4);
  k.y = z + h * (a51 * k.k1 + a52 * k.k2 + a53 * k.k3 + a54 * k.k4);
  F(s + c5 * h, k.y, k.k5);
  k.y = z + h * (a61 * k.k1 + a62 * k.k2 + a63 * k.k3 + a64 * k.k4 + a65 * k.k5);
  F(s + h, k.y, k.k6);
  k.y = z + h * (b1 * k.k1 + b3 * k.k3 + b4 * k.k4 + b5 * k.k5 + b6 * k.k6);
  F(s + h, k.y, k.k7);
  k.err = h * (e1 * k.k1 + e3 * k.k3 + e4 * k.k4 + e5 * k.k5 + e6 * k.k6 + e7 * k.k7);
  double en = 0;
  for (int i = 0; i < z.size(); ++i) {
    const double sc = atol(i) + rtol * std::max(std::abs(z(i)), std::abs(k.y(i)));
    const double ei = std::abs(k.err(i)) / sc;
    en = std::isfinite(ei) ? std::max(en, ei) : NAN;
    if (!std::isfinite(en)) break;
  }
  return en;
}

// Where the flow is sampled: `samples` points evenly over the period S, the first at its start.
std::vector<double> sampleTimes(double S, int samples) {
  std::vector<double> sample_at;
  for (int k = 0; k < samples; ++k) sample_at.push_back(S * k / samples);
  return sample_at;
}

// Error weights: periodic states by their scale, quadratures relative only, Φ absolute.
Eigen::VectorXd errorWeights(const PeriodicSystem& sys, double atol_scale, int N) {
  const int n = sys.n, nx = sys.n + sys.quadratures;
  Eigen::VectorXd atol = Eigen::VectorXd::Constant(N, atol_scale);
  for (int i = 0; i < n; ++i) atol(i) = atol_scale * sys.scale(i);
  for (int i = n; i < nx; ++i) atol(i) = atol_scale;
  return atol;
}

// Why a flow over the period cannot be integrated as set up; empty when it can.
std::string setUpProblem(const PeriodicSystem& sys, const Eigen::VectorXd& x0) {
  const int n = sys.n, nx = sys.n + sys.quadratures;
  if (n <= 0 || !(sys.period > 0) || x0.size() != nx || sys.scale.size() != n || !sys.rhs)
    return "periodic system set up wrongly (sizes, period or right-hand side)";
  return "";
}

// Where the next step aims: the next sample or the period's end, and whether the step was
// shortened to land on it.
struct StepTarget {
  double target = 0;
  bool clipped = false;
};

// One integration over the period: the augmented state, its error weights, the samples still to
// take and the adaptive step. The result's counters, samples and failure fill as it goes.
class PeriodIntegration {
 public:
  PeriodIntegration(const PeriodicSystem& sys, const Eigen::VectorXd& x0, const FlowOptions& o, FlowResult& r)
      : sys_(sys), o_(o), r_(r), F_(sys, o.monodromy, r.evaluations), nx_(sys.n + sys.quadratures),
        z_(F_.size()), atol_(errorWeights(sys, o.atol_scale, F_.size())), S_(sys.period),
        sample_at_(sampleTimes(S_, o.samples)), k_(F_.size()), h_(S_ / 200) {
    z_.head(nx_) = x0;
    if (o.monodromy) Eigen::Map<Eigen::MatrixXd>(z_.data() + nx_, sys.n, sys.n).setIdentity();
    if (!sample_at_.empty()) {
      record();
      next_sample_ = 1;
    }
    F_(s_, z_, k_.k1);
  }

  // Steps to the period's end; false (with r.failure) when the integration gave up.
  bool run() {
    while (s_ < S_) {
      if (r_.steps + r_.rejected >= o_.max_steps)
        return fail("period not integrated within " + std::to_string(o_.max_steps) + " steps");
      const StepTarget t = aim();
      const double en = dormandPrinceStep(F_, s_, h_, z_, atol_, o_.rtol, k_);
      if (!std::isfinite(en)) {  // a stage left the region where f is defined: a smaller step
        if (!retryUndefinedStage()) return false;
        continue;
      }
      if (en <= 1.0) {
        if (accept(en, t)) break;
      } else {
        ++r_.rejected;
        h_ *= std::max(0.1, 0.9 * std::pow(en, -0.2));
      }
      if (h_ < 1e-14 * S_) return fail("step size underflow at s = " + std::to_string(s_));
    }
    return true;
  }

  // The state at the period's end and, when asked, the monodromy Φ(S).
  void finish() {
    r_.x_end = z_.head(nx_);
    if (o_.monodromy) r_.monodromy = Eigen::Map<const Eigen::MatrixXd>(z_.data() + nx_, sys_.n, sys_.n);
    r_.ok = true;
  }

 private:
  void record() {
    r_.s_samples.push_back(s_);
    r_.x_samples.push_back(z_.head(nx_));
  }

  bool fail(std::string why) {
    r_.failure = std::move(why);
    return false;
  }

  // The step is shortened to land on the next sample or the period's end.
  StepTarget aim() {
    StepTarget t{S_, false};
    if (next_sample_ < sample_at_.size()) t.target = sample_at_[next_sample_];
    if (s_ + h_ >= t.target) {
      h_ = t.target - s_;
      t.clipped = true;
    }
    return t;
  }

  // A step a tenth as long after a stage left the defined region; false when that gets too small.
  bool retryUndefinedStage() {
    ++r_.rejected;
    h_ *= 0.1;
    if (h_ >= 1e-14 * S_) return true;
    char b[160];
    std::snprintf(b, sizeof b, "the motion left the range where the model is defined %.2g of the way through "
                  "the period", s_ / S_);
    return fail(b);
  }

  // Takes the step (sampling where it landed on a sample) and sizes the next; true at the period's end.
  bool accept(double en, const StepTarget& t) {
    s_ = t.clipped ? t.target : s_ + h_;
    z_ = k_.y;
    k_.k1 = k_.k7;  // first same as last
    ++r_.steps;
    if (t.clipped && next_sample_ < sample_at_.size() && t.target == sample_at_[next_sample_]) {
      record();
      ++next_sample_;
    }
    if (t.clipped && t.target == S_) return true;
    const double fac = en > 0 ? 0.9 * std::pow(en, -0.2) : 5.0;
    h_ *= std::min(5.0, std::max(0.2, fac));
    return false;
  }

  const PeriodicSystem& sys_;
  const FlowOptions& o_;
  FlowResult& r_;
  Augmented F_;
  const int nx_;
  Eigen::VectorXd z_;
  const Eigen::VectorXd atol_;
  const double S_;
  const std::vector<double> sample_at_;
  size_t next_sample_ = 0;
  DormandPrinceStages k_;
  double s_ = 0, h_;
};

}  // namespace

FlowResult flowOverPeriod(const PeriodicSystem& sys, const Eigen::VectorXd& x0, const FlowOptions& o) {
  FlowResult r;
  r.failure = setUpProblem(sys, x0);
  if (!r.failure.empty()) return r;
  PeriodIntegration period(sys, x0, o, r);
  if (period.run()) period.finish();
  return r;
}

namespace {

// The largest residual entry relative to its state's scale; NaN when any entry is not finite.
double scaledResidual(const PeriodicSystem& sys, const Eigen::VectorXd& d) {
  double m = 0;
  for (int i = 0; i < sys.n; ++i) {
    const double e = std::abs(d(i)) / sys.scale(i);
    if (!std::isfinite(e)) return double(NAN);
    m = std::max(m, e);
  }
  return m;
}

// o.warmup_periods whole periods from the start x (updated), without the variational equations.
// Returns the flow's failure, empty when every period went through.
template <class Run>
std::string warmUp(const PeriodicSystem& sys, Run& run, const OrbitOptions& o, Eigen::VectorXd& x) {
  const int n = sys.n;
  FlowOptions plain = o.flow;
  plain.monodromy = false;
  plain.samples = 0;
  for (int k = 0; k < o.warmup_periods; ++k) {
    const FlowResult f = run(x, plain);
    if (!f.ok) return f.failure;
    x.head(n) = f.x_end.head(n);
  }
  return "";
}

// A start x of the period map with its flow f (monodromy included), the residual
// res = x(S) - x(0) and that residual's scaled size r.
struct PeriodMapPoint {
  Eigen::VectorXd x;
  FlowResult f;
  Eigen::VectorXd res;
  double r = 0;
};

// The flows inside Newton's method: with the variational equations, without samples.
FlowOptions newtonFlowOptions(const OrbitOptions& o) {
  FlowOptions var = o.flow;
  var.monodromy = true;
  var.samples = 0;
  return var;
}

// Newton's step dx on the period map, halved (at most eight times) until the residual falls or
// meets the tolerance. Accepted: p holds the new start, its flow and its residual.
template <class Run>
bool dampedNewtonStep(const PeriodicSystem& sys, Run& run, const FlowOptions& var, const Eigen::VectorXd& dx,
                      double tolerance, PeriodMapPoint& p) {
  const int n = sys.n;
  double lambda = 1.0;
  for (int half = 0; half < 8; ++half, lambda *= 0.5) {
    Eigen::VectorXd xt = p.x;
    xt.head(n) += lambda * dx;
    FlowResult ft = run(xt, var);
    if (!ft.ok) continue;
    const Eigen::VectorXd rt = ft.x_end.head(n) - xt.head(n);
    const double st = scaledResidual(sys, rt);
    if (std::isfinite(st) && (st < p.r || st <= tolerance)) {
      p.x = xt;
      p.f = std::move(ft);
      p.res = rt;
      p.r = st;
      return true;
    }
  }
  return false;
}

// Newton's first point: the guess after the warm-up periods, flowed once with the monodromy.
// Returns why there is none, empty when p holds it.
template <class Run>
std::string startingPoint(const PeriodicSystem& sys, Run& run, const OrbitOptions& o, const Eigen::VectorXd& guess,
                          PeriodMapPoint& p) {
  const int n = sys.n;
  p.x = Eigen::VectorXd::Zero(n + sys.quadratures);
  p.x.head(n) = guess.head(n);
  const std::string failure = warmUp(sys, run, o, p.x);
  if (!failure.empty()) return failure;
  p.f = run(p.x, newtonFlowOptions(o));
  if (!p.f.ok) return p.f.failure;
  p.res = p.f.x_end.head(n) - p.x.head(n);
  p.r = scaledResidual(sys, p.res);
  if (!std::isfinite(p.r)) return "the period map is not finite at the first guess";
  return "";
}

// Newton's iterations from p while the residual exceeds the tolerance; the orbit gets their
// count and the residual reached, or the failure (false).
template <class Run>
bool newtonOnPeriodMap(const PeriodicSystem& sys, Run& run, const OrbitOptions& o, PeriodMapPoint& p,
                       PeriodicOrbit& orbit) {
  const int n = sys.n;
  const FlowOptions var = newtonFlowOptions(o);
  int it = 0;
  for (; it < o.max_newton && p.r > o.tolerance; ++it) {
    const Eigen::MatrixXd J = p.f.monodromy - Eigen::MatrixXd::Identity(n, n);
    const Eigen::VectorXd dx = J.fullPivLu().solve(-p.res);
    if (!dx.allFinite()) {
      orbit.failure = "Newton step not finite (monodromy has a multiplier 1)";
      return false;
    }
    if (!dampedNewtonStep(sys, run, var, dx, o.tolerance, p)) {
      // No step reduces the residual any more: the map's own integration error is reached.
      if (p.r <= o.accept_stagnation) break;
      orbit.failure = "Newton's method on the period map did not converge (residual " + std::to_string(p.r) + ")";
      orbit.residual = p.r;
      return false;
    }
  }
  orbit.newton_iterations = it;
  orbit.residual = p.r;
  return true;
}

// The orbit at the converged start p.x, from the flow there with the samples asked for. Without
// samples it is the last flow of Newton's method itself (same start, same options, the same
// numbers bit for bit): integrating the period again cost a fifth to a third of each point of a
// stability chart.
template <class Run>
void orbitAt(const PeriodicSystem& sys, Run& run, const OrbitOptions& o, PeriodMapPoint& p, PeriodicOrbit& orbit) {
  FlowOptions fin = o.flow;
  fin.monodromy = true;
  FlowResult ff = fin.samples == 0 ? std::move(p.f) : run(p.x, fin);
  if (ff.ok && (!ff.x_end.allFinite() || !ff.monodromy.allFinite())) {
    ff.ok = false;
    ff.failure = "non-finite orbit";
  }
  if (!ff.ok) {
    orbit.failure = ff.failure;
    return;
  }
  orbit.found = true;
  orbit.x0 = p.x.head(sys.n);
  orbit.monodromy = ff.monodromy;
  orbit.quadratures = ff.x_end.tail(sys.quadratures);
  orbit.s_samples = std::move(ff.s_samples);
  orbit.x_samples = std::move(ff.x_samples);
}

}  // namespace

PeriodicOrbit findPeriodicOrbit(const PeriodicSystem& sys, const Eigen::VectorXd& guess, const OrbitOptions& o) {
  PeriodicOrbit orbit;
  auto run = [&](const Eigen::VectorXd& x0, const FlowOptions& fo) {
    FlowResult fr = flowOverPeriod(sys, x0, fo);
    orbit.evaluations += fr.evaluations;
    return fr;
  };
  PeriodMapPoint p;
  orbit.failure = startingPoint(sys, run, o, guess, p);
  if (!orbit.failure.empty()) return orbit;
  if (!newtonOnPeriodMap(sys, run, o, p, orbit)) return orbit;
  if (p.r > o.tolerance && p.r > o.accept_stagnation) {
    orbit.failure = "no periodic orbit within " + std::to_string(o.max_newton) + " Newton iterations (residual " +
                    std::to_string(p.r) + ")";
    return orbit;
  }
  orbitAt(sys, run, o, p, orbit);
  return orbit;
}

}  // namespace rollerdyn::modes
