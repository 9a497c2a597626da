// The motor.start and motor.stop sections: defaults, each starting method's keys, and every
// cross-key rule rejected with file, line, key and what was expected (the scene is
// kMinimalScene of SceneTestSupport.h, changed by --set, or with a motor.start map inserted
// into its motor map).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "SceneTestSupport.h"
#include "scene/SceneParser.h"

namespace rollerdyn {
namespace {

using test::expectSceneError;
using test::kMinimalScene;

// kMinimalScene with the --set arguments `sets`.
Scene parsedWith(const std::vector<std::string>& sets) { return parseSceneText(kMinimalScene, "test.yaml", sets); }

TEST(SceneMotorSwitching, DefaultsAreDirectOnLineAtZeroNeverOff) {
  const Scene s = parsedWith({});
  EXPECT_EQ(s.motor_start.method, StartMethod::DirectOnLine);
  EXPECT_EQ(s.motor_start.t_on, 0.0);
  EXPECT_EQ(s.motor_start.phase, 0.0);
  EXPECT_TRUE(std::isinf(s.motor_stop.t_off));
  EXPECT_TRUE(std::isinf(s.motor_stop.t_restart));
  EXPECT_EQ(s.motor_stop.brake_torque, 0.0);
}

TEST(SceneMotorSwitching, StarDeltaByTimeOrBySpeed) {
  const Scene a = parsedWith({"motor.start.method=star_delta", "motor.start.changeover_time=1.2"});
  EXPECT_EQ(a.motor_start.method, StartMethod::StarDelta);
  EXPECT_DOUBLE_EQ(a.motor_start.changeover_time, 1.2);
  EXPECT_TRUE(std::isnan(a.motor_start.changeover_speed));
  const Scene b = parsedWith({"motor.start.method=star_delta", "motor.start.changeover_speed=90"});
  EXPECT_DOUBLE_EQ(b.motor_start.changeover_speed, 90.0);
  EXPECT_TRUE(std::isnan(b.motor_start.changeover_time));
}

TEST(SceneMotorSwitching, StarDeltaNeedsExactlyOneChangeover) {
  expectSceneError(kMinimalScene,
                   {"motor.start.changeover_time", "exactly one of motor.start.changeover_time or "
                                                   "motor.start.changeover_speed (motor.start.method is star_delta)"},
                   {"motor.start.method=star_delta"});
  expectSceneError(kMinimalScene,
                   {"--set #3", "motor.start.changeover_speed",
                    "exactly one of motor.start.changeover_time or motor.start.changeover_speed "
                    "(motor.start.changeover_time is given too)"},
                   {"motor.start.method=star_delta", "motor.start.changeover_time=1", "motor.start.changeover_speed=90"});
}

TEST(SceneMotorSwitching, ChangeoverMustFollowSwitchOnAndStayBelowSynchronousSpeed) {
  expectSceneError(kMinimalScene,
                   {"motor.start.changeover_time: expected a number > t_on = 2 [s] (motor.start.t_on), got 1"},
                   {"motor.start.method=star_delta", "motor.start.t_on=2", "motor.start.changeover_time=1"});
  // The later --set is blamed: here the switch-on time.
  expectSceneError(kMinimalScene,
                   {"--set #3", "motor.start.t_on: expected a number < changeover_time = 1 [s]"},
                   {"motor.start.method=star_delta", "motor.start.changeover_time=1", "motor.start.t_on=2"});
  expectSceneError(kMinimalScene,
                   {"motor.start.changeover_speed: expected a rotor speed in (0, omega_sync = 104.72) [rad/s] "
                    "(motor.omega_sync), got 110"},
                   {"motor.start.method=star_delta", "motor.start.changeover_speed=110"});
}

TEST(SceneMotorSwitching, InAFileTheErrorNamesItsLine) {
  // A motor.start map inserted at the end of the minimal scene's motor map (lines 19-22).
  const std::string yaml = kMinimalScene.substr(0, kMinimalScene.find("reducer:")) +
                           "  start:\n    method: soft_starter\n    ramp_time: 2\n    initial_voltage: 1.5\n" +
                           kMinimalScene.substr(kMinimalScene.find("reducer:"));
  const SceneError e = expectSceneError(yaml, {"test.yaml:22: motor.start.initial_voltage: expected a number in (0, 1], got 1.5"});
  EXPECT_EQ(e.key(), "motor.start.initial_voltage");
}

TEST(SceneMotorSwitching, RampedMethodsNeedTheirKeys) {
  expectSceneError(kMinimalScene, {"motor.start.ramp_time", "required when motor.start.method is soft_starter"},
                   {"motor.start.method=soft_starter", "motor.start.initial_voltage=0.3"});
  expectSceneError(kMinimalScene,
                   {"motor.start.initial_voltage", "required when motor.start.method is soft_starter"},
                   {"motor.start.method=soft_starter", "motor.start.ramp_time=2"});
  expectSceneError(kMinimalScene,
                   {"motor.start.initial_frequency", "required when motor.start.method is frequency_converter"},
                   {"motor.start.method=frequency_converter", "motor.start.ramp_time=2"});
  const Scene s = parsedWith({"motor.start.method=frequency_converter", "motor.start.ramp_time=2",
                              "motor.start.initial_frequency=2.5", "motor.start.boost=0.04"});
  EXPECT_EQ(s.motor_start.method, StartMethod::FrequencyConverter);
  EXPECT_DOUBLE_EQ(s.motor_start.initial_frequency, 2.5);
  EXPECT_DOUBLE_EQ(s.motor_start.boost, 0.04);
}

TEST(SceneMotorSwitching, KeysOfAnotherMethodAreValidatedButKept) {
  // A scene written for a soft starter can be run direct on line with one --set.
  const Scene s = parsedWith({"motor.start.ramp_time=2", "motor.start.initial_voltage=0.3"});
  EXPECT_EQ(s.motor_start.method, StartMethod::DirectOnLine);
  expectSceneError(kMinimalScene, {"motor.start.initial_voltage: expected a number in (0, 1], got 0"},
                   {"motor.start.initial_voltage=0"});
}

TEST(SceneMotorSwitching, StopTimesInOrder) {
  expectSceneError(kMinimalScene, {"motor.stop.t_off: expected a number > t_on = 3 [s] (motor.start.t_on), got 2"},
                   {"motor.start.t_on=3", "motor.stop.t_off=2"});
  expectSceneError(kMinimalScene,
                   {"motor.stop.t_off: expected a number > changeover_time + changeover_gap = 1.05 [s]"},
                   {"motor.start.method=star_delta", "motor.start.changeover_time=1", "motor.start.changeover_gap=0.05",
                    "motor.stop.t_off=1.02"});
  expectSceneError(kMinimalScene, {"motor.stop.t_off", "a switch-off time before motor.stop.t_restart"},
                   {"motor.stop.t_restart=2"});
  expectSceneError(kMinimalScene, {"motor.stop.t_restart: expected a number > t_off = 2 [s] (motor.stop.t_off), got 1.5"},
                   {"motor.stop.t_off=2", "motor.stop.t_restart=1.5"});
  expectSceneError(kMinimalScene,
                   {"motor.stop.brake_torque: expected 0 without motor.stop.t_off (the brake acts after the switch-off)"},
                   {"motor.stop.brake_torque=100"});
  expectSceneError(kMinimalScene, {"motor.stop.brake_delay", "engages the brake before motor.stop.t_restart = 2.5 s"},
                   {"motor.stop.t_off=2", "motor.stop.brake_torque=100", "motor.stop.brake_delay=0.6",
                    "motor.stop.t_restart=2.5"});
  const Scene s = parsedWith({"motor.stop.t_off=2", "motor.stop.brake_torque=100", "motor.stop.brake_delay=0.1",
                              "motor.stop.t_restart=2.5"});
  EXPECT_DOUBLE_EQ(s.motor_stop.t_off, 2.0);
  EXPECT_DOUBLE_EQ(s.motor_stop.t_restart, 2.5);
}

TEST(SceneMotorSwitching, UnknownMethodSuggestsNothingAndListsTheChoices) {
  expectSceneError(kMinimalScene,
                   {"motor.start.method: expected one of: direct_on_line, star_delta, soft_starter, "
                    "frequency_converter, got star-delta"},
                   {"motor.start.method=star-delta"});
}

TEST(SceneMotorSwitching, CurrentLimitNeedsALawWithACurrent) {
  expectSceneError(kMinimalScene,
                   {"motor.start.current_limit: expected 0 with motor.model kloss (no stator current in that law; "
                    "use motor.model circuit or park), got 80"},
                   {"motor.start.method=soft_starter", "motor.start.ramp_time=2", "motor.start.initial_voltage=0.3",
                    "motor.start.current_limit=80"});
  expectSceneError(kMinimalScene,
                   {"--set #5", "motor.model: expected circuit or park (motor.start.current_limit needs a model of the "
                    "stator current), got kloss_dynamic"},
                   {"motor.start.method=soft_starter", "motor.start.ramp_time=2", "motor.start.initial_voltage=0.3",
                    "motor.start.current_limit=80", "motor.model=kloss_dynamic"});
}

TEST(SceneMotorSwitching, ConverterStartsBelowTheRatedFrequency) {
  expectSceneError(kMinimalScene,
                   {"motor.start.initial_frequency: expected a frequency in (0, f_n = 50) [Hz] (motor.frequency), got 50"},
                   {"motor.start.method=frequency_converter", "motor.start.ramp_time=2",
                    "motor.start.initial_frequency=50"});
}

}  // namespace
}  // namespace rollerdyn
