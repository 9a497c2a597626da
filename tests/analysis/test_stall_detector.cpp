// The stall rule shared by both models (src/analysis/StallDetector.h).
#include <gtest/gtest.h>

#include "analysis/StallDetector.h"

using namespace rollerdyn;

namespace {
constexpr double kSync = 104.72 / 9.8;  // ω0/u of Loveikin, Pochka, Romasevych (2018) [rad/s]
}

TEST(StallDetector, StartFromRestThatSpinsUpIsNotAStall) {
  StallDetector d(true, kSync);
  for (double t = 0; t <= 5.0; t += 0.005) {
    const double w = std::min(10.0, 50.0 * t);  // passes 1 % of 10.7 rad/s after 2 ms
    EXPECT_FALSE(d.update(t, w, w)) << t;
  }
}

TEST(StallDetector, DriveThatNeverStartsIsStalledAtZeroAfterTheWindow) {
  StallDetector d(true, kSync);
  double t = 0;
  for (; t < StallDetector::kWindow - 1e-9; t += 0.005) EXPECT_FALSE(d.update(t, 0.01, 0.02));
  EXPECT_TRUE(d.update(StallDetector::kWindow, 0.01, 0.02));
  EXPECT_DOUBLE_EQ(d.since(), 0.0);
  EXPECT_EQ(d.status(), "motor stalled at t = 0 s");
}

TEST(StallDetector, SpellIsTimedFromItsStartAndResetByRecovery) {
  StallDetector d(true, kSync);
  EXPECT_FALSE(d.update(1.0, 5.0, 5.0));
  EXPECT_FALSE(d.update(2.0, 0.05, 5.0));  // crank slow: spell starts
  EXPECT_FALSE(d.update(2.5, 5.0, 5.0));   // recovered: spell forgotten
  EXPECT_FALSE(d.update(3.0, 5.0, -1.0));  // motor side running backwards: new spell
  EXPECT_FALSE(d.update(3.9, 5.0, -1.0));
  EXPECT_TRUE(d.update(4.0, 5.0, -1.0));
  EXPECT_DOUBLE_EQ(d.since(), 3.0);
}

TEST(StallDetector, SceneWithoutMotorNeverStalls) {
  StallDetector d(false, kSync);
  for (double t = 0; t <= 3.0; t += 0.1) EXPECT_FALSE(d.update(t, 0.0, 0.0));
}

// The threshold is 1 % of the synchronous crank speed ω0/u (StallDetector.h): a crank creeping at
// 1.5 % of it for 2 s is turning, one at 0.5 % for 1 s has stalled.
TEST(StallDetector, ThresholdIsOnePercentOfTheSynchronousCrankSpeed) {
  StallDetector creeping(true, kSync), stopped(true, kSync);
  bool stalled = false;
  for (double t = 0; t <= 2.0; t += 0.005) stalled = stalled || creeping.update(t, 0.015 * kSync, 0.015 * kSync);
  EXPECT_FALSE(stalled) << "a crank at 1.5 % of ω0/u is not stalled";
  for (double t = 0; t <= 1.0 + 1e-9; t += 0.005) stalled = stopped.update(t, 0.005 * kSync, 0.005 * kSync);
  EXPECT_TRUE(stalled) << "a crank at 0.5 % of ω0/u for 1 s is stalled";
}
