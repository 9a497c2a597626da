// The crank speed's extrema located inside integrator steps (CrankSpeedExtrema.h): on the cubic
// Hermite interpolant of a step and on an integrator's own interpolant.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/CrankSpeedExtrema.h"

namespace rollerdyn {
namespace {

constexpr double kPi = 3.14159265358979323846;

// ω = 10 + sin t, ε = cos t, in steps of h: the maxima at π/2 + 2πk and minima at 3π/2 + 2πk.
CrankSpeedExtremaFinder sineInSteps(double h, double t_end, bool with_dense) {
  CrankSpeedExtremaFinder f;
  const CrankSpeedExtremaFinder::Dense exact = [](double t, double& w, double& e) {
    w = 10.0 + std::sin(t);
    e = std::cos(t);
  };
  f.restart(0.0, 10.0, 1.0);
  for (double t = h; t <= t_end + 1e-12; t += h)
    f.stepTo(t, 10.0 + std::sin(t), std::cos(t), with_dense ? exact : CrankSpeedExtremaFinder::Dense());
  return f;
}

TEST(CrankSpeedExtrema, HermiteFindsEachExtremumInsideItsStep) {
  // Steps of 0.3 rad: the cubic's error in ω is ~h⁴/384·max|ω⁗| = 2e-5, in the time of the
  // extremum ~h³/24 / |ω̈| ≈ 1e-3 (ε's interpolant is a quadratic).
  const CrankSpeedExtremaFinder f = sineInSteps(0.3, 4 * kPi, false);
  ASSERT_EQ(f.extrema().size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) {
    const double t_true = kPi / 2 + k * kPi;
    EXPECT_NEAR(f.extrema()[k].t, t_true, 2e-3) << k;
    EXPECT_NEAR(f.extrema()[k].omega, k % 2 == 0 ? 11.0 : 9.0, 5e-5) << k;
  }
}

TEST(CrankSpeedExtrema, TheIntegratorsInterpolantLocatesToRoundOff) {
  const CrankSpeedExtremaFinder f = sineInSteps(0.7, 4 * kPi, true);  // long steps
  ASSERT_EQ(f.extrema().size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_NEAR(f.extrema()[k].t, kPi / 2 + k * kPi, 1e-9) << k;
    EXPECT_NEAR(f.extrema()[k].omega, k % 2 == 0 ? 11.0 : 9.0, 1e-14) << k;
  }
}

TEST(CrankSpeedExtrema, NoSignChangeOfTheAccelerationNoExtremum) {
  CrankSpeedExtremaFinder f;
  f.restart(0.0, 1.0, 2.0);
  f.stepTo(1.0, 3.0, 2.0);   // ε > 0 throughout
  f.stepTo(2.0, 3.0, 0.0);   // ε reaches 0 at the step's end: not strictly inside
  f.stepTo(3.0, 3.0, 0.0);   // a plateau (a cam's constant-speed stretch)
  EXPECT_TRUE(f.extrema().empty());
}

TEST(CrankSpeedExtrema, ARestartDoesNotInterpolateAcrossTheEvent) {
  CrankSpeedExtremaFinder f;
  f.restart(0.0, 10.0, 1.0);
  f.stepTo(1.0, 10.5, 0.2);
  f.restart(1.0, 10.5, -5.0);  // an event at t = 1 s changes ε, not ω
  f.stepTo(2.0, 8.0, -1.0);
  EXPECT_TRUE(f.extrema().empty());  // ε changed sign at the event, not inside a step
}

TEST(CrankSpeedExtrema, ExtremaAfterTheLastRowAreLeftOut) {
  CrankSpeedExtremaFinder f = sineInSteps(0.1, 4 * kPi, false);
  ASSERT_EQ(f.extrema().size(), 4u);
  f.dropAfter(2.5 * kPi);  // an event cut the step short
  EXPECT_EQ(f.extrema().size(), 2u);
  EXPECT_EQ(f.takeUpTo(1.0 * kPi).size(), 1u);
}

}  // namespace
}  // namespace rollerdyn
