// The modal analysis with a motor law that has states of its own (the space-phasor (Park) machine)
// and what it says when it cannot be made. Finding of the six-cart trial: with motor.model=park
// the period map's Newton iteration did not converge (the machine's flux linkages were left at zero:
// no torque), simulate printed the first estimate's warning alone, and `modes` fell back to frozen
// modes at 1 rad/s (the initial speed, 0, the running speed is 10.68 rad/s) with a negative
// damping ratio and no warning.
#include <cmath>

#include <gtest/gtest.h>

#include "modes/ModalAnalysis.h"
#include "modes/RunModes.h"
#include "scene/SceneParser.h"
#include "support/SixCartScene.h"
#include "reduced/ReducedModel.h"

using namespace rollerdyn;
using namespace rollerdyn::modes;

namespace {

Scene sixCarts(const std::vector<std::string>& more = {}) { return test_scenes::sixCartsAt60(more); }

ModesReport light(const Scene& s, int max_newton = 30, int warmup_periods = 3) {
  ModesOptions o;
  o.multibody = false;
  o.campbell = false;
  o.charts = false;
  o.angles = 36;
  o.max_newton = max_newton;
  o.warmup_periods = warmup_periods;
  return analyseModes(s, o);
}

bool mentions(const std::vector<std::string>& w, const std::string& text) {
  for (const std::string& s : w)
    if (s.find(text) != std::string::npos) return true;
  return false;
}

}  // namespace

// The Park machine's steady running is found, at the speed a simulation settles at: 10.68 rad/s
// (simulate, t_end = 6 s, speed ripple 0.00029). The mean speed is set by the mean torque balance
// on the machine's static curve alone, which both share; 1 % covers the simulation's window mean
// (the ripple is 0.03 %). Its coupling mode is damped (no negative damping ratio anywhere).
TEST(ParkModes, TheSteadyMotionIsFoundAtTheRunningSpeed) {
  const ModesReport r = light(sixCarts({"motor.model=park"}));
  ASSERT_TRUE(r.steady.found) << r.steady.failure;
  EXPECT_NEAR(r.steady.omega_mean, 10.68, 0.01 * 10.68);
  EXPECT_TRUE(r.steady.verdict.stable) << r.steady.verdict.text;
  ASSERT_FALSE(r.frozen.empty());
  EXPECT_GT(r.frozen[0].torsional_damping.min, 0);
  // The frozen-angle modes are taken along that motion, not at the initial speed.
  for (const FrozenAngle& f : r.frozen[0].angles) EXPECT_NEAR(f.point.omega, 10.68, 0.05 * 10.68);
}

// Without a steady motion (Newton given no iterations and no warm-up revolutions: the first guess,
// uniform rotation, is not the orbit), the frozen-angle modes are taken at the running speed
// the motor's static curve gives against the mean load, never at the initial speed (0 here, which
// the old fallback raised to 1 rad/s), and a warning says the analysis is incomplete and why.
TEST(ParkModes, WithoutASteadyMotionTheFrozenModesAreAtTheRunningSpeedAndAWarningSaysSo) {
  const Scene s = sixCarts();
  const ModesReport r = light(s, 0, 0);
  ASSERT_FALSE(r.steady.found);
  const SteadyGuess g = steadyGuess(ReducedModel(s));
  ASSERT_TRUE(g.ok) << g.failure;
  ASSERT_FALSE(r.frozen.empty());
  ASSERT_FALSE(r.frozen[0].angles.empty());
  for (const FrozenAngle& f : r.frozen[0].angles) EXPECT_DOUBLE_EQ(f.point.omega, g.omega);
  EXPECT_GT(g.omega, 10.0);  // the running speed, not 1 rad/s
  EXPECT_TRUE(mentions(r.warnings, "modal analysis incomplete")) << (r.warnings.empty() ? "no warning" : r.warnings[0]);
  EXPECT_TRUE(mentions(r.warnings, r.steady.failure));
}

// A machine whose mean load exceeds the motor's breakdown torque has no running speed: no modes at
// all and a warning that the analysis is not applicable (never silence).
TEST(ParkModes, WithoutARunningSpeedTheAnalysisIsDeclaredNotApplicable) {
  const Scene s = sixCarts({"loads.roller_force_direction=opposes_velocity"});
  ASSERT_FALSE(steadyGuess(ReducedModel(s)).ok);
  const ModesReport r = light(s);
  ASSERT_FALSE(r.steady.found);
  ASSERT_FALSE(r.frozen.empty());
  EXPECT_FALSE(r.frozen[0].ok);
  EXPECT_TRUE(r.frozen[0].angles.empty());
  EXPECT_TRUE(mentions(r.warnings, "modal analysis not applicable")) << (r.warnings.empty() ? "no warning" : r.warnings[0]);
  // The run's verdict beside a first-estimate hit: tests/studies/test_run_resonance_verdict.cpp.
}

// A negative frozen-angle damping ratio is printed with what it means (the mode grows), never as
// a plain damping.
TEST(ModesConsole, ANegativeFrozenDampingRatioIsNamedAsAGrowingMode) {
  ModesReport r;
  r.scene = "synthetic";
  r.elastic = r.motor = true;
  ModelFrozenModes m;
  m.model = "reduced";
  m.ok = true;
  m.torsional = Band{65.0, 64.0, 66.0};
  m.torsional_damping = Band{0.4, -0.00196, 1.0};
  r.frozen.push_back(m);
  const std::string text = modesText(r);
  ASSERT_NE(text.find("damping ratio -0.00196"), std::string::npos) << text;
  EXPECT_NE(text.find("grows"), std::string::npos) << text;
}

// The Campbell diagram of the Park machine varies the crank speed as a frequency converter does:
// each speed is reached. The circuit laws take their speed from the supply frequency, and the
// speed shift used to move only omega_sync, so every point ran at the operating speed 10.68 rad/s.
// 2 %: the shift is exact for a load that does not depend on the speed (DriveOrbit.h); the
// forming loads here depend on it only through the carts' smoothing speed.
TEST(ParkModes, TheCampbellDiagramReachesItsSpeeds) {
  ModesOptions o;
  o.multibody = false;
  o.charts = false;
  o.angles = 36;
  o.speeds = 3;
  o.speed_low = 0.8;
  o.speed_high = 1.2;
  const ModesReport r = analyseModes(sixCarts({"motor.model=park"}), o);
  ASSERT_TRUE(r.steady.found) << r.steady.failure;
  ASSERT_EQ(r.campbell.points.size(), 3u);
  for (const CampbellPoint& p : r.campbell.points) {
    ASSERT_TRUE(p.found) << p.failure;
    EXPECT_NEAR(p.omega_mean, p.omega_target, 0.02 * p.omega_target);
  }
}
