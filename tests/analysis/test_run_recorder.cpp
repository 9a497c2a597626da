// The stop rules every run shares (src/analysis/RunRecorder.h): the order in which they apply,
// that each one ends the run with its own status line and keeps the rows recorded so far, and
// what does not end a run (a slow star stage, a caller that only follows the progress).
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "analysis/RunRecorder.h"
#include "motor/Supply.h"
#include "scene/Scene.h"

using namespace rollerdyn;

namespace {


Scene sceneWithMotor(bool motor) {
  Scene s{};
  s.motor.enabled = motor;
  s.motor.omega_sync = 104.72;
  s.reducer.ratio = 9.8;
  s.loads.velocity_smoothing = 1e-3;
  s.simulation.t_end = 5.0;
  return s;
}

bool startsWith(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

}  // namespace

TEST(RunRecorder, TurningDriveRunsToItsEndAndKeepsEveryRow) {
  const Scene sc = sceneWithMotor(true);
  RunResult run;
  RunRecorder rec(sc, nullptr, false, run);
  const std::vector<double> v = {0.5, -0.5};
  for (int i = 0; i <= 500; ++i) {
    const double t = 0.01 * i;
    ASSERT_TRUE(rec.record(t, {t, 10.0 * t}, nullptr, {10.0 * t, 10.0, 10.0, &v, nullptr})) << t;
  }
  EXPECT_TRUE(run.stats.complete);
  EXPECT_EQ(run.stats.status, "completed");
  EXPECT_EQ(run.timeseries.rows.size(), 501u);
  EXPECT_TRUE(run.reactions.rows.empty());
}

TEST(RunRecorder, NonFiniteValueEndsTheRunBeforeAnyOtherRule) {
  const Scene sc = sceneWithMotor(true);
  RunResult run;
  std::atomic<bool> stop{true};  // an interrupt is pending too: the numerical failure comes first
  RunControl control;
  control.interrupt = &stop;
  RunRecorder rec(sc, nullptr, false, run, control);
  stop = false;
  ASSERT_TRUE(rec.record(0.0, {0.0, 0.0}, nullptr, {0.0, 10.0, 10.0, nullptr, nullptr}));  // the initial state
  stop = true;
  std::vector<double> reactions = {0.25, std::numeric_limits<double>::quiet_NaN()};
  EXPECT_FALSE(rec.record(0.25, {0.25, 1.0}, &reactions, {1.0, 10.0, 10.0, nullptr, nullptr}));
  EXPECT_FALSE(run.stats.complete);
  EXPECT_EQ(run.stats.status, "numerical failure (non-finite value) at t = 0.25 s");
  EXPECT_EQ(run.timeseries.rows.size(), 2u);  // the failed row is kept, as the tables show it
  EXPECT_EQ(run.reactions.rows.size(), 1u);
}

TEST(RunRecorder, HeldDriveStallsAfterTheRestWindowOnlyUnderFullSupply) {
  const Scene sc = sceneWithMotor(true);
  const std::vector<double> v = {0.0};
  // Held at standstill in a star stage (reduced voltage): slow is legitimate there.
  SupplyPhase star;
  star.stage = SupplyPhase::Stage::Star;
  RunResult slow;
  RunRecorder in_star(sc, nullptr, false, slow);
  for (int i = 0; i <= 300; ++i) ASSERT_TRUE(in_star.record(0.01 * i, {0.01 * i}, nullptr, {0.3, 0.0, 0.0, &v, &star}));
  // The same motion at the rated supply: held from t = 0, ended after StallDetector::kRestWindow.
  SupplyPhase rated;
  rated.stage = SupplyPhase::Stage::Rated;
  RunResult held;
  RunRecorder at_rated(sc, nullptr, false, held);
  double t_end = -1;
  for (int i = 0; i <= 300 && t_end < 0; ++i)
    if (!at_rated.record(0.01 * i, {0.01 * i}, nullptr, {0.3, 0.0, 0.0, &v, &rated})) t_end = 0.01 * i;
  EXPECT_NEAR(t_end, StallDetector::kRestWindow, 1e-9);
  EXPECT_EQ(held.stats.status, StallDetector::statusAt(0.0));
  EXPECT_EQ(StallDetector::motionOfStatus(held.stats.status), "stalled");
}

TEST(RunRecorder, TrippedSoftStarterEndsTheRunAsAFailedStart) {
  const Scene sc = sceneWithMotor(true);
  const Supply supply;
  SupplyPhase tripped;
  tripped.stage = SupplyPhase::Stage::Tripped;
  RunResult run;
  RunRecorder rec(sc, &supply, false, run);
  EXPECT_FALSE(rec.record(2.0, {2.0}, nullptr, {3.0, 5.0, 5.0, nullptr, &tripped}));
  EXPECT_TRUE(startsWith(run.stats.status, Supply::kTripStatus)) << run.stats.status;
  EXPECT_EQ(StallDetector::motionOfStatus(run.stats.status), "stalled");
}

TEST(RunRecorder, MachineWithoutMotorComesToRestUnlessItsCrankSpeedIsPrescribed) {
  const Scene sc = sceneWithMotor(false);
  const std::vector<double> creeping = {2e-4, -5e-4};  // every cart below v_s = 1 mm/s
  for (const bool prescribed : {false, true}) {
    RunResult run;
    RunRecorder rec(sc, nullptr, prescribed, run);
    double t_end = -1;
    for (int i = 0; i <= 300 && t_end < 0; ++i)
      if (!rec.record(0.01 * i, {0.01 * i}, nullptr, {0.1, 0.01, 0.01, &creeping, nullptr})) t_end = 0.01 * i;
    if (prescribed) {
      EXPECT_LT(t_end, 0.0);
      EXPECT_TRUE(run.stats.complete);
    } else {
      EXPECT_NEAR(t_end, RestDetector::kWindow, 1e-9);
      EXPECT_EQ(RestDetector::motionOfStatus(run.stats.status), "at_rest") << run.stats.status;
    }
  }
}

TEST(RunRecorder, InterruptStopsAfterTheProgressReportOfTheSameRow) {
  const Scene sc = sceneWithMotor(true);
  std::atomic<bool> stop{false};
  std::vector<double> reported;
  RunControl control;
  control.interrupt = &stop;
  control.progress = [&](double t, double t_end) {
    reported.push_back(t);
    EXPECT_EQ(t_end, 5.0);
    if (t >= 0.3 - 1e-12) stop = true;  // the user presses Ctrl-C while row t = 0.3 s is reported
  };
  RunResult run;
  RunRecorder rec(sc, nullptr, false, run, control);
  int rows = 0;
  for (int i = 0; i <= 100; ++i, ++rows)
    if (!rec.record(0.1 * i, {0.1 * i}, nullptr, {1.0 * i, 10.0, 10.0, nullptr, nullptr})) break;
  EXPECT_EQ(reported.size(), 3u);  // t = 0.1, 0.2, 0.3: the initial state at t = 0 is no progress
  EXPECT_EQ(run.timeseries.rows.size(), 4u);
  EXPECT_EQ(run.stats.status, "interrupted at t = 0.3 s");
}

TEST(RunRecorder, CauseFoundByTheModelEndsTheRunWithItsOwnWords) {
  const Scene sc = sceneWithMotor(true);
  RunResult run;
  RunRecorder rec(sc, nullptr, false, run);
  rec.fail("integration failed at t = 1.5 s: step size too small");
  EXPECT_TRUE(rec.ended());
  EXPECT_FALSE(run.stats.complete);
  EXPECT_EQ(run.stats.status, "integration failed at t = 1.5 s: step size too small");
}
