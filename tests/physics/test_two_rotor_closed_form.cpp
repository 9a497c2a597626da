// The closed form of Dyomin (two rotors) (physics/TwoRotorClosedForm.h) checked against the
// equation it solves, not against itself: the twist ψ(t) must satisfy eq. (7),
// ψ̈ + 2δ1·ψ̇ + p0²·ψ = M(t)/J1 + M_c/J2, with δ1 and p0 written out here (eq. (9), (10)), and
// start from rest. Derivatives by central differences with step h: the truncation error of the
// second difference is ψ''''·h²/12 ~ (5ω)⁴·|ψ|·h²/12, about 1e-7 of the forcing at h = 1e-4 s.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/TwoRotorClosedForm.h"

namespace rollerdyn {
namespace {

TwoRotorParameters chain(double b, double omega) {
  TwoRotorParameters p;
  p.J1 = 73.6;
  p.J2 = 95.0;
  p.k = 2e5;
  p.b = b;
  p.M1 = 1000;
  p.alpha = 0.3;
  p.Mc = 1000 * (M_PI - 0.6) / M_PI;
  p.omega = omega;
  return p;
}

// max over t of |ψ̈ + 2δ1ψ̇ + p0²ψ − F(t)| relative to max |F − mean F| over the same samples.
double odeResidual(const TwoRotorParameters& p, bool with_transient) {
  const double p0sq = p.k * (p.J1 + p.J2) / (p.J1 * p.J2), d1 = p.b * (p.J1 + p.J2) / (2 * p.J1 * p.J2);
  const double h = 1e-4;
  double worst = 0, scale = 0;
  for (double t = 0.05; t < 2.0; t += 0.0137) {
    auto psi = [&](double tt) { return twistExact(p, tt, with_transient); };
    const double y = psi(t), yp = (psi(t + h) - psi(t - h)) / (2 * h), ypp = (psi(t + h) - 2 * y + psi(t - h)) / (h * h);
    const double F = driveTorque(p, t) / p.J1 + p.Mc / p.J2;
    worst = std::max(worst, std::abs(ypp + 2 * d1 * yp + p0sq * y - F));
    scale = std::max(scale, std::abs(F - p0sq * meanTwist(p)));
  }
  return worst / scale;
}

TEST(TwoRotorClosedForm, FrequenciesEq9Eq10Eq14) {
  const TwoRotorParameters p = chain(2000, 10.47);
  const double p0 = std::sqrt(2e5 * (73.6 + 95.0) / (73.6 * 95.0)), d1 = 2000 * (73.6 + 95.0) / (2 * 73.6 * 95.0);
  EXPECT_NEAR(naturalFrequency(p), p0, 1e-12 * p0);
  EXPECT_NEAR(dampingRate(p), d1, 1e-12 * d1);
  EXPECT_NEAR(dampedFrequency(p), std::sqrt(p0 * p0 - d1 * d1), 1e-12 * p0);
  EXPECT_TRUE(std::isnan(dampedFrequency(chain(1e6, 10.47))));  // overdamped: no oscillating transient
}

TEST(TwoRotorClosedForm, ExactTwistSolvesEq7FromRest) {
  for (double b : {2000.0, 0.0, 1e5 /* overdamped */})
    for (double omega : {10.47, 23.15}) {
      if (b == 0.0 && omega == 23.15) continue;  // undamped at 3ω ≈ p0: no bounded steady state
      const TwoRotorParameters p = chain(b, omega);
      EXPECT_LT(odeResidual(p, true), 1e-5) << "b = " << b << ", omega = " << omega;
      EXPECT_LT(odeResidual(p, false), 1e-5) << "b = " << b << ", omega = " << omega;
      EXPECT_NEAR(twistExact(p, 0.0, true), 0.0, 1e-12);
      const double h = 1e-6;
      EXPECT_NEAR((twistExact(p, h, true) - twistExact(p, -h, true)) / (2 * h), 0.0, 1e-6);  // ψ̇(0) = 0
    }
}

TEST(TwoRotorClosedForm, PrintedAmplitudesDropTheOneOverN) {
  // Eq. (18) as printed, 2M1/(πJ1·D5), is five times the answer to the sin 5ωt/5 term of (8),
  // eq. (20) twice the answer to sin 2α·cos 2ωt/2: n = 5 and n = 2 have one term each.
  const TwoRotorParameters p = chain(2000, 10.47);
  const auto h = closedFormResponse(p);
  ASSERT_EQ(h.size(), 4u);
  EXPECT_EQ(h[3].n, 5);
  EXPECT_NEAR(h[3].amplitude_printed / h[3].amplitude, 5.0, 1e-12);
  EXPECT_NEAR(h[1].amplitude_printed / h[1].amplitude, 2.0, 1e-12);
}

}  // namespace
}  // namespace rollerdyn
