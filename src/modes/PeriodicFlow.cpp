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
    Eigen::Map<const Eigen::MatrixXd> Phi(z.data() + nx_, n, n);
    Eigen::Map<Eigen::MatrixXd> dPhi(dz.data() + nx_, n, n);
    dPhi.noalias() = A_ * Phi;
  }

 private:
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

}  // namespace

FlowResult flowOverPeriod(const PeriodicSystem& sys, const Eigen::VectorXd& x0, const FlowOptions& o) {
  FlowResult r;
  const int n = sys.n, nx = sys.n + sys.quadratures;
  if (n <= 0 || !(sys.period > 0) || x0.size() != nx || sys.scale.size() != n || !sys.rhs) {
    r.failure = "periodic system set up wrongly (sizes, period or right-hand side)";
    return r;
  }
  Augmented F(sys, o.monodromy, r.evaluations);
  const int N = F.size();
  Eigen::VectorXd z(N), w(N);
  z.head(nx) = x0;
  if (o.monodromy) Eigen::Map<Eigen::MatrixXd>(z.data() + nx, n, n).setIdentity();
  const Eigen::VectorXd atol = errorWeights(sys, o.atol_scale, N);

  const double S = sys.period;
  const std::vector<double> sample_at = sampleTimes(S, o.samples);
  size_t next_sample = 0;
  auto record = [&](double s) {
    r.s_samples.push_back(s);
    r.x_samples.push_back(z.head(nx));
  };
  if (!sample_at.empty()) {
    record(0.0);
    next_sample = 1;
  }

  DormandPrinceStages k(N);
  double s = 0, h = S / 200;
  F(s, z, k.k1);
  while (s < S) {
    if (r.steps + r.rejected >= o.max_steps) {
      r.failure = "period not integrated within " + std::to_string(o.max_steps) + " steps";
      return r;
    }
    double target = S;
    if (next_sample < sample_at.size()) target = sample_at[next_sample];
    bool clipped = false;
    if (s + h >= target) {
      h = target - s;
      clipped = true;
    }
    const double en = dormandPrinceStep(F, s, h, z, atol, o.rtol, k);
    if (!std::isfinite(en)) {  // a stage left the region where f is defined: a smaller step
      ++r.rejected;
      h *= 0.1;
      if (h < 1e-14 * S) {
        char b[160];
        std::snprintf(b, sizeof b, "the motion left the range where the model is defined %.2g of the way through "
                      "the period", s / S);
        r.failure = b;
        return r;
      }
      continue;
    }
    if (en <= 1.0) {
      s = clipped ? target : s + h;
      z = k.y;
      k.k1 = k.k7;  // first same as last
      ++r.steps;
      if (clipped && next_sample < sample_at.size() && target == sample_at[next_sample]) {
        record(s);
        ++next_sample;
      }
      if (clipped && target == S) break;
      const double fac = en > 0 ? 0.9 * std::pow(en, -0.2) : 5.0;
      h *= std::min(5.0, std::max(0.2, fac));
    } else {
      ++r.rejected;
      h *= std::max(0.1, 0.9 * std::pow(en, -0.2));
    }
    if (h < 1e-14 * S) {
      r.failure = "step size underflow at s = " + std::to_string(s);
      return r;
    }
  }
  r.x_end = z.head(nx);
  if (o.monodromy) r.monodromy = Eigen::Map<const Eigen::MatrixXd>(z.data() + nx, n, n);
  r.ok = true;
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

// Newton's step dx on the period map, halved (at most eight times) until the residual falls or
// meets the tolerance. Accepted: x, f, res and r hold the new start, its flow and its residual.
template <class Run>
bool dampedNewtonStep(const PeriodicSystem& sys, Run& run, const FlowOptions& var, const Eigen::VectorXd& dx,
                      double tolerance, Eigen::VectorXd& x, FlowResult& f, Eigen::VectorXd& res, double& r) {
  const int n = sys.n;
  double lambda = 1.0;
  for (int half = 0; half < 8; ++half, lambda *= 0.5) {
    Eigen::VectorXd xt = x;
    xt.head(n) += lambda * dx;
    FlowResult ft = run(xt, var);
    if (!ft.ok) continue;
    const Eigen::VectorXd rt = ft.x_end.head(n) - xt.head(n);
    const double st = scaledResidual(sys, rt);
    if (std::isfinite(st) && (st < r || st <= tolerance)) {
      x = xt;
      f = std::move(ft);
      res = rt;
      r = st;
      return true;
    }
  }
  return false;
}

}  // namespace

PeriodicOrbit findPeriodicOrbit(const PeriodicSystem& sys, const Eigen::VectorXd& guess, const OrbitOptions& o) {
  PeriodicOrbit orbit;
  auto run = [&](const Eigen::VectorXd& x0, const FlowOptions& fo) {
    FlowResult fr = flowOverPeriod(sys, x0, fo);
    orbit.evaluations += fr.evaluations;
    return fr;
  };
  const int n = sys.n, nx = sys.n + sys.quadratures;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(nx);
  x.head(n) = guess.head(n);
  orbit.failure = warmUp(sys, run, o, x);
  if (!orbit.failure.empty()) return orbit;
  FlowOptions var = o.flow;
  var.monodromy = true;
  var.samples = 0;
  FlowResult f = run(x, var);
  if (!f.ok) {
    orbit.failure = f.failure;
    return orbit;
  }
  Eigen::VectorXd res = f.x_end.head(n) - x.head(n);
  double r = scaledResidual(sys, res);
  if (!std::isfinite(r)) {
    orbit.failure = "the period map is not finite at the first guess";
    return orbit;
  }
  int it = 0;
  for (; it < o.max_newton && r > o.tolerance; ++it) {
    const Eigen::MatrixXd J = f.monodromy - Eigen::MatrixXd::Identity(n, n);
    const Eigen::VectorXd dx = J.fullPivLu().solve(-res);
    if (!dx.allFinite()) {
      orbit.failure = "Newton step not finite (monodromy has a multiplier 1)";
      return orbit;
    }
    const bool accepted = dampedNewtonStep(sys, run, var, dx, o.tolerance, x, f, res, r);
    if (!accepted) {
      // No step reduces the residual any more: the map's own integration error is reached.
      if (r <= o.accept_stagnation) break;
      orbit.failure = "Newton's method on the period map did not converge (residual " + std::to_string(r) + ")";
      orbit.residual = r;
      return orbit;
    }
  }
  orbit.newton_iterations = it;
  orbit.residual = r;
  if (r > o.tolerance && r > o.accept_stagnation) {
    orbit.failure = "no periodic orbit within " + std::to_string(o.max_newton) + " Newton iterations (residual " +
                    std::to_string(r) + ")";
    return orbit;
  }
  // The flow at the converged start with the samples asked for. Without samples it is the last
  // flow of Newton's method itself (same start, same options, the same numbers bit for bit):
  // integrating the period again cost a fifth to a third of each point of a stability chart.
  FlowOptions fin = o.flow;
  fin.monodromy = true;
  FlowResult ff = fin.samples == 0 ? std::move(f) : run(x, fin);
  if (ff.ok && (!ff.x_end.allFinite() || !ff.monodromy.allFinite())) {
    ff.ok = false;
    ff.failure = "non-finite orbit";
  }
  if (!ff.ok) {
    orbit.failure = ff.failure;
    return orbit;
  }
  orbit.found = true;
  orbit.x0 = x.head(n);
  orbit.monodromy = ff.monodromy;
  orbit.quadratures = ff.x_end.tail(sys.quadratures);
  orbit.s_samples = std::move(ff.s_samples);
  orbit.x_samples = std::move(ff.x_samples);
  return orbit;
}

}  // namespace rollerdyn::modes
