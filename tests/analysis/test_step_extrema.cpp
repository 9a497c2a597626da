// The crank speed's extrema inside CVODE's steps (analysis/StepExtrema.h), on ω = 10 + sin t:
// located on CVODE's interpolant, and forgotten beyond a restart that replaced the motion there.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "analysis/StepExtrema.h"

namespace rollerdyn {
namespace {

constexpr double kPi = 3.14159265358979323846;

// ω̇ = cos t from ω(0) = 10 while `turning`, else ω̇ = 1 (a motion without extrema), to the
// relative accuracy rtol.
OdeProblem sineSpeed(const bool& turning, double rtol) {
  OdeProblem p;
  p.t0 = 0.0;
  p.stop_time = 20.0;
  p.y0 = Eigen::VectorXd::Constant(1, 10.0);
  p.rtol = rtol;
  p.atol = Eigen::VectorXd::Constant(1, 10.0 * rtol);
  p.absolute_only = {false};
  p.rhs = [&turning](double t, const double*, double* ydot) {
    ydot[0] = turning ? std::cos(t) : 1.0;
    return true;
  };
  return p;
}

TEST(StepExtrema, LocatesTheExtremaOnCvodesInterpolant) {
  const bool turning = true;
  OdeProblem p = sineSpeed(turning, 1e-8);
  StepExtrema extrema(0);
  extrema.install(p);
  CvodeIntegrator integ(p);
  extrema.observe(integ);
  ASSERT_TRUE(integ.advanceTo(4 * kPi - 0.1)) << integ.error();
  const std::vector<CrankSpeedExtremum> found = extrema.takeUpTo(integ.time());
  ASSERT_EQ(found.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_NEAR(found[k].t, kPi / 2 + k * kPi, 1e-6) << k;
    EXPECT_NEAR(found[k].omega, k % 2 == 0 ? 11.0 : 9.0, 1e-5) << k;  // CVODE's global error
  }
}

// An event applied at an output time that CVODE interpolated back to: its last step had already
// passed the maximum at π/2, which the restart's new motion never reaches.
TEST(StepExtrema, ARestartForgetsTheExtremaOfTheStepBeyondIt) {
  bool turning = true;
  OdeProblem p = sineSpeed(turning, 1e-4);  // long steps
  StepExtrema extrema(0);
  extrema.install(p);
  double t_observed = 0;  // the last step's end
  p.on_step = [inner = p.on_step, &t_observed](double t, const double* y, const double* ydot, bool after_step) {
    t_observed = std::max(t_observed, t);
    inner(t, y, ydot, after_step);
  };
  CvodeIntegrator integ(p);
  extrema.observe(integ);
  const double t_event = kPi / 2 - 1e-3;
  ASSERT_TRUE(integ.advanceTo(t_event)) << integ.error();
  ASSERT_GT(t_observed, kPi / 2) << "the step did not reach beyond the maximum: nothing to forget";
  turning = false;
  integ.restart(integ.time(), integ.y());
  ASSERT_TRUE(integ.advanceTo(3.0)) << integ.error();
  EXPECT_TRUE(extrema.takeUpTo(3.0).empty());
}

TEST(StepExtrema, APrescribedSpeedHasNoObserver) {
  const bool turning = true;
  OdeProblem p = sineSpeed(turning, 1e-6);
  StepExtrema extrema(-1);
  extrema.install(p);
  EXPECT_FALSE(p.on_step);
}

}  // namespace
}  // namespace rollerdyn
