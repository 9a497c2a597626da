// Every class of bad input is rejected with the promised message: file, correct line, key path
// and the expected-clause. Line numbers refer to kMinimalScene (see SceneTestSupport.h).
#include <gtest/gtest.h>

#include <string>

#include "SceneTestSupport.h"
#include "scene/SceneParser.h"

namespace rollerdyn {
namespace {

using test::expectSceneError;
using test::kMinimalScene;
using test::replaced;
using test::without;

TEST(SceneRejects, MinimalSceneIsValid) {
  // Guards the fixture: every rejection below must come from its one edit.
  EXPECT_NO_THROW(parseSceneText(kMinimalScene, "test.yaml"));
}

// --- unknown keys -------------------------------------------------------------------------

TEST(SceneRejects, UnknownNestedKeyNamesLineKeyAndAllowedKeys) {
  const SceneError e = expectSceneError(
      replaced("  count: 2", "  cuont: 2"),
      {"balanced.yaml:12: carts.cuont: expected one of the keys allowed under carts: count, "
       "sides, mass, geometry",
       "unknown key 'cuont'", "did you mean 'count'?"},
      {}, "balanced.yaml");
  EXPECT_EQ(e.file(), "balanced.yaml");
  EXPECT_EQ(e.line(), 12);
  EXPECT_EQ(e.key(), "carts.cuont");
}

TEST(SceneRejects, UnknownTopLevelKey) {
  expectSceneError(replaced("simulation:", "simulaton:"),
                   {"test.yaml:2: simulaton: expected one of the top-level keys: source, "
                    "simulation, initial, crank",
                    "did you mean 'simulation'?"});
}

TEST(SceneRejects, UnknownKeyTwoLevelsDown) {
  expectSceneError(kMinimalScene + "loads:\n  guide_friction:\n    coeficient: 0.1\n",
                   {"test.yaml:26: loads.guide_friction.coeficient:",
                    "allowed under loads.guide_friction: coefficient"});
}

TEST(SceneRejects, UnknownKeyWithNoCloseMatchHasNoSuggestion) {
  const SceneError e = expectSceneError(kMinimalScene + "colour: red\n",
                                        {"test.yaml:24: colour:", "unknown key 'colour'"});
  EXPECT_EQ(std::string(e.what()).find("did you mean"), std::string::npos);
}

// --- wrong types --------------------------------------------------------------------------

TEST(SceneRejects, TextWhereNumberExpected) {
  expectSceneError(replaced("  t_end: 1.0", "  t_end: ten"),
                   {"test.yaml:3: simulation.t_end: expected a number > 0 [s], got ten"});
}

TEST(SceneRejects, QuotedNumberIsAString) {
  expectSceneError(replaced("  radius: 0.2", "  radius: \"0.2\""),
                   {"test.yaml:5: crank.radius: expected a number > 0 [m], got \"0.2\""});
}

TEST(SceneRejects, MapWhereNumberExpected) {
  expectSceneError(replaced("  radius: 0.2", "  radius: {value: 0.2}"),
                   {"test.yaml:5: crank.radius: expected a number > 0 [m], got a map"});
}

TEST(SceneRejects, ListWhereNumberExpected) {
  // carts.mass may be a list of carts.count numbers (docs/per-cart.md), not of any other length;
  // a number key that is not per cart takes no list.
  expectSceneError(replaced("  mass: 1000", "  mass: [1000, 1000, 1000]"),
                   {"test.yaml:13: carts.mass: expected a list of 2 numbers > 0 [kg], one per cart (carts.count = 2), got a list of 3"});
  expectSceneError(replaced("  radius: 0.2", "  radius: [0.2, 0.2]"),
                   {"test.yaml:5: crank.radius: expected a number > 0 [m], got a list of 2"});
}

TEST(SceneRejects, NullWhereNumberExpected) {
  expectSceneError(replaced("  radius: 0.2", "  radius:"),
                   {"test.yaml:5: crank.radius: expected a number > 0 [m], got nothing (null)"});
}

TEST(SceneRejects, ScalarWhereMapExpected) {
  expectSceneError(kMinimalScene + "flywheel: 50\n",
                   {"test.yaml:24: flywheel: expected a map (one of the keys allowed under "
                    "flywheel: inertia, location), got 50"});
}

TEST(SceneRejects, NonIntegerCount) {
  expectSceneError(replaced("  count: 2", "  count: 2.5"),
                   {"test.yaml:12: carts.count: expected an integer in [1, 1000], got 2.5"});
}

TEST(SceneRejects, UnknownChoiceWord) {
  expectSceneError(replaced("  model: distributed", "  model: lumped"),
                   {"test.yaml:8: rods.model: expected one of: distributed, split, massless, "
                    "got lumped"});
  expectSceneError(replaced("  t_end: 1.0", "  t_end: 1.0\n  integrator: RungeKutta4"),
                   {"test.yaml:4: simulation.integrator: expected one of: RungeKuttaMerson,",
                    "CPodes, got RungeKutta4"});
}

TEST(SceneRejects, FlagAcceptsOnlyTrueOrFalse) {
  expectSceneError(replaced("  rotor_inertia: 0.138", "  rotor_inertia: 0.138\n  enabled: yes"),
                   {"test.yaml:19: motor.enabled: expected true or false, got yes"});
}

// --- missing required keys ----------------------------------------------------------------

TEST(SceneRejects, MissingRequiredKeyNamedAtParentLine) {
  const SceneError e = expectSceneError(
      without("  length: 0.8"),
      {"test.yaml:7: rods.length: expected a number > 0 [m]", "got nothing (key missing)"});
  EXPECT_EQ(e.key(), "rods.length");
  EXPECT_EQ(e.line(), 7);
}

// A user's own scene need not cite a paper: `source` may be left out (but not given empty).
TEST(SceneRejects, SourceIsOptionalInAUsersOwnScene) {
  const Scene s = parseSceneText(without("source: unit-test scene"), "test.yaml");
  EXPECT_EQ(s.source, "");
}

TEST(SceneRejects, EmptySource) {
  expectSceneError(replaced("source: unit-test scene", "source: \"\""),
                   {"test.yaml:1: source: expected a citation"});
}

TEST(SceneRejects, MissingWholeSection) {
  std::string y = kMinimalScene.substr(0, kMinimalScene.find("coupling:"));
  expectSceneError(y, {"coupling.type: expected one of: elastic, rigid, got nothing (key missing)"});
}

TEST(SceneRejects, RodMassRequiredUnlessMassless) {
  expectSceneError(without("  mass: 64"),
                   {"test.yaml:7: rods.mass:", "required unless rods.model is massless"});
  expectSceneError(replaced("  mass: 64", "  mass: 0"),
                   {"test.yaml:10: rods.mass: expected a number > 0 [kg] (0 only with rods.model "
                    "massless), got 0"});
  // A negative mass gets the same rule, not ">= 0", which 0 would then contradict.
  expectSceneError(replaced("  mass: 64", "  mass: -64"),
                   {"test.yaml:10: rods.mass: expected a number > 0 [kg] (0 only with rods.model "
                    "massless), got -64"});
}

TEST(SceneRejects, ElasticCouplingNeedsStiffness) {
  expectSceneError(replaced("  type: rigid", "  type: elastic"),
                   {"test.yaml:22: coupling.stiffness: expected a number > 0 [N·m/rad] (required "
                    "when coupling.type is elastic), got nothing (key missing)"});
  expectSceneError(replaced("  type: rigid", "  type: elastic\n  stiffness: 0"),
                   {"test.yaml:24: coupling.stiffness: expected a number > 0 [N·m/rad], got 0"});
}

// --- critical slip: exactly one way -------------------------------------------------------

TEST(SceneRejects, NoWayToGiveCriticalSlip) {
  expectSceneError(without("  critical_slip: 0.1"),
                   {"test.yaml:14: motor.critical_slip: expected exactly one of "
                    "motor.critical_slip, motor.omega_critical, or motor.omega_nominal + "
                    "motor.overload_ratio"});
}

TEST(SceneRejects, TwoWaysToGiveCriticalSlip) {
  expectSceneError(replaced("  critical_slip: 0.1", "  critical_slip: 0.1\n  omega_critical: 95"),
                   {"test.yaml:18: motor.omega_critical: expected exactly one of",
                    "(motor.critical_slip is given too), got 95"});
}

TEST(SceneRejects, NominalSpeedWithoutOverloadRatio) {
  expectSceneError(replaced("  critical_slip: 0.1", "  omega_nominal: 102.1"),
                   {"test.yaml:14: motor.overload_ratio: expected a number > 1",
                    "required with motor.omega_nominal", "got nothing (key missing)"});
}

TEST(SceneRejects, OverloadRatioMustExceedOne) {
  expectSceneError(
      replaced("  critical_slip: 0.1", "  omega_nominal: 102.1\n  overload_ratio: 1.0"),
      {"test.yaml:18: motor.overload_ratio: expected a number > 1, got 1"});
}

TEST(SceneRejects, CriticalSpeedBelowSynchronous) {
  expectSceneError(replaced("  critical_slip: 0.1", "  omega_critical: 104.72"),
                   {"test.yaml:17: motor.omega_critical: expected a number in (0, omega_sync = "
                    "104.72) [rad/s], got 104.72"});
}

TEST(SceneRejects, DerivedCriticalSlipAboveOne) {
  expectSceneError(
      replaced("  critical_slip: 0.1", "  omega_nominal: 70\n  overload_ratio: 3"),
      {"test.yaml:18: motor.overload_ratio: expected a value giving critical slip", "< 1"});
}

TEST(SceneRejects, CriticalSlipOutsideUnitInterval) {
  expectSceneError(replaced("  critical_slip: 0.1", "  critical_slip: 1.0"),
                   {"test.yaml:17: motor.critical_slip: expected a number in (0, 1), got 1"});
}

// --- physically impossible values --------------------------------------------------------

TEST(SceneRejects, RodNotLongerThanCrank) {
  const SceneError e = expectSceneError(replaced("  length: 0.8", "  length: 0.2"),
                                        {"test.yaml:9: rods.length: expected l > r", "got 0.2"});
  EXPECT_EQ(e.key(), "rods.length");
}

TEST(SceneRejects, NegativeCrankRadius) {
  expectSceneError(replaced("  radius: 0.2", "  radius: -0.2"),
                   {"test.yaml:5: crank.radius: expected a number > 0 [m], got -0.2"});
}

TEST(SceneRejects, CartCountBounds) {
  expectSceneError(replaced("  count: 2", "  count: 0"),
                   {"test.yaml:12: carts.count: expected an integer in [1, 1000], got 0"});
  expectSceneError(replaced("  count: 2", "  count: 1001"), {"carts.count", "got 1001"});
}

TEST(SceneRejects, EfficiencyAboveOne) {
  expectSceneError(replaced("  efficiency: 0.9", "  efficiency: 1.2"),
                   {"test.yaml:21: reducer.efficiency: expected a number in (0, 1], got 1.2"});
}

TEST(SceneRejects, ZeroRotorInertia) {
  expectSceneError(replaced("  rotor_inertia: 0.138", "  rotor_inertia: 0"),
                   {"test.yaml:18: motor.rotor_inertia: expected a number > 0 [kg·m²], got 0"});
}

TEST(SceneRejects, TimeSpanAndOutputStep) {
  expectSceneError(replaced("  t_end: 1.0", "  t_end: 0"),
                   {"test.yaml:3: simulation.t_end: expected a number > 0 [s], got 0"});
  expectSceneError(replaced("  t_end: 1.0", "  t_end: 1.0\n  output_step: 2"),
                   {"test.yaml:4: simulation.output_step: expected a number in (0, t_end = 1] [s]",
                    "got 2"});
  expectSceneError(replaced("  t_end: 1.0", "  t_end: 1.0\n  accuracy: 1"),
                   {"test.yaml:4: simulation.accuracy: expected a number in (0, 1), got 1"});
  // Fewer than 10 output rows per crank revolution: the second trial's 0.5 s step printed a
  // run-up to a mean speed above the synchronous one. The limit is T/10, T = 2π·u/ω0.
  expectSceneError(replaced("  t_end: 1.0", "  t_end: 1.0\n  output_step: 0.5"),
                   {"test.yaml:4: simulation.output_step: expected at most", "10 output rows per crank revolution",
                    "got 0.5"});
}

TEST(SceneRejects, FrictionCoefficientRange) {
  expectSceneError(kMinimalScene + "loads:\n  guide_friction:\n    coefficient: 1.0\n",
                   {"test.yaml:26: loads.guide_friction.coefficient: expected a number in [0, 1)"});
}

TEST(SceneRejects, GuideFrictionNeedsGuideRollerBase) {
  const std::string friction = "loads:\n  guide_friction:\n    coefficient: 0.008\n";
  expectSceneError(kMinimalScene + friction,
                   {"test.yaml:11: carts.geometry.b: expected a number > 0 [m] (required when "
                    "loads.guide_friction.coefficient > 0), got nothing (key missing)"});
  const std::string zero_b = replaced("  mass: 1000", "  mass: 1000\n  geometry:\n    b: 0");
  expectSceneError(zero_b + friction,
                   {"test.yaml:15: carts.geometry.b: expected a number > 0 [m]", "got 0"});
  const std::string good_b = replaced("  mass: 1000", "  mass: 1000\n  geometry:\n    b: 0.37");
  EXPECT_NO_THROW(parseSceneText(good_b + friction, "t.yaml"));
}

TEST(SceneRejects, OtherRanges) {
  expectSceneError(kMinimalScene + "loads:\n  gravity: -9.81\n",
                   {"test.yaml:25: loads.gravity: expected a number >= 0 [m/s²], got -9.81"});
  expectSceneError(kMinimalScene + "loads:\n  velocity_smoothing: 0\n",
                   {"test.yaml:25: loads.velocity_smoothing: expected a number > 0 [m/s]"});
  expectSceneError(kMinimalScene + "reduced:\n  baranov_step_deg: 11\n",
                   {"test.yaml:25: reduced.baranov_step_deg: expected a number in (0, 10] [deg]"});
  expectSceneError(kMinimalScene + "reduced:\n  baranov_step_deg: 0\n",
                   {"reduced.baranov_step_deg", "got 0"});
  expectSceneError(replaced("  offset_deg: 90", "  offset_deg: 360"),
                   {"test.yaml:6: crank.offset_deg: expected a number in [0, 360) [deg]"});
  expectSceneError(kMinimalScene + "  damping: -1\n",
                   {"test.yaml:24: coupling.damping: expected a number >= 0 [N·m·s/rad]"});
  expectSceneError(kMinimalScene + "  inertia: -0.3\n", {"test.yaml:24: coupling.inertia"});
  expectSceneError(replaced("  efficiency: 0.9", "  efficiency: 0.9\n  delta: 0"),
                   {"test.yaml:22: reducer.delta: expected a number > 0"});
  expectSceneError(kMinimalScene + "loads:\n  roller_force_front: -5\n",
                   {"test.yaml:25: loads.roller_force_front: expected a number >= 0 [N]"});
}

TEST(SceneRejects, NonFiniteNumbers) {
  expectSceneError(replaced("  radius: 0.2", "  radius: .nan"),
                   {"test.yaml:5: crank.radius: expected a finite number > 0 [m], got .nan"});
  expectSceneError(replaced("  t_end: 1.0", "  t_end: .inf"),
                   {"test.yaml:3: simulation.t_end: expected a finite number", "got .inf"});
  expectSceneError(kMinimalScene + "initial:\n  crank_angle_deg: -.inf\n",
                   {"test.yaml:25: initial.crank_angle_deg: expected a finite number"});
}

// --- carts.sides --------------------------------------------------------------------------

TEST(SceneRejects, SidesListLengthMustMatchCount) {
  expectSceneError(replaced("  mass: 1000", "  mass: 1000\n  sides: [same, opposite, same]"),
                   {"test.yaml:14: carts.sides: expected a list of 2 entries same/opposite, one "
                    "per cart (carts.count = 2), got a list of 3"});
}

TEST(SceneRejects, SidesEntryMustBeSameOrOpposite) {
  expectSceneError(replaced("  mass: 1000", "  mass: 1000\n  sides:\n    - same\n    - left"),
                   {"test.yaml:16: carts.sides[1]: expected same or opposite, got left"});
}

TEST(SceneRejects, SidesUnknownShorthand) {
  expectSceneError(replaced("  mass: 1000", "  mass: 1000\n  sides: mirrored"),
                   {"test.yaml:14: carts.sides: expected a list of same/opposite",
                    "same, opposite, alternate, got mirrored"});
}

// --- document-level problems --------------------------------------------------------------

TEST(SceneRejects, DuplicateKey) {
  expectSceneError(replaced("  mass: 1000", "  mass: 1000\n  count: 3"),
                   {"test.yaml:14: carts.count: expected each key at most once (first given at "
                    "line 12), got a second 'count'"});
}

TEST(SceneRejects, DuplicateSection) {
  expectSceneError(kMinimalScene + "crank:\n  radius: 0.3\n",
                   {"test.yaml:24: crank: expected each key at most once (first given at line 4)"});
}

TEST(SceneRejects, SecondDocument) {
  expectSceneError(kMinimalScene + "---\nsource: another\n",
                   {"test.yaml:25: expected exactly one YAML document per scene file"});
}

TEST(SceneRejects, YamlSyntaxError) {
  const SceneError e = expectSceneError(replaced("  offset_deg: 90", "  offset_deg: [90, 180"),
                                        {"test.yaml:", "expected valid YAML, got a syntax error"});
  // The unclosed flow list is detected where the next key starts.
  EXPECT_GE(e.line(), 6);
  EXPECT_LE(e.line(), 7);
}

TEST(SceneRejects, BadIndentationIsSyntaxError) {
  const SceneError e = expectSceneError("source: x\nsimulation:\n  t_end: 1\n    bad: 2\n",
                                        {"test.yaml:4: expected valid YAML"});
  EXPECT_EQ(e.line(), 4);
}

TEST(SceneRejects, EmptyDocument) {
  expectSceneError("# nothing here\n", {"test.yaml:1: expected a map of scene keys",
                                        "got an empty document"});
}

TEST(SceneRejects, TopLevelMustBeMap) {
  expectSceneError("- source\n- crank\n", {"test.yaml:1: expected a map of scene keys", "got a list"});
}

TEST(SceneRejects, UnreadableFile) {
  try {
    parseSceneFile("/nonexistent/dir/scene.yaml");
    FAIL() << "expected a SceneError";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/scene.yaml: expected a readable scene "
                                         "file"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace rollerdyn
