// CvodeIntegrator (CVODE's Adams and BDF methods behind a SUNDIALS-free interface) on equations
// with closed-form solutions, its tolerance handling, and its failure path.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "numerics/CvodeIntegrator.h"

namespace rollerdyn {
namespace {

OdeProblem oscillator(double rtol) {
  // ẍ = -ω²·x, x(0) = 1, ẋ(0) = 0: x = cos ωt, ẋ = -ω·sin ωt.
  OdeProblem p;
  const double w = 3.0;
  p.rhs = [w](double, const double* y, double* yd) {
    yd[0] = y[1];
    yd[1] = -w * w * y[0];
    return true;
  };
  p.t0 = 0.0;
  p.stop_time = 2.0;
  p.y0 = Eigen::Vector2d(1.0, 0.0);
  p.rtol = rtol;
  p.atol = Eigen::Vector2d::Constant(rtol);
  p.absolute_only = {false, false};
  return p;
}

TEST(CvodeIntegrator, OscillatorMatchesClosedFormAndConvergesWithTolerance) {
  double previous = 1.0;
  for (double rtol : {1e-4, 1e-7, 1e-10}) {
    CvodeIntegrator integ(oscillator(rtol));
    double err = 0.0;
    for (int k = 1; k <= 20; ++k) {
      const double t = 0.1 * k;
      ASSERT_TRUE(integ.advanceTo(t)) << integ.error();
      EXPECT_DOUBLE_EQ(integ.time(), t);
      err = std::max({err, std::abs(integ.y()(0) - std::cos(3.0 * t)),
                      std::abs(integ.y()(1) + 3.0 * std::sin(3.0 * t)) / 3.0});
    }
    EXPECT_LT(err, 1e3 * rtol) << rtol;   // global error within a few decades of the tolerance
    EXPECT_LT(err, previous) << rtol;     // and it shrinks as the tolerance is tightened
    previous = err;
    EXPECT_GT(integ.steps(), 0);
    EXPECT_GE(integ.rhsEvaluations(), integ.steps());
    EXPECT_GE(integ.jacobianEvaluations(), 1);  // Newton: at least the first step's matrix
    EXPECT_GE(integ.newtonConvergenceFailures(), 0);
  }
}

TEST(CvodeIntegrator, FixedPointIterationSolvesTheSameProblem) {
  OdeProblem p = oscillator(1e-9);
  p.newton = false;
  CvodeIntegrator integ(p);
  ASSERT_TRUE(integ.advanceTo(2.0)) << integ.error();
  EXPECT_NEAR(integ.y()(0), std::cos(6.0), 1e-6);
  EXPECT_EQ(integ.jacobianEvaluations(), 0);  // no Jacobian without Newton
}

TEST(CvodeIntegrator, AbsoluteOnlyStateIgnoresItsMagnitude) {
  // y' = 1 from y = 1e6: with rtol·|y| the tolerance would be 1e6·rtol; absolute_only keeps atol.
  OdeProblem p;
  p.rhs = [](double t, const double*, double* yd) {
    yd[0] = 1.0 + std::sin(50.0 * t);
    return true;
  };
  p.stop_time = 1.0;
  p.y0 = Eigen::VectorXd::Constant(1, 1e6);
  p.rtol = 1e-6;
  p.atol = Eigen::VectorXd::Constant(1, 1e-8);
  p.absolute_only = {true};
  CvodeIntegrator integ(p);
  ASSERT_TRUE(integ.advanceTo(1.0)) << integ.error();
  const double exact = 1e6 + 1.0 + (1.0 - std::cos(50.0)) / 50.0;
  EXPECT_NEAR(integ.y()(0), exact, 1e-6);
}

TEST(CvodeIntegrator, FailingRightHandSideIsReportedNotThrown) {
  OdeProblem p = oscillator(1e-6);
  p.rhs = [](double t, const double*, double* yd) {
    yd[0] = yd[1] = 0.0;
    return t < 0.5;  // cannot be evaluated past t = 0.5
  };
  CvodeIntegrator integ(p);
  EXPECT_FALSE(integ.advanceTo(1.0));
  EXPECT_FALSE(integ.error().empty());
  EXPECT_LT(integ.time(), 1.0);
  // Where it gave up: its steps crept up to the point past which f cannot be evaluated.
  EXPECT_GT(integ.failureTime(), 0.4);
  EXPECT_LE(integ.failureTime(), 0.5);
}

TEST(CvodeIntegrator, ThrowingRightHandSideEndsTheRunWithItsMessage) {
  OdeProblem p = oscillator(1e-6);
  p.rhs = [](double t, const double*, double* yd) -> bool {
    if (t > 0.25) throw std::runtime_error("geometry out of range");
    yd[0] = yd[1] = 0.0;
    return true;
  };
  CvodeIntegrator integ(p);
  EXPECT_FALSE(integ.advanceTo(1.0));
  EXPECT_NE(integ.error().find("geometry out of range"), std::string::npos) << integ.error();
}

TEST(CvodeIntegrator, MismatchedToleranceSizesAreRejected) {
  OdeProblem p = oscillator(1e-6);
  p.absolute_only = {false};
  EXPECT_THROW(CvodeIntegrator{p}, std::invalid_argument);
}

// The oscillator plus a fast first-order lag that follows it and feeds nothing back:
// ż = (x - z)/τ, z(0) = 1. Its Jacobian column is exactly (0, 0, -1/τ), so a structure that gives
// it as known is exact. With x = cos ωt the closed form is
//   z = (cos ωt + ωτ·sin ωt)/(1 + ω²τ²) + (1 - 1/(1 + ω²τ²))·e^(-t/τ).
OdeProblem oscillatorWithLag(double rtol, double tau) {
  OdeProblem p = oscillator(rtol);
  const double w = 3.0;
  p.rhs = [w, tau](double, const double* y, double* yd) {
    yd[0] = y[1];
    yd[1] = -w * w * y[0];
    yd[2] = (y[0] - y[2]) / tau;
    return true;
  };
  p.y0 = Eigen::Vector3d(1.0, 0.0, 1.0);
  p.atol = Eigen::Vector3d::Constant(rtol);
  p.absolute_only = {false, false, false};
  return p;
}

double lagExact(double t, double tau) {
  const double w = 3.0, d = 1.0 + w * w * tau * tau;
  return (std::cos(w * t) + w * tau * std::sin(w * t)) / d + (1.0 - 1.0 / d) * std::exp(-t / tau);
}

TEST(CvodeIntegrator, StructuredJacobianSolvesTheSameProblemWithFewerEvaluations) {
  const double tau = 1e-3;  // stiff against the step the oscillator needs: Newton has work to do
  OdeProblem full_problem = oscillatorWithLag(1e-9, tau);
  OdeProblem structured_problem = full_problem;
  structured_problem.jacobian.difference_quotient = {true, true, false};
  structured_problem.jacobian.diagonal = Eigen::Vector3d(0.0, 0.0, -1.0 / tau);
  CvodeIntegrator full(full_problem), structured(structured_problem);
  for (int k = 1; k <= 20; ++k) {
    const double t = 0.1 * k;
    ASSERT_TRUE(full.advanceTo(t)) << full.error();
    ASSERT_TRUE(structured.advanceTo(t)) << structured.error();
    EXPECT_NEAR(structured.y()(0), std::cos(3.0 * t), 1e-6) << t;
    EXPECT_NEAR(structured.y()(2), lagExact(t, tau), 1e-6) << t;
    EXPECT_NEAR(full.y()(2), lagExact(t, tau), 1e-6) << t;
    EXPECT_NEAR(structured.y()(2), full.y()(2), 1e-8) << t;
  }
  ASSERT_GT(structured.jacobianEvaluations(), 0);
  // Two difference-quotient columns per Jacobian instead of three.
  EXPECT_LT(structured.rhsEvaluations(), full.rhsEvaluations());
}

TEST(CvodeIntegrator, KnownEntriesOfKnownColumnsAreAdded) {
  // Adds w' = c·z, an integral of the lag state (like an energy integral of a power that depends
  // on it): z's column is known, -1/τ on the diagonal and c in w's row (given by known_entries);
  // w's column is zero. Closed form: w = c·∫z dt =
  //   c·[(sin ωt/ω + τ·(1 - cos ωt))/(1 + ω²τ²) + (1 - 1/(1 + ω²τ²))·τ·(1 - e^(-t/τ))].
  const double tau = 1e-3, c = 2.0, w = 3.0;
  OdeProblem p = oscillatorWithLag(1e-9, tau);
  p.rhs = [w, tau, c](double, const double* y, double* yd) {
    yd[0] = y[1];
    yd[1] = -w * w * y[0];
    yd[2] = (y[0] - y[2]) / tau;
    yd[3] = c * y[2];
    return true;
  };
  p.y0 = Eigen::Vector4d(1.0, 0.0, 1.0, 0.0);
  p.atol = Eigen::Vector4d::Constant(1e-9);
  p.absolute_only = {false, false, false, false};
  p.jacobian.difference_quotient = {true, true, false, false};
  p.jacobian.diagonal = Eigen::Vector4d(0.0, 0.0, -1.0 / tau, 0.0);
  int calls = 0;
  p.jacobian.known_entries = [&calls, c](double, const double*, Eigen::Ref<Eigen::MatrixXd> jac) {
    EXPECT_EQ(jac(3, 2), 0.0);  // known column: only its diagonal before the callback
    jac(3, 2) = c;
    ++calls;
    return true;
  };
  CvodeIntegrator integ(p);
  for (int k = 1; k <= 20; ++k) {
    const double t = 0.1 * k, d = 1.0 + w * w * tau * tau;
    ASSERT_TRUE(integ.advanceTo(t)) << integ.error();
    const double exact = c * ((std::sin(w * t) / w + tau * (1.0 - std::cos(w * t))) / d +
                              (1.0 - 1.0 / d) * tau * (1.0 - std::exp(-t / tau)));
    EXPECT_NEAR(integ.y()(3), exact, 1e-6) << t;
  }
  EXPECT_EQ(calls, integ.jacobianEvaluations());
}

TEST(CvodeIntegrator, MalformedJacobianStructureIsRejected) {
  OdeProblem p = oscillatorWithLag(1e-6, 1e-3);
  p.jacobian.difference_quotient = {true, true};  // one entry short
  p.jacobian.diagonal = Eigen::Vector2d::Zero();
  EXPECT_THROW(CvodeIntegrator{p}, std::invalid_argument);
  p.jacobian.difference_quotient = {true, true, false};
  p.jacobian.diagonal = Eigen::Vector3d(0.0, 0.0, std::nan(""));  // known column without a value
  EXPECT_THROW(CvodeIntegrator{p}, std::invalid_argument);
  p.jacobian.diagonal = Eigen::Vector3d(0.0, 0.0, -1e3);
  p.newton = false;  // a Jacobian needs the Newton corrector
  EXPECT_THROW(CvodeIntegrator{p}, std::invalid_argument);
}

// A stiff linear system: a fast mode λ_f = -1e5 /s decays under a slow one (λ_s = -1 /s), the
// shape of an induction machine's electrical transients under the mechanical motion. Closed form:
// y0 = e^{λ_s t}, y1 = e^{λ_s t} - e^{λ_f t} (driven from y0). BDF follows the slow mode at
// orders up to 5 with steps far longer than 1/|λ_f|; Adams-Moulton is stable at such steps only
// at its orders 1 and 2, so it must take the short steps of a low-order method (measured: BDF
// 316 steps, Adams 2563, ratio 8.1; asserted: at least 4).
OdeProblem stiffPair(bool bdf) {
  OdeProblem p;
  const double ls = -1.0, lf = -1e5;
  p.rhs = [=](double, const double* y, double* yd) {
    yd[0] = ls * y[0];
    yd[1] = lf * y[1] + (ls - lf) * y[0];
    return true;
  };
  p.t0 = 0.0;
  p.stop_time = 5.0;
  p.y0 = Eigen::Vector2d(1.0, 0.0);
  p.rtol = 1e-8;
  p.atol = Eigen::Vector2d::Constant(1e-10);
  p.absolute_only = {false, false};
  p.bdf = bdf;
  return p;
}

TEST(CvodeIntegrator, BdfSolvesAStiffProblemInFarFewerStepsThanAdams) {
  CvodeIntegrator bdf(stiffPair(true)), adams(stiffPair(false));
  ASSERT_TRUE(bdf.advanceTo(5.0)) << bdf.error();
  ASSERT_TRUE(adams.advanceTo(5.0)) << adams.error();
  const double y0 = std::exp(-5.0), y1 = std::exp(-5.0) - std::exp(-5e5);
  EXPECT_NEAR(bdf.y()(0), y0, 1e-6 * y0);
  EXPECT_NEAR(bdf.y()(1), y1, 1e-6 * y0);
  EXPECT_LT(4 * bdf.steps(), adams.steps()) << "BDF " << bdf.steps() << ", Adams " << adams.steps();
}

TEST(CvodeIntegrator, BdfOrderAboveFiveOrWithoutNewtonIsRejected) {
  OdeProblem p = stiffPair(true);
  p.max_order = 6;
  EXPECT_THROW(CvodeIntegrator{p}, std::invalid_argument);
  p.max_order = 0;
  p.newton = false;
  EXPECT_THROW(CvodeIntegrator{p}, std::invalid_argument);
}

// Events of a run: the oscillator's x = cos 3t falls through 0.5 at t = π/9 (rising event
// function g = 0.5 - x), the run then jumps the state (x -> -x) and continues from there; a stop
// time keeps the integrator from stepping past a later discontinuity.
TEST(CvodeIntegrator, StopsAtARootAndRestartsFromAChangedState) {
  OdeProblem p = oscillator(1e-10);
  p.root = [](double, const double* y) { return 0.5 - y[0]; };
  CvodeIntegrator integ(p);
  integ.enableRoot(true);
  ASSERT_TRUE(integ.advanceTo(1.0)) << integ.error();
  ASSERT_TRUE(integ.rootFound());
  const double t_root = M_PI / 9.0;
  EXPECT_NEAR(integ.time(), t_root, 1e-8);
  EXPECT_NEAR(integ.y()(0), 0.5, 1e-8);
  const long steps_before = integ.steps(), jacobians_before = integ.jacobianEvaluations();
  // Jump: x -> -x (the exact solution is then -cos 3t, passing the jump time).
  integ.enableRoot(false);
  Eigen::VectorXd y = integ.y();
  y = -y;
  integ.restart(integ.time(), y);
  integ.setStopTime(0.6);
  ASSERT_TRUE(integ.advanceTo(1.0)) << integ.error();
  EXPECT_FALSE(integ.rootFound());
  EXPECT_DOUBLE_EQ(integ.time(), 0.6);  // stopped at the stop time, not at t_out
  EXPECT_NEAR(integ.y()(0), -std::cos(1.8), 1e-7);
  integ.setStopTime(2.0);
  ASSERT_TRUE(integ.advanceTo(2.0)) << integ.error();
  EXPECT_NEAR(integ.y()(0), -std::cos(6.0), 1e-7);
  // Counters keep counting across the restart (CVODE's own start from zero).
  EXPECT_GT(integ.steps(), steps_before);
  EXPECT_GT(integ.jacobianEvaluations(), jacobians_before);
}

TEST(CvodeIntegrator, EnablingAnAbsentEventFunctionIsAnError) {
  CvodeIntegrator integ(oscillator(1e-6));
  EXPECT_THROW(integ.enableRoot(true), std::logic_error);
}

}  // namespace
}  // namespace rollerdyn
