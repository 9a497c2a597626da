// The supply a starting method applies over time (motor/Supply.h): each method's stages and
// laws, the events in order, the law's states mapped at each switching event, the brake and the
// restart. A small law defined here records what it is told.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "motor/Supply.h"

namespace rollerdyn {
namespace {

using Stage = SupplyPhase::Stage;

// One state; steady current I(U = 1, ω) = 100·(1 - ω/ω0) + 10 A; switchStates records the calls.
class RecordingLaw : public MotorLaw {
 public:
  std::string description() const override { return "test law"; }
  double synchronousSpeed() const override { return 100.0; }
  int stateCount() const override { return 1; }
  void evaluate(const SupplyState&, double, const double*, MotorEvaluation& out, double* xdot) const override {
    out.torque = 0;
    if (xdot) xdot[0] = 0;
  }
  void switchStates(const SupplyState& before, const SupplyState& after, double, double* x) const override {
    calls.push_back({before, after});
    x[0] += 1.0;
  }
  double steadyTorque(const SupplyState&, double) const override { return 0; }
  double steadyCurrent(const SupplyState& s, double w) const override {
    return s.voltage * (100.0 * (1.0 - w / 100.0) + 10.0);
  }
  struct Call {
    SupplyState before, after;
  };
  mutable std::vector<Call> calls;
};

class NoCurrentLaw : public RecordingLaw {
 public:
  double steadyCurrent(const SupplyState&, double) const override { return MotorEvaluation::kNotModelled; }
};

constexpr double kW0 = 100.0;

Supply supplyOf(const MotorStart& start, const MotorStop& stop = {}, const MotorLaw* law = nullptr) {
  return Supply(start, stop, kW0, 50.0, 0.5, law);
}

TEST(Supply, WithoutSettingsTheRatedSupplyIsConnectedAllTheTime) {
  const Supply s = supplyOf({});
  EXPECT_TRUE(s.constant());
  const SupplyPhase p = s.initialPhase();
  EXPECT_EQ(p.stage, Stage::Rated);
  const SupplyState x = s.state(p, 3.0, 50.0);
  EXPECT_TRUE(x.connected);
  EXPECT_EQ(x.voltage, 1.0);
  EXPECT_EQ(x.frequency, 1.0);
  EXPECT_TRUE(std::isinf(s.nextEventTime(p)));
  EXPECT_TRUE(std::isnan(s.triggerSpeed(p)));
  EXPECT_FALSE(Supply().hasBrake());
}

TEST(Supply, DirectOnLineLaterWaitsDisconnected) {
  MotorStart st;
  st.t_on = 0.5;
  st.phase = 0.3;
  const Supply s = supplyOf(st);
  EXPECT_FALSE(s.constant());
  SupplyPhase p = s.initialPhase();
  EXPECT_EQ(p.stage, Stage::Waiting);
  EXPECT_FALSE(s.state(p, 0.2, 0).connected);
  EXPECT_EQ(s.nextEventTime(p), 0.5);
  EXPECT_FALSE(s.applyDueEvents(p, 0.4999, 0, false, nullptr, nullptr));
  EXPECT_TRUE(s.applyDueEvents(p, 0.5, 0, false, nullptr, nullptr));
  EXPECT_EQ(p.stage, Stage::Rated);
  EXPECT_EQ(p.since, 0.5);
  EXPECT_TRUE(s.state(p, 0.6, 0).connected);
  EXPECT_EQ(s.state(p, 0.6, 0).phase, 0.3);
  EXPECT_EQ(s.ratedFrom(), 0.5);
}

TEST(Supply, StarDeltaByTimeWithOpenTransition) {
  MotorStart st;
  st.method = StartMethod::StarDelta;
  st.changeover_time = 2.0;
  st.changeover_gap = 0.05;
  st.phase = 0.1;
  RecordingLaw law;
  const Supply s = supplyOf(st, {}, &law);
  SupplyPhase p = s.initialPhase();
  ASSERT_EQ(p.stage, Stage::Star);
  const SupplyState star = s.state(p, 1.0, 0);
  EXPECT_NEAR(star.voltage, 1.0 / std::sqrt(3.0), 1e-15);
  EXPECT_EQ(star.phase, 0.1);
  EXPECT_EQ(s.atSwitchOn().voltage, star.voltage);
  EXPECT_EQ(s.nextEventTime(p), 2.0);
  double x = 0;
  EXPECT_TRUE(s.applyDueEvents(p, 2.0, 80.0, false, &law, &x));
  EXPECT_EQ(p.stage, Stage::Gap);
  EXPECT_FALSE(s.state(p, 2.01, 80).connected);
  EXPECT_NEAR(s.nextEventTime(p), 2.05, 1e-15);
  EXPECT_TRUE(s.applyDueEvents(p, 2.05, 79.0, false, &law, &x));
  EXPECT_EQ(p.stage, Stage::Rated);
  const SupplyState delta = s.state(p, 3.0, 90);
  EXPECT_EQ(delta.voltage, 1.0);
  EXPECT_NEAR(delta.phase, 0.1 + M_PI / 6.0, 1e-15);  // delta phase voltage leads the star one by 30°
  // The law was told twice: star -> disconnected, disconnected -> delta.
  ASSERT_EQ(law.calls.size(), 2u);
  EXPECT_TRUE(law.calls[0].before.connected);
  EXPECT_FALSE(law.calls[0].after.connected);
  EXPECT_FALSE(law.calls[1].before.connected);
  EXPECT_TRUE(law.calls[1].after.connected);
  EXPECT_EQ(x, 2.0);
  EXPECT_NEAR(s.ratedFrom(), 2.05, 1e-15);
}

TEST(Supply, StarDeltaBySpeedIsASpeedTrigger) {
  MotorStart st;
  st.method = StartMethod::StarDelta;
  st.changeover_speed = 85.0;
  RecordingLaw law;
  const Supply s = supplyOf(st, {}, &law);
  SupplyPhase p = s.initialPhase();
  EXPECT_EQ(s.triggerSpeed(p), 85.0);
  EXPECT_TRUE(std::isinf(s.nextEventTime(p)));
  EXPECT_TRUE(std::isnan(s.ratedFrom()));
  double x = 0;
  EXPECT_FALSE(s.applyDueEvents(p, 1.0, 84.9, false, &law, &x));
  // A root finder stops at the crossing, where the speed may be a hair below the trigger.
  EXPECT_TRUE(s.applyDueEvents(p, 1.2, 84.9999999, true, &law, &x));
  EXPECT_EQ(p.stage, Stage::Rated);
  EXPECT_EQ(p.since, 1.2);
  EXPECT_TRUE(std::isnan(s.triggerSpeed(p)));
  ASSERT_EQ(law.calls.size(), 1u);
  EXPECT_NEAR(law.calls[0].before.voltage, 1 / std::sqrt(3.0), 1e-15);
  EXPECT_EQ(law.calls[0].after.voltage, 1.0);
}

TEST(Supply, SoftStarterRampAndCurrentLimit) {
  MotorStart st;
  st.method = StartMethod::SoftStarter;
  st.t_on = 1.0;
  st.ramp_time = 4.0;
  st.initial_voltage = 0.4;
  const Supply plain = supplyOf(st);
  SupplyPhase p = plain.initialPhase();
  plain.applyDueEvents(p, 1.0, 0, false, nullptr, nullptr);
  ASSERT_EQ(p.stage, Stage::Ramp);
  EXPECT_DOUBLE_EQ(plain.state(p, 1.0, 0).voltage, 0.4);
  EXPECT_DOUBLE_EQ(plain.state(p, 3.0, 0).voltage, 0.7);
  EXPECT_DOUBLE_EQ(plain.nextEventTime(p), 5.0);
  EXPECT_EQ(plain.ratedFrom(), 5.0);
  plain.applyDueEvents(p, 5.0, 0, false, nullptr, nullptr);
  EXPECT_EQ(p.stage, Stage::Rated);

  // I(U = 1) = 110 A at rest, 60 A at half speed: a 50 A limit holds U to 50/110 and 50/60.
  st.current_limit = 50.0;
  RecordingLaw law;
  const Supply limited = supplyOf(st, {}, &law);
  SupplyPhase q{Stage::Ramp, 1.0};
  EXPECT_DOUBLE_EQ(limited.state(q, 1.0, 0.0).voltage, 0.4);           // the ramp is below the limit
  EXPECT_DOUBLE_EQ(limited.state(q, 3.0, 0.0).voltage, 50.0 / 110.0);  // the limit takes over
  EXPECT_DOUBLE_EQ(limited.state(q, 4.0, 50.0).voltage, 50.0 / 60.0);  // U_ramp = 0.85 above it
  EXPECT_DOUBLE_EQ(limited.state(q, 4.5, 90.0).voltage, 0.925);        // ramp again: 50/20 > U_ramp
  NoCurrentLaw kloss_like;
  EXPECT_THROW(supplyOf(st, {}, &kloss_like), std::invalid_argument);
  EXPECT_THROW(supplyOf(st, {}, nullptr), std::invalid_argument);
}

// A real soft starter keeps its current limit after the ramp until the motor is up to speed. The
// test law draws I(U = 1, ω) = 100·(1 - ω/100) + 10 A, so a 50 A limit is reached at U_n where
// 100·(1 - ω/100) = 40: ω_lim = 60 rad/s. Before the fix the ramp's end switched to the rated
// supply whatever the speed: a direct-on-line start at t_on + t_ramp.
TEST(Supply, CurrentLimitHoldsAfterTheRampUntilTheCurrentAtRatedVoltageIsWithinIt) {
  MotorStart st;
  st.method = StartMethod::SoftStarter;
  st.t_on = 1.0;
  st.ramp_time = 4.0;
  st.initial_voltage = 0.4;
  st.current_limit = 50.0;
  st.max_start_time = 10.0;
  RecordingLaw law;
  const Supply s = supplyOf(st, {}, &law);
  EXPECT_NEAR(s.limitSpeed(), 60.0, 1e-9);
  EXPECT_TRUE(std::isnan(s.ratedFrom()));  // known only in the run
  SupplyPhase p = s.initialPhase();
  s.applyDueEvents(p, 1.0, 0.0, false, nullptr, nullptr);
  ASSERT_EQ(p.stage, Stage::Ramp);
  EXPECT_EQ(s.nextEventTime(p), 5.0);
  // The ramp ends with the rotor at 30 rad/s, where U_n would draw 80 A: the limit stays.
  s.applyDueEvents(p, 5.0, 30.0, false, nullptr, nullptr);
  EXPECT_NE(p.stage, Stage::Rated);
  EXPECT_TRUE(s.state(p, 5.0, 30.0).connected);
  EXPECT_DOUBLE_EQ(s.state(p, 5.0, 30.0).voltage, 50.0 / 80.0);   // continuous with the ramp's last value
  EXPECT_DOUBLE_EQ(s.state(p, 8.0, 45.0).voltage, 50.0 / 65.0);   // long after the ramp, still limited
  EXPECT_FALSE(Supply::fullSupply(p));                             // the stall rule waits
  // Its end is the upward crossing of ω_lim (found by the run's root finding), not a time:
  EXPECT_NEAR(s.triggerSpeed(p), 60.0, 1e-9);
  EXPECT_EQ(s.nextEventTime(p), 11.0);  // the trip: t_on + max_start_time
  // The voltage reaches U_n continuously there.
  EXPECT_NEAR(s.state(p, 8.0, 60.0 - 1e-9).voltage, 1.0, 1e-10);
  EXPECT_EQ(s.state(p, 8.0, 59.0).voltage, 50.0 / 51.0);
  s.applyDueEvents(p, 8.5, 60.0, true, nullptr, nullptr);
  EXPECT_EQ(p.stage, Stage::Rated);  // the bypass
  EXPECT_EQ(s.state(p, 8.6, 60.0).voltage, 1.0);

  // A rotor already at ω_lim when the ramp ends: the bypass closes at the ramp's end.
  SupplyPhase q{Stage::Ramp, 1.0};
  s.applyDueEvents(q, 5.0, 70.0, false, nullptr, nullptr);
  EXPECT_EQ(q.stage, Stage::Rated);
}

// A start still limited at t_on + max_start_time trips the starter: the motor is disconnected
// for good, and the run's status line says why.
TEST(Supply, AStartStillLimitedAtItsMaximumStartTimeTripsTheStarter) {
  MotorStart st;
  st.method = StartMethod::SoftStarter;
  st.t_on = 1.0;
  st.ramp_time = 4.0;
  st.initial_voltage = 0.4;
  st.current_limit = 50.0;
  st.max_start_time = 10.0;
  RecordingLaw law;
  const Supply s = supplyOf(st, {}, &law);
  EXPECT_EQ(s.tripTime(), 11.0);
  SupplyPhase p = s.initialPhase();
  s.applyDueEvents(p, 1.0, 0.0, false, nullptr, nullptr);
  s.applyDueEvents(p, 5.0, 0.0, false, nullptr, nullptr);
  EXPECT_FALSE(s.applyDueEvents(p, 10.999, 20.0, false, nullptr, nullptr));
  EXPECT_TRUE(s.applyDueEvents(p, 11.0, 20.0, false, nullptr, nullptr));
  EXPECT_TRUE(Supply::tripped(p));
  EXPECT_FALSE(s.state(p, 12.0, 20.0).connected);
  EXPECT_TRUE(std::isinf(s.nextEventTime(p)));
  EXPECT_TRUE(std::isnan(s.triggerSpeed(p)));
  const std::string status = s.tripStatus(11.0);
  EXPECT_EQ(status.rfind("the soft starter tripped at t = 11 s: the motor had not reached the rotor speed 60 rad/s", 0),
            0u)
      << status;
  EXPECT_NE(status.find("motor.start.max_start_time = 10 s"), std::string::npos) << status;

  // max_start_time = 0: it never trips.
  st.max_start_time = 0.0;
  const Supply patient = supplyOf(st, {}, &law);
  SupplyPhase q{Stage::Ramp, 1.0};
  patient.applyDueEvents(q, 5.0, 0.0, false, nullptr, nullptr);
  EXPECT_TRUE(std::isinf(patient.nextEventTime(q)));
  EXPECT_TRUE(std::isinf(patient.tripTime()));
}

TEST(Supply, ACurrentLimitTheMotorCannotReachAtFullSpeedIsRefused) {
  MotorStart st;
  st.method = StartMethod::SoftStarter;
  st.ramp_time = 4.0;
  st.initial_voltage = 0.4;
  RecordingLaw law;
  st.current_limit = 9.0;  // below the no-load current 10 A: the bypass could never close
  try {
    supplyOf(st, {}, &law);
    ADD_FAILURE() << "a limit below the no-load current was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("motor.start.current_limit = 9 A is at or below the motor's no-load current 10 A"),
              std::string::npos)
        << e.what();
  }
  st.current_limit = 200.0;  // above the standstill current 110 A: the limit never acts at U_n
  EXPECT_EQ(supplyOf(st, {}, &law).limitSpeed(), 0.0);
  st.current_limit = 50.0;
  st.max_start_time = 3.0;  // shorter than the ramp
  EXPECT_THROW(supplyOf(st, {}, &law), std::invalid_argument);
}

TEST(Supply, FrequencyConverterVOverFRampWithBoost) {
  MotorStart st;
  st.method = StartMethod::FrequencyConverter;
  st.ramp_time = 5.0;
  st.initial_frequency = 5.0;  // f_0/f_n = 0.1
  st.boost = 0.05;
  const Supply s = supplyOf(st);
  const SupplyPhase p = s.initialPhase();
  ASSERT_EQ(p.stage, Stage::Ramp);
  EXPECT_DOUBLE_EQ(s.state(p, 0.0, 0).frequency, 0.1);
  EXPECT_DOUBLE_EQ(s.state(p, 0.0, 0).voltage, 0.05 + 0.95 * 0.1);
  EXPECT_DOUBLE_EQ(s.state(p, 2.5, 0).frequency, 0.55);
  EXPECT_DOUBLE_EQ(s.state(p, 2.5, 0).voltage, 0.05 + 0.95 * 0.55);
  EXPECT_DOUBLE_EQ(s.state(p, 5.0, 0).voltage, 1.0);
  MotorStart bad = st;
  bad.initial_frequency = 60.0;
  EXPECT_THROW(supplyOf(bad), std::invalid_argument);
}

TEST(Supply, SwitchOffBrakeAndRestart) {
  MotorStop stop;
  stop.t_off = 3.0;
  stop.brake_torque = 200.0;
  stop.brake_delay = 0.2;
  stop.t_restart = 4.0;
  RecordingLaw law;
  const Supply s = supplyOf({}, stop, &law);
  EXPECT_TRUE(s.hasBrake());
  SupplyPhase p = s.initialPhase();
  EXPECT_EQ(s.nextEventTime(p), 3.0);
  double x = 0;
  s.applyDueEvents(p, 3.0, 90, false, &law, &x);
  EXPECT_EQ(p.stage, Stage::Off);
  EXPECT_EQ(s.brakeTorque(p, 90), 0.0);  // not yet engaged
  EXPECT_NEAR(s.nextEventTime(p), 3.2, 1e-15);
  s.applyDueEvents(p, 3.2, 80, false, &law, &x);
  EXPECT_EQ(p.stage, Stage::Braking);
  EXPECT_NEAR(s.brakeTorque(p, 80), -200.0, 1e-9);             // against the rotation
  EXPECT_NEAR(s.brakeTorque(p, -80), 200.0, 1e-9);
  EXPECT_NEAR(s.brakeTorque(p, 0.25), -200.0 * std::tanh(0.5), 1e-12);  // smoothed through rest
  s.applyDueEvents(p, 4.0, 30, false, &law, &x);
  EXPECT_EQ(p.stage, Stage::Restarted);
  EXPECT_EQ(s.brakeTorque(p, 30), 0.0);
  EXPECT_TRUE(s.state(p, 4.1, 30).connected);
  EXPECT_TRUE(std::isinf(s.nextEventTime(p)));
  // Told at switch-off and at the restart; the brake changes no supply.
  ASSERT_EQ(law.calls.size(), 2u);
  EXPECT_FALSE(law.calls[0].after.connected);
  EXPECT_TRUE(law.calls[1].after.connected);
}

TEST(Supply, SwitchOffDuringARampEndsIt) {
  MotorStart st;
  st.method = StartMethod::SoftStarter;
  st.ramp_time = 5.0;
  st.initial_voltage = 0.5;
  MotorStop stop;
  stop.t_off = 2.0;
  const Supply s = supplyOf(st, stop);
  SupplyPhase p = s.initialPhase();
  EXPECT_EQ(s.nextEventTime(p), 2.0);
  s.applyDueEvents(p, 2.0, 10, false, nullptr, nullptr);
  EXPECT_EQ(p.stage, Stage::Off);
}

TEST(Supply, EventsDueAtOneInstantAllApply) {
  MotorStop stop;
  stop.t_off = 1.0;
  stop.brake_torque = 50.0;  // no delay: off and braking at once
  const Supply s = supplyOf({}, stop);
  SupplyPhase p = s.initialPhase();
  s.applyDueEvents(p, 1.0, 50, false, nullptr, nullptr);
  EXPECT_EQ(p.stage, Stage::Braking);
}

}  // namespace
}  // namespace rollerdyn
