// The optimality criterion of Loveikin and Pochka (cam drive paper): I_Z = (m/2)∫ (x⁗)² dt (eq. (1)-(2); the paper's
// "acceleration of the third order" is the fourth derivative, see physics/CamMotionLaw.h), its
// closed forms (11), (17), (19) and the optimum x1 = ẋ_y·t1/2 (eq. (20)-(21)).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "physics/CamMotionLaw.h"

namespace rollerdyn {
namespace {

// 4-point Gauss-Legendre: exact for polynomials up to degree 7. x⁗ is a cubic, its square a
// sextic, and its first to fourth integrals are quartic to septic: every integral below is exact
// to round-off (relative ~1e-15), so tolerances of 1e-10 leave only room for round-off.
double gauss4(const std::function<double(double)>& f, double a, double b) {
  const double x[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
  const double w[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};
  double s = 0;
  for (int i = 0; i < 4; ++i) s += w[i] * f(0.5 * (a + b) + 0.5 * (b - a) * x[i]);
  return 0.5 * (b - a) * s;
}

const double kMass = 1000.0;  // Loveikin, Pochka, Romasevych (2018) cart [kg]

TEST(ReversalCriterion, ClosedFormsEq11And17MatchTheIntegralOfTheSnap) {
  // Any x1, ẋ_y, t: the closed forms are the integral of (m/2)·(x⁗)² of eq. (10) / (16).
  for (double x1 : {0.01, 0.03, 0.08}) {
    for (double v : {0.1, 0.2}) {
      for (double tp : {0.3, 0.5}) {
        const double Ib = 0.5 * kMass * gauss4([&](double t) { return std::pow(brakingSnap(t, x1, v, tp), 2); }, 0, tp);
        const double Is = 0.5 * kMass * gauss4([&](double t) { return std::pow(startSnap(t, x1, v, tp), 2); }, 0, tp);
        const double closed = reversalCriterionPart(kMass, x1, v, tp);
        EXPECT_NEAR(Ib, closed, 1e-10 * closed) << x1 << ' ' << v << ' ' << tp;
        EXPECT_NEAR(Is, closed, 1e-10 * closed) << x1 << ' ' << v << ' ' << tp;
        // eq. (19) = eq. (18) with t2 = tn = t1 = braking + start.
        EXPECT_NEAR(reversalCriterion(kMass, x1, v, tp), Ib + Is, 1e-10 * (Ib + Is));
      }
    }
  }
}

TEST(ReversalCriterion, Eq10And16MeetTheirBoundaryConditions) {
  // Integrating x⁗ four times from the initial conditions (6) / (12) must reach the end
  // conditions (7) / (13): braking from x = -x1, ẋ = ẋ_y to rest at 0; start from rest at 0 to
  // x = -x1, ẋ = -ẋ_y; ẍ = x⃛ = 0 at both ends.
  const double x1 = 0.03, v = 0.2, T = 0.5;
  for (int which = 0; which < 2; ++which) {
    auto snap = [&](double t) { return which == 0 ? brakingSnap(t, x1, v, T) : startSnap(t, x1, v, T); };
    const double x0 = which == 0 ? -x1 : 0.0, v0 = which == 0 ? v : 0.0;
    auto jerk = [&](double t) { return gauss4(snap, 0, t); };
    auto acc = [&](double t) { return gauss4(jerk, 0, t); };
    auto vel = [&](double t) { return v0 + gauss4(acc, 0, t); };
    const double x_end = x0 + gauss4(vel, 0, T);
    const double x_target = which == 0 ? 0.0 : -x1, v_target = which == 0 ? 0.0 : -v;
    EXPECT_NEAR(jerk(T), 0.0, 1e-10) << which;
    EXPECT_NEAR(acc(T), 0.0, 1e-12) << which;
    EXPECT_NEAR(vel(T), v_target, 1e-13) << which;
    EXPECT_NEAR(x_end, x_target, 1e-14) << which;
  }
}

TEST(ReversalCriterion, OptimumOfEq19IsHalfTheSpeedTimesT1) {
  const double v = 0.16, t1 = 0.5;
  const double x1 = optimalReversalDistance(v, t1);  // eq. (21)
  EXPECT_DOUBLE_EQ(x1, 0.04);
  const double I0 = reversalCriterion(kMass, x1, v, t1);
  for (double d : {-0.01, -1e-3, 1e-3, 0.01}) EXPECT_GT(reversalCriterion(kMass, x1 + d, v, t1), I0) << d;
  // ∂I_Z/∂x1 = 0 (eq. (20)); I_Z is quadratic in x1, so the central difference is exact up to
  // round-off (~1e-16·I0/h).
  const double h = 1e-4;
  const double slope = (reversalCriterion(kMass, x1 + h, v, t1) - reversalCriterion(kMass, x1 - h, v, t1)) / (2 * h);
  EXPECT_NEAR(slope, 0.0, 1e-9 * I0 / x1);
  // At the optimum C1 = 0 (eq. (22)): x⁗ of eq. (10) is the derivative of the x⃛ of eq. (23),
  // -60·ẋ_y·(6t²/t1⁵ - 6t/t1⁴ + 1/t1³).
  for (double t : {0.0, 0.1, 0.25, 0.4, 0.5}) {
    const double d_eq23 = -60 * v * (6 * t * t / std::pow(t1, 5) - 6 * t / std::pow(t1, 4) + 1 / std::pow(t1, 3));
    EXPECT_NEAR(brakingSnap(t, x1, v, t1), d_eq23, 1e-9 * std::abs(60 * v / std::pow(t1, 3)));
  }
}

TEST(ReversalCriterion, MotionLawOfEq29To31IsTheOptimalReversal) {
  // Δx = 0.4 m, t3 = 3 s: x1 = Δx/10, ẋ_y = 6Δx/(5t3), t1 = t3/6 (eq. (28)) satisfy eq. (21),
  // and the criterion of the law's own reversal (braking at the end of one stroke + start of the
  // next) equals eq. (19) at that optimum, 720·m·ẋ_y²/t1⁵.
  const double dx = 0.4, t3 = 3.0;
  const double x1 = dx / 10, v = 6 * dx / (5 * t3), t1 = t3 / 6;
  EXPECT_NEAR(x1, optimalReversalDistance(v, t1), 1e-15);
  auto snap2 = [&](double t) { return std::pow(camMotionTime(t, dx, t3).snap, 2); };
  const double Ib = 0.5 * kMass * gauss4(snap2, 5 * t3 / 6, t3);
  const double Is = 0.5 * kMass * gauss4(snap2, 0, t3 / 6);
  const double I19 = reversalCriterion(kMass, x1, v, t1);
  EXPECT_NEAR(Ib + Is, I19, 1e-10 * I19);
  EXPECT_NEAR(I19, 720 * kMass * v * v / std::pow(t1, 5), 1e-10 * I19);
  // The printed x⁗ is the derivative of the printed jerk (central difference, h = 1e-6 s: error
  // h²/6·|x⁽⁵⁾| ~ 1e-9 of the snap scale).
  for (double t : {0.1, 0.3, 2.6, 2.9}) {
    const double h = 1e-6;
    const double fd = (camMotionTime(t + h, dx, t3).jerk - camMotionTime(t - h, dx, t3).jerk) / (2 * h);
    EXPECT_NEAR(camMotionTime(t, dx, t3).snap, fd, 1e-6 * 15552 * dx / std::pow(t3, 4)) << t;
  }
}

}  // namespace
}  // namespace rollerdyn
