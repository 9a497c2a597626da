// The supply's switching events in a CVODE run (analysis/CvodeSupplyEvents.h), on a rotor that
// accelerates at 10 rad/s² in star and 20 rad/s² after the changeover: CVODE stops at the event,
// the model's mapping is applied there and the run continues from the new state.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/CvodeSupplyEvents.h"

namespace rollerdyn {
namespace {

using Stage = SupplyPhase::Stage;

// y = (ω_r, count of the events the model applied); the supply's phase kept here, as a model
// keeps it.
struct Rotor {
  Supply supply;
  SupplyPhase phase = supply.initialPhase();

  explicit Rotor(const MotorStart& start) : supply(start, MotorStop{}, 100.0, 50.0, 0.5) {}

  OdeProblem problem() {
    OdeProblem p;
    p.stop_time = 10.0;
    p.y0 = Eigen::Vector2d(0.0, 0.0);
    p.rtol = 1e-10;
    p.atol = Eigen::Vector2d(1e-10, 1e-10);
    p.absolute_only = {false, false};
    p.rhs = [this](double, const double*, double* ydot) {
      ydot[0] = phase.stage == Stage::Star ? 10.0 : 20.0;
      ydot[1] = 0.0;
      return true;
    };
    return p;
  }
  CvodeSupplyEvents::Model events() {
    CvodeSupplyEvents::Model e;
    e.supply = &supply;
    e.t_end = 10.0;
    e.rotor_speed = [](const double* y) { return y[0]; };
    e.phase = [this] { return phase; };
    e.apply = [this](double t, Eigen::VectorXd& y, bool speed_reached) {
      if (!supply.applyDueEvents(phase, t, y(0), speed_reached, nullptr, nullptr)) return false;
      y(1) += 1.0;
      return true;
    };
    return e;
  }
};

// Runs the rotor to t = 10 s with output times every 1.5 s; the integrator's state at the end.
Eigen::VectorXd runToTen(Rotor& rotor) {
  OdeProblem p = rotor.problem();
  CvodeSupplyEvents events(rotor.events());
  events.install(p);
  CvodeIntegrator integ(p);
  events.arm(integ);
  for (double t = 1.5; t < 10.0; t += 1.5) {
    EXPECT_TRUE(events.advanceTo(integ, t)) << integ.error();
    EXPECT_EQ(integ.time(), t);  // the output time, whatever happened on the way
  }
  EXPECT_TRUE(events.advanceTo(integ, 10.0)) << integ.error();
  return integ.y();
}

TEST(CvodeSupplyEvents, TheSpeedTriggerStopsCvodeAtItsRootAndTheModelsMappingApplies) {
  MotorStart start;
  start.method = StartMethod::StarDelta;
  start.changeover_speed = 85.0;  // reached at 8.5 s, between the output times 7.5 and 9
  Rotor rotor(start);
  const Eigen::VectorXd y = runToTen(rotor);
  EXPECT_EQ(rotor.phase.stage, Stage::Rated);
  EXPECT_NEAR(rotor.phase.since, 8.5, 1e-8);
  EXPECT_NEAR(y(0), 85.0 + 20.0 * 1.5, 1e-6);
  EXPECT_EQ(y(1), 1.0);
}

TEST(CvodeSupplyEvents, ATimedEventStopsCvodeAtItsTime) {
  MotorStart start;
  start.method = StartMethod::StarDelta;
  start.changeover_time = 2.0;  // between the output times 1.5 and 3
  start.changeover_gap = 0.05;  // a second event, 50 ms later
  Rotor rotor(start);
  const Eigen::VectorXd y = runToTen(rotor);
  EXPECT_EQ(rotor.phase.stage, Stage::Rated);
  EXPECT_EQ(rotor.phase.since, 2.05);
  EXPECT_NEAR(y(0), 20.0 + 20.0 * 8.0, 1e-6);
  EXPECT_EQ(y(1), 2.0);
}

TEST(CvodeSupplyEvents, AConstantSupplyHasNone) {
  Rotor rotor{MotorStart{}};
  ASSERT_TRUE(rotor.supply.constant());
  const Eigen::VectorXd y = runToTen(rotor);
  EXPECT_NEAR(y(0), 200.0, 1e-6);
  EXPECT_EQ(y(1), 0.0);
}

}  // namespace
}  // namespace rollerdyn
