// What the periodic orbit costs (PeriodicFlow.h): without samples, the converged orbit's monodromy
// is that of Newton's last flow, which started at the solution; the period is not integrated again
// (a stability chart finds one orbit per grid point).
#include <cmath>

#include <gtest/gtest.h>

#include "modes/PeriodicFlow.h"

using namespace rollerdyn::modes;

namespace {

// ẍ + 2ζωẋ + ω²x = cos t, period 2π: periodic response x(0) = (ω²-1)/D, ẋ(0) = 2ζω/D,
// D = (ω²-1)² + (2ζω)².
PeriodicSystem forcedOscillator() {
  const double w = 3.0, zeta = 0.1;
  PeriodicSystem s;
  s.n = 2;
  s.period = 2 * M_PI;
  s.scale = Eigen::Vector2d(0.1, 0.1);
  s.rhs = [=](double t, const Eigen::VectorXd& x, Eigen::VectorXd& f) {
    f.resize(2);
    f << x(1), std::cos(t) - w * w * x(0) - 2 * zeta * w * x(1);
  };
  return s;
}

Eigen::Vector2d exactStart() {
  const double w = 3.0, zeta = 0.1;
  const double D = (w * w - 1) * (w * w - 1) + 4 * zeta * zeta * w * w;
  return {(w * w - 1) / D, 2 * zeta * w / D};
}

}  // namespace

// Started on the orbit with a tolerance its first flow meets: no Newton step and no second flow,
// so the orbit costs exactly the right-hand sides of one flow with the variational equations.
TEST(PeriodicOrbitCost, OrbitStartedOnTheSolutionCostsOneFlow) {
  const PeriodicSystem s = forcedOscillator();
  OrbitOptions o;
  o.warmup_periods = 0;
  o.tolerance = 1e-6;  // far above the map's integration error (rtol 1e-9)
  const PeriodicOrbit orbit = findPeriodicOrbit(s, exactStart(), o);
  ASSERT_TRUE(orbit.found) << orbit.failure;
  EXPECT_EQ(orbit.newton_iterations, 0);
  FlowOptions var = o.flow;
  var.monodromy = true;
  const FlowResult one = flowOverPeriod(s, exactStart(), var);
  ASSERT_TRUE(one.ok);
  EXPECT_EQ(orbit.evaluations, one.evaluations);
}

// From a poor guess (Newton steps needed): the monodromy and the end state reported are those of
// the flow from the orbit's start, bit for bit, as when the period was integrated once more.
TEST(PeriodicOrbitCost, MonodromyIsTheFlowsFromTheConvergedStartBitForBit) {
  const PeriodicSystem s = forcedOscillator();
  OrbitOptions o;
  const PeriodicOrbit orbit = findPeriodicOrbit(s, Eigen::Vector2d(0, 0), o);
  ASSERT_TRUE(orbit.found) << orbit.failure;
  EXPECT_GT(orbit.newton_iterations, 0);
  FlowOptions var = o.flow;
  var.monodromy = true;
  const FlowResult again = flowOverPeriod(s, orbit.x0, var);
  ASSERT_TRUE(again.ok);
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) EXPECT_EQ(orbit.monodromy(i, j), again.monodromy(i, j)) << i << "," << j;
  EXPECT_NEAR(orbit.x0(0), exactStart()(0), 1e-8);
  EXPECT_NEAR(orbit.x0(1), exactStart()(1), 1e-8);
}

// With samples the orbit still integrates the period once more at the solution for them.
TEST(PeriodicOrbitCost, SamplesAreTakenOnTheConvergedOrbit) {
  const PeriodicSystem s = forcedOscillator();
  OrbitOptions o;
  o.flow.samples = 8;
  const PeriodicOrbit orbit = findPeriodicOrbit(s, Eigen::Vector2d(0, 0), o);
  ASSERT_TRUE(orbit.found) << orbit.failure;
  ASSERT_EQ(orbit.s_samples.size(), 8u);
  const double w = 3.0, zeta = 0.1, D = (w * w - 1) * (w * w - 1) + 4 * zeta * zeta * w * w;
  for (size_t k = 0; k < orbit.s_samples.size(); ++k) {
    const double t = orbit.s_samples[k];
    // x(t) = ((ω²-1)·cos t + 2ζω·sin t)/D
    EXPECT_NEAR(orbit.x_samples[k](0), ((w * w - 1) * std::cos(t) + 2 * zeta * w * std::sin(t)) / D, 1e-7) << t;
  }
}
