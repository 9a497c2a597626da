// Order amplitudes over whole crank revolutions (analysis/CrankOrders.h) on series with known
// harmonics, sampled at a non-uniform crank speed as a real run is.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/CrankOrders.h"

using namespace rollerdyn;

namespace {
// y = 3 + 2·cos(φ + 0.4) + 0.5·sin(4φ) on rows 1 ms apart, the crank turning at
// ω(t) = 10·(1 + 0.2·sin(4φ)) rad/s (a steady drive's speed ripple), for `turns` revolutions.
Table series(double turns) {
  Table ts;
  ts.columns = {"t", "phi_crank", "y"};
  double phi = 0.3, t = 0;
  const double h = 1e-3;
  while (phi < 0.3 + 2 * M_PI * turns) {
    ts.rows.push_back({t, phi, 3 + 2 * std::cos(phi + 0.4) + 0.5 * std::sin(4 * phi)});
    phi += h * 10 * (1 + 0.2 * std::sin(4 * phi));
    t += h;
  }
  return ts;
}
}  // namespace

TEST(CrankOrders, RecoversKnownHarmonicsOverWholeRevolutions) {
  const CrankOrderAmplitudes a = crankOrderAmplitudes(series(6.5), "y", 3, 5);
  ASSERT_TRUE(a.valid);
  ASSERT_EQ(a.amplitude.size(), 6u);
  // Trapezoids of h <= 0.012 rad on an uneven grid: the error of a product of orders up to 2k = 8
  // is ~h²·(2k)²/12 ≈ 8e-4 of its amplitude, i.e. ~4e-4 on A_4 = 0.5 and far less on the others.
  EXPECT_NEAR(a.amplitude[0], 3.0, 5e-4);
  EXPECT_NEAR(a.amplitude[1], 2.0, 5e-4);
  EXPECT_NEAR(a.amplitude[2], 0.0, 5e-4);
  EXPECT_NEAR(a.amplitude[3], 0.0, 5e-4);
  EXPECT_NEAR(a.amplitude[4], 0.5, 5e-4);
  EXPECT_NEAR(a.amplitude[5], 0.0, 5e-4);
  EXPECT_GT(a.t_begin, 0.0);
  EXPECT_LT(a.t_begin, a.t_end);
}

TEST(CrankOrders, RefusesARunShorterThanTheWindowOrTurningBack) {
  EXPECT_FALSE(crankOrderAmplitudes(series(1.5), "y", 3, 2).valid);
  Table back = series(4);
  for (auto& row : back.rows) row[1] = -row[1];  // the crank turns backwards
  EXPECT_FALSE(crankOrderAmplitudes(back, "y", 2, 2).valid);
  EXPECT_THROW(crankOrderAmplitudes(series(4), "y", 0, 2), std::invalid_argument);
}
