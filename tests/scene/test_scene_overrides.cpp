// --set overrides: applied to the YAML tree before validation, so they change the scene and
// pass (or fail) exactly the same checks; a failure cites the --set argument.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "SceneTestSupport.h"
#include "scene/SceneParser.h"

namespace rollerdyn {
namespace {

using test::expectSceneError;
using test::kMinimalScene;
using test::replaced;

TEST(SceneOverrides, ReplaceScalar) {
  const Scene s = parseSceneText(kMinimalScene, "t.yaml", {"crank.offset_deg=45", "carts.mass=900"});
  EXPECT_NEAR(s.crank.offset, M_PI / 4.0, 1e-15);
  EXPECT_DOUBLE_EQ(s.carts.mass, 900.0);
}

TEST(SceneOverrides, FlowListValue) {
  const Scene s = parseSceneText(kMinimalScene, "t.yaml", {"carts.sides=[same,opposite]"});
  EXPECT_EQ(s.carts.side, (std::vector<int>{1, -1}));
}

TEST(SceneOverrides, SetsOptionalKeysTheFileOmits) {
  const Scene s = parseSceneText(
      kMinimalScene, "t.yaml",
      {"loads.guide_friction.coefficient=0.01", "carts.geometry.b=0.37", "flywheel.inertia=50",
       "flywheel.location=motor_shaft", "coupling.damping=2000"});
  EXPECT_DOUBLE_EQ(s.loads.guide_friction, 0.01);
  EXPECT_DOUBLE_EQ(s.carts.geometry.b, 0.37);
  EXPECT_DOUBLE_EQ(s.flywheel.inertia, 50.0);
  EXPECT_EQ(s.flywheel.location, FlywheelLocation::MotorShaft);
  EXPECT_DOUBLE_EQ(s.coupling.damping, 2000.0);
}

TEST(SceneOverrides, LaterOverrideWins) {
  const Scene s = parseSceneText(kMinimalScene, "t.yaml", {"carts.mass=900", "carts.mass=800"});
  EXPECT_DOUBLE_EQ(s.carts.mass, 800.0);
}

TEST(SceneOverrides, AppliedBeforeValidation) {
  // The file alone is invalid; the override replaces the bad value before it is checked.
  const std::string bad = replaced("  t_end: 1.0", "  t_end: -1");
  EXPECT_THROW(parseSceneText(bad, "t.yaml"), SceneError);
  EXPECT_DOUBLE_EQ(parseSceneText(bad, "t.yaml", {"simulation.t_end=2"}).simulation.t_end, 2.0);
}

TEST(SceneOverrides, SwitchToElasticNeedsStiffness) {
  expectSceneError(kMinimalScene, {"coupling.stiffness", "required when coupling.type is elastic"},
                   {"coupling.type=elastic"});
  const Scene s = parseSceneText(kMinimalScene, "t.yaml",
                                 {"coupling.type=elastic", "coupling.stiffness=2e5"});
  EXPECT_EQ(s.coupling.type, CouplingType::Elastic);
  EXPECT_DOUBLE_EQ(s.coupling.stiffness, 2e5);
}

TEST(SceneOverrides, BadValueCitesTheSetArgument) {
  const SceneError e = expectSceneError(
      kMinimalScene,
      {"--set #2 (simulation.t_end=abc): simulation.t_end: expected a number > 0 [s], got abc"},
      {"carts.mass=900", "simulation.t_end=abc"});
  EXPECT_EQ(e.overrideIndex(), 2);
  EXPECT_EQ(e.line(), 0);
  EXPECT_EQ(e.key(), "simulation.t_end");
  EXPECT_EQ(e.file(), "test.yaml");
}

TEST(SceneOverrides, CrossKeyRuleBlamesTheOverride) {
  // rods.length from --set breaks l > r ...
  expectSceneError(kMinimalScene,
                   {"--set #1 (rods.length=0.1): rods.length: expected l > r = 0.2 m "
                    "(crank.radius), got 0.1"},
                   {"rods.length=0.1"});
  // ... and so does crank.radius from --set, with the file's rods.length unchanged.
  expectSceneError(kMinimalScene,
                   {"--set #1 (crank.radius=0.9): crank.radius: expected r < l = 0.8 m "
                    "(rods.length), i.e. l > r, got 0.9"},
                   {"crank.radius=0.9"});
}

TEST(SceneOverrides, CountChangeMustMatchSides) {
  const std::string two_sides = replaced("  mass: 1000", "  mass: 1000\n  sides: [same, opposite]");
  expectSceneError(two_sides, {"--set #1 (carts.count=3): carts.count: expected an integer equal "
                               "to the length of carts.sides (2), got 3"},
                   {"carts.count=3"});
}

TEST(SceneOverrides, UnknownKeyPathFails) {
  const SceneError e = expectSceneError(
      kMinimalScene,
      {"--set #1 (carts.cuont=4): carts.cuont: expected a key path of the scene schema; one of "
       "the keys allowed under carts: count, sides, mass, geometry",
       "got unknown key 'cuont' (did you mean 'count'?)"},
      {"carts.cuont=4"});
  EXPECT_EQ(e.overrideIndex(), 1);
  expectSceneError(kMinimalScene, {"--set #1 (colour=red): colour:", "one of the top-level keys"},
                   {"colour=red"});
  expectSceneError(kMinimalScene,
                   {"--set #1 (crank.radius.x=1): crank.radius.x: expected no key below leaf key "
                    "crank.radius"},
                   {"crank.radius.x=1"});
}

TEST(SceneOverrides, MalformedArgument) {
  expectSceneError(kMinimalScene,
                   {"--set #1 (carts.count): carts.count: expected KEY.PATH=VALUE", "got no '='"},
                   {"carts.count"});
  expectSceneError(kMinimalScene,
                   {"--set #1 (carts.sides=[same): carts.sides: expected a YAML scalar or flow "
                    "value"},
                   {"carts.sides=[same"});
}

TEST(SceneOverrides, WholeMapValueIsCheckedForUnknownKeys) {
  expectSceneError(kMinimalScene,
                   {"--set #1 (flywheel={inertia: 5, mass: 3}): flywheel.mass: expected one of "
                    "the keys allowed under flywheel: inertia, location"},
                   {"flywheel={inertia: 5, mass: 3}"});
  const Scene s = parseSceneText(kMinimalScene, "t.yaml", {"flywheel={inertia: 5}"});
  EXPECT_DOUBLE_EQ(s.flywheel.inertia, 5.0);
}

TEST(SceneOverrides, SecondWayToGiveSlipViaSet) {
  expectSceneError(kMinimalScene,
                   {"--set #1 (motor.omega_critical=95): motor.omega_critical: expected exactly "
                    "one of",
                    "motor.critical_slip is given too"},
                   {"motor.omega_critical=95"});
  // The override is blamed even when it comes first in schema order.
  expectSceneError(replaced("  critical_slip: 0.1", "  omega_critical: 95"),
                   {"--set #1 (motor.critical_slip=0.1): motor.critical_slip: expected exactly "
                    "one of",
                    "motor.omega_critical is given too"},
                   {"motor.critical_slip=0.1"});
}

TEST(SceneOverrides, FileErrorOnPathStaysAFileError) {
  // The file puts a number where the flywheel map belongs; setting a key inside it must not
  // hide the file's mistake.
  expectSceneError(kMinimalScene + "flywheel: 3\n",
                   {"test.yaml:24: flywheel: expected a map", "got 3"}, {"flywheel.inertia=1"});
}

TEST(SceneOverrides, ValuesOutsideTheOverrideStillComeFromTheFile) {
  // An override elsewhere must not take the blame for a file error.
  expectSceneError(replaced("  radius: 0.2", "  radius: -1"),
                   {"test.yaml:5: crank.radius: expected a number > 0 [m], got -1"},
                   {"carts.mass=900"});
}

}  // namespace
}  // namespace rollerdyn
