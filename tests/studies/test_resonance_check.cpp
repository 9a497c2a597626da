// Resonance check of the elastic coupling (Dyomin (two rotors) eq. (10)) for installation scenes:
// the first estimate and the orders it checks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "reduced/ReducedModel.h"
#include "studies/ResonanceCheck.h"
#include "support/Loveikin2018Scene.h"

namespace rollerdyn {
namespace {

// The orders whose harmonic of Q(φ) = M_load(φ, ω) + ½·J_n2'(φ)·ω² (the torque the crank side
// puts against the coupling at a steady ω, the crank equation of the reduced model) is at least
// `share` of the largest, by a direct Fourier sum over 2048 angles (not the tool's FFT), with the
// analytic J_n2'. Also the amplitudes.
std::vector<int> ordersAbove(const Scene& s, double omega, double share, std::vector<double>* amplitude = nullptr) {
  const ReducedModel m(s);
  const int n = 2048, k_max = 24;
  std::vector<double> q(n);
  for (int i = 0; i < n; ++i) {
    const double phi = 2 * M_PI * i / n;
    q[i] = m.loadTorque(phi, omega) + 0.5 * m.crankSideInertiaDerivative(phi) * omega * omega;
  }
  std::vector<double> A(k_max + 1, 0.0);
  for (int k = 1; k <= k_max; ++k) {
    double a = 0, b = 0;
    for (int i = 0; i < n; ++i) {
      a += q[i] * std::cos(k * 2 * M_PI * i / n);
      b += q[i] * std::sin(k * 2 * M_PI * i / n);
    }
    A[k] = 2 * std::hypot(a, b) / n;
  }
  const double largest = *std::max_element(A.begin(), A.end());
  std::vector<int> out;
  for (int k = 1; k <= k_max; ++k)
    if (A[k] >= share * largest) out.push_back(k);
  if (amplitude) *amplitude = A;
  return out;
}

TEST(ResonanceCheck, NaturalFrequencyOfLoveikin2018Drive) {
  const Scene s = test_scenes::loveikin2018Scene();
  const ReducedModel m(s);
  // Mean J_n2 over a revolution against an independent fine trapezoidal average.
  double J2 = 0;
  const int n = 100000;
  for (int i = 0; i < n; ++i) J2 += m.crankSideInertia(2 * M_PI * i / n) / n;
  EXPECT_NEAR(meanCrankSideInertia(s), J2, 1e-9 * J2);
  const ResonanceReport r = checkResonance(s, 10.5);
  ASSERT_TRUE(r.applicable);
  EXPECT_DOUBLE_EQ(r.J1, s.motorSideInertia());
  EXPECT_NEAR(r.p0, std::sqrt(2e5 * (r.J1 + J2) / (r.J1 * J2)), 1e-9 * r.p0);  // eq. (10)
}

// Dyomin's own two rotors on a chain driven by a harmonic torque (`rollerdyn chain`): ω, 2ω, 3ω, 5ω.
TEST(ResonanceCheck, TheChainsHarmonicDriveIsCheckedAtOneTwoThreeFiveOmega) {
  const double p0 = 60.0;
  // n·ω = p0/ratio: ratio 1.05 and 0.95 are inside, 1.11 and 0.89 outside the 10 % band.
  for (int n : {1, 2, 3, 5}) {
    EXPECT_EQ(resonanceHits(p0, p0 / (1.05 * n)).size(), 1u) << n;
    EXPECT_EQ(resonanceHits(p0, p0 / (0.95 * n)).size(), 1u) << n;
    const auto outside = resonanceHits(p0, p0 / (1.11 * n));
    for (const ResonanceHit& h : outside) EXPECT_NE(h.harmonic, n);
  }
  EXPECT_TRUE(resonanceHits(p0, p0 / 4).empty());   // 4ω: not among the harmonics checked
  EXPECT_TRUE(resonanceHits(p0, 0.0).empty());      // no speed, no check
}

// Six equal carts at 60° on one side: the exciting torque has only multiples of 6 (the layout's
// phase sums cancel the rest), and the first estimate checks exactly the orders whose harmonic is
// at least 1 % of the largest. So p0 = 3.02ω (c = 5e4 N·m/rad in the trial) is no hit: order 3 is
// not in the torque (amplitude below 1e-9 of the largest), whatever the docs said.
TEST(ResonanceCheck, TheFirstEstimateChecksTheOrdersTheExcitingTorqueHas) {
  Scene s = test_scenes::loveikin2018Scene();
  s.carts.count = 6;
  s.carts.side.assign(6, 1);
  s.crank.offset = M_PI / 3;
  const double omega = 10.6;
  std::vector<double> A;
  const std::vector<int> expected = ordersAbove(s, omega, 0.01, &A);
  ASSERT_FALSE(expected.empty());
  for (int k : expected) EXPECT_EQ(k % 6, 0) << k;
  const ResonanceReport r = checkResonance(s, omega);
  EXPECT_EQ(r.orders, expected);
  const double largest = *std::max_element(A.begin(), A.end());
  EXPECT_LT(A[3], 1e-9 * largest);
  s.coupling.stiffness = 5e4;
  const ResonanceReport soft = checkResonance(s, 10.0);
  ASSERT_NEAR(soft.p0 / 10.0, 3.0, 0.3);  // p0 ≈ 3ω
  EXPECT_TRUE(soft.hits.empty()) << "order " << soft.hits[0].harmonic;
  const ResonanceReport near6 = checkResonance(s, soft.p0 / 6.05);  // and order 6 is a hit
  ASSERT_EQ(near6.hits.size(), 1u);
  EXPECT_EQ(near6.hits[0].harmonic, 6);
}

// Carts of their own: four carts at 90° excite only 4, 8, ... while they are equal; an empty cart
// (no loads) or a crank 2° off brings the other orders in, each as large as the difference makes
// it, and the first estimate checks exactly those at least 1 % of the largest (no longer every
// order up to 12 whatever its size).
TEST(ResonanceCheck, UnequalCartsAddTheOrdersTheirDifferenceMakesLarge) {
  Scene s = test_scenes::loveikin2018Scene();
  const double omega = 10.6;
  ASSERT_EQ(checkResonance(s, omega).orders, ordersAbove(s, omega, 0.01));
  for (int k : checkResonance(s, omega).orders) EXPECT_EQ(k % 4, 0) << k;
  Scene empty = s;
  empty.cart_loads.assign(4, CartLoads{s.loads.roller_force_front, s.loads.roller_force_rear, s.loads.roller_normal_front,
                                       s.loads.roller_normal_rear, s.loads.rolling_resistance});
  empty.cart_loads[1] = CartLoads{};
  const std::vector<int> e = ordersAbove(empty, omega, 0.01);
  EXPECT_EQ(checkResonance(empty, omega).orders, e);
  EXPECT_TRUE(std::any_of(e.begin(), e.end(), [](int k) { return k % 4 != 0; }));
  Scene off = s;
  off.crank.angle_errors = {0, 0, 2 * M_PI / 180, 0};
  EXPECT_EQ(checkResonance(off, omega).orders, ordersAbove(off, omega, 0.01));
}

}  // namespace
}  // namespace rollerdyn
