// The Floquet code (PeriodicFlow.h, Floquet.h) on systems with known answers: the Mathieu
// equation's transition curves and a damped constant-coefficient oscillator.
#include <cmath>
#include <complex>
#include <functional>

#include <Eigen/LU>
#include <gtest/gtest.h>

#include "modes/Floquet.h"
#include "modes/PeriodicFlow.h"

using namespace rollerdyn::modes;

namespace {

// ẍ + (δ + ε cos t)·x = 0 as x' = A(t)x, period 2π.
PeriodicSystem mathieu(double delta, double eps) {
  PeriodicSystem s;
  s.n = 2;
  s.period = 2 * M_PI;
  s.scale = Eigen::Vector2d(1, 1);
  s.rhs = [=](double t, const Eigen::VectorXd& x, Eigen::VectorXd& f) {
    f.resize(2);
    f << x(1), -(delta + eps * std::cos(t)) * x(0);
  };
  s.jacobian = [=](double t, const Eigen::VectorXd&, Eigen::MatrixXd& A) {
    A.resize(2, 2);
    A << 0, 1, -(delta + eps * std::cos(t)), 0;
  };
  return s;
}

double traceOfMonodromy(double delta, double eps) {
  FlowOptions o;
  o.rtol = 1e-12;
  o.atol_scale = 1e-12;
  const FlowResult r = flowOverPeriod(mathieu(delta, eps), Eigen::Vector2d(1, 0), o);
  EXPECT_TRUE(r.ok) << r.failure;
  return r.monodromy.trace();
}

// δ in [lo, hi] where tr Φ = target (bisection; the bracket must change sign).
double transition(double eps, double target, double lo, double hi) {
  double flo = traceOfMonodromy(lo, eps) - target;
  const double fhi = traceOfMonodromy(hi, eps) - target;
  EXPECT_LT(flo * fhi, 0) << "bracket [" << lo << ", " << hi << "] at eps " << eps;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi), fm = traceOfMonodromy(mid, eps) - target;
    if (fm * flo > 0) {
      lo = mid;
      flo = fm;
    } else {
      hi = mid;
    }
  }
  return 0.5 * (lo + hi);
}

}  // namespace

// Unit determinant (Liouville: the Mathieu equation has no damping) holds to the integration
// accuracy: a check that the variational equations are integrated, not just the solution.
TEST(Floquet, MathieuMonodromyHasUnitDeterminant) {
  FlowOptions o;
  o.rtol = 1e-12;
  o.atol_scale = 1e-12;
  const FlowResult r = flowOverPeriod(mathieu(0.3, 0.2), Eigen::Vector2d(1, 0), o);
  ASSERT_TRUE(r.ok);
  EXPECT_NEAR(r.monodromy.determinant(), 1.0, 1e-10);
}

// First transition curves, where a multiplier reaches -1 (period 4π), from δ = 1/4:
// δ = 1/4 ± ε/2 - ε²/8 + O(ε³) (Nayfeh and Mook, Nonlinear Oscillations, ch. 5; the ε² term is the
// next of the published expansion). The measured curves must agree with the first-order
// expansion to within ε²/8 + 2ε³ and with the second-order one to within 2ε³.
TEST(Floquet, MathieuFirstTransitionCurvesFromOneQuarter) {
  for (double eps : {0.05, 0.1, 0.2}) {
    const double upper = transition(eps, -2.0, 0.25, 0.25 + eps);
    const double lower = transition(eps, -2.0, 0.25 - eps, 0.25);
    EXPECT_NEAR(upper, 0.25 + eps / 2, eps * eps / 8 + 2 * eps * eps * eps) << eps;
    EXPECT_NEAR(lower, 0.25 - eps / 2, eps * eps / 8 + 2 * eps * eps * eps) << eps;
    EXPECT_NEAR(upper, 0.25 + eps / 2 - eps * eps / 8, 2 * eps * eps * eps) << eps;
    EXPECT_NEAR(lower, 0.25 - eps / 2 - eps * eps / 8, 2 * eps * eps * eps) << eps;
  }
}

// Second transition curves, multiplier +1 (period 2π), from δ = 1: δ = 1 - ε²/12 and
// δ = 1 + 5ε²/12, both + O(ε⁴) (the ε⁴ coefficients, 0.0015 and -0.2208, follow from the
// standard form's a2, b2 with q = 2ε: McLachlan, Theory and Application of Mathieu Functions).
TEST(Floquet, MathieuSecondTransitionCurvesFromOne) {
  for (double eps : {0.1, 0.2, 0.3}) {
    const double e2 = eps * eps, e4 = e2 * e2;
    const double lower = transition(eps, 2.0, 1 - e2 / 4, 1 + e2 / 8);
    const double upper = transition(eps, 2.0, 1 + e2 / 8, 1 + e2);
    EXPECT_NEAR(lower, 1 - e2 / 12, 0.01 * e4 + 1e-9) << eps;
    EXPECT_NEAR(upper, 1 + 5 * e2 / 12, 0.25 * e4) << eps;
    EXPECT_NEAR(upper, 1 + 5 * e2 / 12 - 0.2208 * e4, 0.05 * e4) << eps;  // the next term too
  }
}

// Inside the first zone the multipliers are real, one outside the unit circle: unstable.
TEST(Floquet, MathieuInsideFirstZoneIsUnstable) {
  FlowOptions o;
  o.rtol = 1e-11;
  const FlowResult r = flowOverPeriod(mathieu(0.25, 0.1), Eigen::Vector2d(1, 0), o);
  ASSERT_TRUE(r.ok);
  const auto m = floquetMultipliers(r.monodromy, 2 * M_PI, 0.5);
  ASSERT_EQ(m.size(), 2u);
  EXPECT_GT(m[0].modulus, 1.05);
  EXPECT_LT(m[0].mu.real(), 0);                 // period-doubling: μ < -1
  EXPECT_NEAR(m[0].frequency, 0.5, 1e-9);       // at half the excitation frequency
  const auto outside = floquetMultipliers(
      flowOverPeriod(mathieu(0.4, 0.1), Eigen::Vector2d(1, 0), o).monodromy, 2 * M_PI, 0.6);
  EXPECT_NEAR(outside[0].modulus, 1.0, 1e-8);   // undamped and stable: on the unit circle
}

// Damped constant-coefficient oscillator ẍ + 2ζωẋ + ω²x = 0 over any period T: multipliers
// exp(λT), λ = -ζω ± iω√(1-ζ²); the frequency and damping ratio recovered from them.
TEST(Floquet, DampedConstantCoefficientMultipliersAreExpLambdaT) {
  const double w = 7.0, zeta = 0.05, T = 2.3;  // ωT/2π = 2.56: the branch needs the reference
  PeriodicSystem s;
  s.n = 2;
  s.period = T;
  s.scale = Eigen::Vector2d(1, w);
  s.rhs = [=](double, const Eigen::VectorXd& x, Eigen::VectorXd& f) {
    f.resize(2);
    f << x(1), -w * w * x(0) - 2 * zeta * w * x(1);
  };  // no Jacobian given: central differences
  FlowOptions o;
  o.rtol = 1e-12;
  o.atol_scale = 1e-12;
  const FlowResult r = flowOverPeriod(s, Eigen::Vector2d(0.3, -0.1), o);
  ASSERT_TRUE(r.ok);
  const std::complex<double> lambda(-zeta * w, w * std::sqrt(1 - zeta * zeta));
  const std::complex<double> expected = std::exp(lambda * T);
  const auto m = floquetMultipliers(r.monodromy, T, w);
  ASSERT_EQ(m.size(), 2u);
  for (const auto& f : m) {
    const std::complex<double> e =
        std::abs(f.mu - expected) < std::abs(f.mu - std::conj(expected)) ? expected : std::conj(expected);
    EXPECT_LT(std::abs(f.mu - e), 1e-9 * std::abs(e)) << f.mu << " vs " << e;
    EXPECT_NEAR(f.frequency, w * std::sqrt(1 - zeta * zeta), 1e-8);
    EXPECT_NEAR(f.damping_ratio, zeta, 1e-8);
    EXPECT_NEAR(f.growth_rate, -zeta * w, 1e-8);
  }
}

// Newton on the period map finds the forced periodic response of a damped oscillator
// ẍ + 2ζωẋ + ω²x = cos t (known amplitude 1/√((ω²-1)² + (2ζω)²)).
TEST(Floquet, PeriodicOrbitOfForcedOscillator) {
  const double w = 3.0, zeta = 0.1;
  PeriodicSystem s;
  s.n = 2;
  s.quadratures = 1;
  s.period = 2 * M_PI;
  s.scale = Eigen::Vector2d(0.1, 0.1);
  s.rhs = [=](double t, const Eigen::VectorXd& x, Eigen::VectorXd& f) {
    f.resize(3);
    f << x(1), std::cos(t) - w * w * x(0) - 2 * zeta * w * x(1), 1.0;
  };
  const PeriodicOrbit o = findPeriodicOrbit(s, Eigen::Vector3d(0, 0, 0));
  ASSERT_TRUE(o.found) << o.failure;
  const double D = (w * w - 1) * (w * w - 1) + 4 * zeta * zeta * w * w;
  EXPECT_NEAR(o.x0(0), (w * w - 1) / D, 1e-8);   // x(0) = A·cos(-ξ)
  EXPECT_NEAR(o.x0(1), 2 * zeta * w / D, 1e-8);  // ẋ(0) = A·sin(ξ)
  EXPECT_NEAR(o.quadratures(0), 2 * M_PI, 1e-10);
}
