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
  // Error weights: periodic states by their scale, quadratures relative only, Φ absolute.
  Eigen::VectorXd atol = Eigen::VectorXd::Constant(N, o.atol_scale);
  for (int i = 0; i < n; ++i) atol(i) = o.atol_scale * sys.scale(i);
  for (int i = n; i < nx; ++i) atol(i) = o.atol_scale;

  const double S = sys.period;
  std::vector<double> sample_at;
  for (int k = 0; k < o.samples; ++k) sample_at.push_back(S * k / o.samples);
  size_t next_sample = 0;
  auto record = [&](double s) {
    r.s_samples.push_back(s);
    r.x_samples.push_back(z.head(nx));
  };
  if (!sample_at.empty()) {
    record(0.0);
    next_sample = 1;
  }

  Eigen::VectorXd k1(N), k2(N), k3(N), k4(N), k5(N), k6(N), k7(N), y(N), err(N);
  double s = 0, h = S / 200;
  F(s, z, k1);
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
    y = z + h * a21 * k1;
    F(s + c2 * h, y, k2);
    y = z + h * (a31 * k1 + a32 * k2);
    F(s + c3 * h, y, k3);
    y = z + h * (a41 * k1 + a42 * k2 + a43 * k3);
    F(s + c4 * h, y, k4);
    y = z + h * (a51 * k1 + a52 * k2 + a53 * k3 + a54 * k4);
    F(s + c5 * h, y, k5);
    y = z + h * (a61 * k1 + a62 * k2 + a63 * k3 + a64 * k4 + a65 * k5);
    F(s + h, y, k6);
    y = z + h * (b1 * k1 + b3 * k3 + b4 * k4 + b5 * k5 + b6 * k6);
    F(s + h, y, k7);
    err = h * (e1 * k1 + e3 * k3 + e4 * k4 + e5 * k5 + e6 * k6 + e7 * k7);
    double en = 0;
    for (int i = 0; i < N; ++i) {
      const double sc = atol(i) + o.rtol * std::max(std::abs(z(i)), std::abs(y(i)));
      const double ei = std::abs(err(i)) / sc;
      en = std::isfinite(ei) ? std::max(en, ei) : NAN;
      if (!std::isfinite(en)) break;
    }
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
      z = y;
      k1 = k7;  // first same as last
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
  FlowOptions plain = o.flow;
  plain.monodromy = false;
  plain.samples = 0;
  for (int k = 0; k < o.warmup_periods; ++k) {
    const FlowResult f = run(x, plain);
    if (!f.ok) {
      orbit.failure = f.failure;
      return orbit;
    }
    x.head(n) = f.x_end.head(n);
  }
  auto scaled = [&](const Eigen::VectorXd& d) {  // NaN when any entry is not finite
    double m = 0;
    for (int i = 0; i < n; ++i) {
      const double e = std::abs(d(i)) / sys.scale(i);
      if (!std::isfinite(e)) return double(NAN);
      m = std::max(m, e);
    }
    return m;
  };
  FlowOptions var = o.flow;
  var.monodromy = true;
  var.samples = 0;
  FlowResult f = run(x, var);
  if (!f.ok) {
    orbit.failure = f.failure;
    return orbit;
  }
  Eigen::VectorXd res = f.x_end.head(n) - x.head(n);
  double r = scaled(res);
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
    double lambda = 1.0;
    bool accepted = false;
    for (int half = 0; half < 8; ++half, lambda *= 0.5) {
      Eigen::VectorXd xt = x;
      xt.head(n) += lambda * dx;
      FlowResult ft = run(xt, var);
      if (!ft.ok) continue;
      const Eigen::VectorXd rt = ft.x_end.head(n) - xt.head(n);
      const double st = scaled(rt);
      if (std::isfinite(st) && (st < r || st <= o.tolerance)) {
        x = xt;
        f = std::move(ft);
        res = rt;
        r = st;
        accepted = true;
        break;
      }
    }
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
