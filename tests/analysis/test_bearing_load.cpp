// Equivalent dynamic load and L10 life (BearingLoad.h) against closed forms of sinusoidal loads:
// over whole periods, E[(F0 + F1·sin)³] = F0³ + 3/2·F0·F1², and with a speed weight the moments
// of sin and |sin| give the other cases (derived in each test).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "analysis/BearingLoad.h"

using namespace rollerdyn;

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Series {
  std::vector<double> t, F, n;
};

// F = F0 + F1·sin(Ωt), n = speed(sin(Ωt)) over `periods` whole periods, step h.
template <class Speed>
Series sampled(double F0, double F1, double Omega, int periods, double h, Speed speed) {
  Series s;
  const double T = periods * 2 * kPi / Omega;
  const long N = std::lround(T / h);
  for (long i = 0; i <= N; ++i) {
    const double t = T * i / N, sn = std::sin(Omega * t);
    s.t.push_back(t);
    s.F.push_back(F0 + F1 * sn);
    s.n.push_back(speed(sn));
  }
  return s;
}

}  // namespace

TEST(BearingLoad, UnweightedSinusoidGivesClosedFormCubicMean) {
  const double F0 = 5000, F1 = 2000;
  const Series s = sampled(F0, F1, 7.0, 3, 1e-3, [](double) { return 0.0; });
  const JointLoad j = jointLoad(s.t, s.F, {}, 0, s.t.size());
  EXPECT_NEAR(j.mean, F0, 1e-6 * F0);
  EXPECT_NEAR(j.amplitude, F1, 1e-4 * F1);  // sampled extremes
  EXPECT_NEAR(j.peak, F0 + F1, 1e-4 * F1);
  EXPECT_NEAR(j.equivalent, std::cbrt(F0 * F0 * F0 + 1.5 * F0 * F1 * F1), 1e-9 * F0);
  EXPECT_TRUE(std::isnan(j.mean_speed));
}

TEST(BearingLoad, SpeedWeightShiftsTheMeanTowardsFastInstants) {
  // n = n0·(1 + sin): E[(F0 + F1 s)³(1 + s)] = F0³ + 3/2·F0·F1² + 3/2·F0²·F1 + 3/8·F1³, E[n] = n0.
  const double F0 = 3000, F1 = 1000, n0 = 12.0;
  const Series s = sampled(F0, F1, 5.0, 4, 1e-3, [&](double sn) { return n0 * (1 + sn); });
  const JointLoad j = jointLoad(s.t, s.F, s.n, 0, s.t.size());
  const double expected = std::cbrt(F0 * F0 * F0 + 1.5 * F0 * F1 * F1 + 1.5 * F0 * F0 * F1 + 0.375 * F1 * F1 * F1);
  EXPECT_NEAR(j.equivalent, expected, 1e-9 * expected);
  EXPECT_NEAR(j.mean_speed, n0, 1e-9 * n0);
}

TEST(BearingLoad, AbsoluteValueOfSpeedIsTheWeight) {
  // A rolling guide roller turns at |v|/(d/2) whichever way the cart goes: n ∝ |sin|.
  // E[(F0 + F1 s)³|s|] / E|s| = F0³ + 2·F0·F1² (E|s| = 2/π, E|s|³ = 4/(3π)).
  const double F0 = 4000, F1 = 1500;
  const Series s = sampled(F0, F1, 3.0, 2, 2e-5, [](double sn) { return -40.0 * sn; });
  const JointLoad j = jointLoad(s.t, s.F, s.n, 0, s.t.size());
  const double expected = std::cbrt(F0 * F0 * F0 + 2 * F0 * F1 * F1);
  EXPECT_NEAR(j.equivalent, expected, 1e-6 * expected);
  EXPECT_NEAR(j.mean_speed, 40.0 * 2 / kPi, 1e-6 * 40.0);
}

TEST(BearingLoad, RatingLifeInRevolutionsAndHours) {
  EXPECT_DOUBLE_EQ(ratingLifeRevolutions(20000, 10000), 8e6);
  // 8e6 revolutions at 2π rad/s = 1 rev/s: 8e6/3600 h.
  EXPECT_NEAR(ratingLifeHours(20000, 10000, 2 * kPi), 8e6 / 3600.0, 1e-9);
  EXPECT_TRUE(std::isnan(ratingLifeRevolutions(0, 10000)));
  EXPECT_TRUE(std::isnan(ratingLifeHours(20000, 10000, 0)));
}

TEST(BearingLoad, ShortOrNonFiniteWindowsGiveNaN) {
  const std::vector<double> t = {0, 1, 2}, F = {1, NAN, 3};
  EXPECT_TRUE(std::isnan(jointLoad(t, F, {}, 0, 3).equivalent));
  EXPECT_TRUE(std::isnan(jointLoad(t, {1, 2, 3}, {}, 0, 1).mean));
  EXPECT_TRUE(std::isnan(jointLoad(t, {1, 2, 3}, {0, 0, 0}, 0, 3).equivalent));  // never turns
  EXPECT_NEAR(jointLoad(t, {1, 2, 3}, {0, 0, 0}, 0, 3).peak, 3, 0);
}

// A rod of l = 4r swings through ±asin(1/4) = ±14.4775°: ISO 281's 10⁶ revolutions are
// 10⁶·180°/28.955° = 6.2165e6 oscillations, and the conversion needs 2γ ≥ 720°/Z: Z ≥ 24.87.
TEST(BearingLoad, OscillationLifeFromTheFullSwingAngle) {
  const double gamma = rodSwingAmplitude(0.2, 0.8);
  EXPECT_NEAR(gamma * 180 / kPi, 14.477512185929925, 1e-12);
  EXPECT_NEAR(oscillationLife(1e6, 2 * gamma), 1e6 * 180 / (2 * 14.477512185929925), 1e-3);
  EXPECT_NEAR(rollingElementsForOscillation(2 * gamma), 720 / (2 * 14.477512185929925), 1e-12);
  EXPECT_TRUE(std::isnan(rodSwingAmplitude(0.8, 0.8)));  // no crank-slider without l > r
  EXPECT_TRUE(std::isnan(oscillationLife(1e6, 0)));
}
