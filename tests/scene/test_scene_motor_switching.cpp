// The motor.start and motor.stop sections: defaults, each starting method's keys, and every
// cross-key rule rejected with file, line, key and what was expected (the scene is
// kMinimalScene of SceneTestSupport.h, changed by --set, or with a motor.start map inserted
// into its motor map).
#include <gtest/gtest.h>

#include "scene/KeyEffects.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "SceneTestSupport.h"
#include "scene/Plausibility.h"
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

// kMinimalScene with a motor.start map (the given lines) inserted at the end of its motor map,
// from line 19 on.
std::string withStartMap(const std::string& lines) {
  return kMinimalScene.substr(0, kMinimalScene.find("reducer:")) + "  start:\n" + lines +
         kMinimalScene.substr(kMinimalScene.find("reducer:"));
}

TEST(SceneMotorSwitching, ASceneForOneMethodRunsWithAnotherOneSetOnTheCommandLineWithAWarning) {
  // A scene written for a soft starter, run direct on line with one --set: its soft-starter keys
  // are still validated, then ignored with a warning naming each key, where it was given and why.
  const std::string yaml = withStartMap("    method: soft_starter\n    ramp_time: 2\n    initial_voltage: 0.3\n");
  const Scene s = parseSceneText(yaml, "test.yaml", {"motor.start.method=direct_on_line"});
  EXPECT_EQ(s.motor_start.method, StartMethod::DirectOnLine);
  ASSERT_EQ(s.ignored_keys.size(), 2u);
  EXPECT_EQ(s.ignored_keys[0].key, "motor.start.ramp_time");
  EXPECT_EQ(s.ignored_keys[0].origin, "test.yaml:21");
  const std::vector<std::string> w = keysWithoutEffect(s, "multibody");
  const std::string expected =
      "motor.start.ramp_time (test.yaml:21) has no effect: motor.start.method direct_on_line (--set #1 "
      "(motor.start.method=direct_on_line)): only a soft_starter or a frequency_converter ramps; this method gives its "
      "supply at once; the key is ignored";
  EXPECT_NE(std::find(w.begin(), w.end(), expected), w.end()) << ::testing::PrintToString(w);
  expectSceneError(yaml, {"motor.start.initial_voltage: expected a number in (0, 1], got 0"},
                   {"motor.start.method=direct_on_line", "motor.start.initial_voltage=0"});
}

// A key that does nothing under the method chosen with it was silently ignored (the trial's
// changeover speed under a soft starter): now refused, naming the key, the method and why.
TEST(SceneMotorSwitching, AKeyWithoutEffectUnderTheChosenMethodIsRefused) {
  expectSceneError(withStartMap("    method: soft_starter\n    ramp_time: 2\n    initial_voltage: 0.35\n"
                                "    changeover_speed: 95\n"),
                   {"test.yaml:23: motor.start.changeover_speed: expected no motor.start.changeover_speed with "
                    "motor.start.method soft_starter (only a star_delta start changes over from star to delta; remove "
                    "the key or change motor.start.method), got 95"});
  struct Case {
    std::vector<std::string> sets;
    std::string key, fragment;
  };
  const std::vector<Case> cases = {
      {{"motor.start.ramp_time=2"}, "motor.start.ramp_time",
       "with motor.start.method direct_on_line (only a soft_starter or a frequency_converter ramps"},
      {{"motor.start.method=frequency_converter", "motor.start.ramp_time=2", "motor.start.initial_frequency=5",
        "motor.start.current_limit=100"},
       "motor.start.current_limit", "with motor.start.method frequency_converter (only the soft_starter's current limit"},
      {{"motor.start.method=soft_starter", "motor.start.ramp_time=2", "motor.start.initial_voltage=0.3",
        "motor.start.boost=0.05"},
       "motor.start.boost", "with motor.start.method soft_starter (only a frequency_converter sets the supply frequency"},
      {{"motor.start.method=star_delta", "motor.start.changeover_time=1", "motor.start.initial_voltage=0.3"},
       "motor.start.initial_voltage", "with motor.start.method star_delta (only a soft_starter starts at a reduced"},
      {{"motor.start.method=direct_on_line", "motor.start.changeover_gap=0.05"}, "motor.start.changeover_gap",
       "with motor.start.method direct_on_line (only a star_delta start changes over"},
      {{"motor.start.method=soft_starter", "motor.start.ramp_time=2", "motor.start.initial_voltage=0.3",
        "motor.start.initial_frequency=5"},
       "motor.start.initial_frequency", "with motor.start.method soft_starter"},
      {{"motor.start.method=star_delta", "motor.start.changeover_time=1", "motor.start.max_start_time=10"},
       "motor.start.max_start_time", "only a current-limited soft_starter has a start time after which it trips"},
      {{"motor.start.method=soft_starter", "motor.start.ramp_time=2", "motor.start.initial_voltage=0.3",
        "motor.start.max_start_time=10"},
       "motor.start.max_start_time",
       "with motor.start.current_limit = 0 (no limit) (without a current limit the soft starter closes its bypass at "
       "the end of the ramp and never trips"},
      {{"motor.stop.t_off=2", "motor.stop.brake_delay=0.1"}, "motor.stop.brake_delay",
       "with motor.stop.brake_torque = 0 (no brake) (there is no brake to engage"},
  };
  for (const Case& c : cases) {
    const SceneError e = expectSceneError(kMinimalScene, {c.key + ": expected no " + c.key + " ", c.fragment}, c.sets);
    EXPECT_EQ(e.key(), c.key);
  }
  // The method set after the key on the command line switches methods: a warning, not an error.
  const Scene s = parsedWith({"motor.start.changeover_gap=0.05", "motor.start.method=direct_on_line"});
  ASSERT_EQ(s.ignored_keys.size(), 1u);
  EXPECT_EQ(s.ignored_keys[0].origin, "--set #1 (motor.start.changeover_gap=0.05)");
}

// The shipped balanced drive (its catalogue motor as the equivalent circuit, a law with a stator
// current) with a current-limited soft start and `more`: the parse error's message.
std::string softStartError(const std::vector<std::string>& more) {
  std::vector<std::string> sets = {"motor.model=circuit", "motor.start.method=soft_starter", "motor.start.ramp_time=2",
                                   "motor.start.initial_voltage=0.3", "motor.start.current_limit=80"};
  sets.insert(sets.end(), more.begin(), more.end());
  try {
    parseSceneFile(std::string(ROLLERDYN_SOURCE_DIR) + "/model/balanced-4cart.yaml", sets);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(parsed)";
}

TEST(SceneMotorSwitching, TheMaximumStartTimeExceedsTheRamp) {
  EXPECT_EQ(softStartError({}), "(parsed)");
  EXPECT_NE(softStartError({"motor.start.max_start_time=1.5"})
                .find("motor.start.max_start_time: expected a number > ramp_time = 2 [s] (motor.start.ramp_time), got 1.5"),
            std::string::npos)
      << softStartError({"motor.start.max_start_time=1.5"});
  const std::string e = softStartError({"motor.start.ramp_time=25"});
  EXPECT_NE(e.find("motor.start.max_start_time: expected a start time > ramp_time = 25 [s] (motor.start.ramp_time; its "
                   "default 20 s is shorter; 0 = never trips)"),
            std::string::npos)
      << e;
  EXPECT_EQ(softStartError({"motor.start.ramp_time=25", "motor.start.max_start_time=0"}), "(parsed)");
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
