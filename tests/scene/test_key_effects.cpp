// Keys a scene gives that the run asked for does not read are named with why (the consistency
// harness found five that changed nothing and nothing said so).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "scene/KeyEffects.h"
#include "scene/SceneParser.h"

namespace rollerdyn {
namespace {

Scene scene(const std::vector<std::string>& sets) {
  return parseSceneFile(std::string(ROLLERDYN_SOURCE_DIR) + "/model/balanced-4cart.yaml", sets);
}

bool named(const std::vector<std::string>& warnings, const std::string& key) {
  for (const std::string& w : warnings)
    if (w.rfind(key + " has no effect", 0) == 0) return true;
  return false;
}

TEST(KeyEffects, TheGivenKeysAreRecorded) {
  const Scene s = scene({"sizing.starts_per_hour=3"});
  EXPECT_NE(std::find(s.given_keys.begin(), s.given_keys.end(), "sizing.starts_per_hour"), s.given_keys.end());
  EXPECT_NE(std::find(s.given_keys.begin(), s.given_keys.end(), "crank.radius"), s.given_keys.end());
  EXPECT_EQ(std::find(s.given_keys.begin(), s.given_keys.end(), "sizing.target_delta"), s.given_keys.end());
}

TEST(KeyEffects, AKeyOfTheOtherModelIsNamed) {
  const Scene s = scene({"reduced.guide_normals=quasi_static", "sizing.bearing_rating.crank_pin=5e4"});
  EXPECT_TRUE(named(keysWithoutEffect(s, "multibody"), "reduced.guide_normals"));
  EXPECT_FALSE(named(keysWithoutEffect(s, "reduced"), "reduced.guide_normals"));
  EXPECT_TRUE(named(keysWithoutEffect(s, "reduced"), "sizing.bearing_rating.crank_pin"));
  EXPECT_FALSE(named(keysWithoutEffect(s, "multibody"), "sizing.bearing_rating.crank_pin"));
}

TEST(KeyEffects, TheWindingConnectionIsNamed) {
  EXPECT_TRUE(named(keysWithoutEffect(scene({"motor.connection=delta"}), "multibody"), "motor.connection"));
}

TEST(KeyEffects, TheRollerSpacingActsOnlyWhereACartsTwoNormalsDiffer) {
  const std::vector<std::string> equal = keysWithoutEffect(
      scene({"carts.geometry.a=0.3", "loads.roller_normal_front=1000", "loads.roller_normal_rear=1000"}), "multibody");
  EXPECT_TRUE(named(equal, "carts.geometry.a"));
  const std::vector<std::string> differ = keysWithoutEffect(
      scene({"carts.geometry.a=0.3", "loads.roller_normal_front=1000", "loads.roller_normal_rear=2000"}), "multibody");
  EXPECT_FALSE(named(differ, "carts.geometry.a"));
}

// The cart's moment arms split the guide normal between its two guide rollers; without guide
// friction and without reactions no output reads that split (the harness: e, d, com_height).
TEST(KeyEffects, TheCartsMomentArmsActOnlyThroughGuideFrictionOrTheReactions) {
  const std::vector<std::string> arms = {"carts.geometry.p", "carts.geometry.b", "carts.geometry.e",
                                         "carts.geometry.d", "carts.geometry.com_height"};
  const auto withArms = [&](std::vector<std::string> sets) {
    for (const std::string& k : arms) sets.push_back(k + "=0.1");
    return keysWithoutEffect(scene(sets), "multibody");
  };
  const std::vector<std::string> neither =
      withArms({"loads.guide_friction.coefficient=0", "simulation.reactions=false"});
  const std::vector<std::string> reactions =
      withArms({"loads.guide_friction.coefficient=0", "simulation.reactions=true"});
  const std::vector<std::string> friction = withArms({"simulation.reactions=false"});
  for (const std::string& k : arms) {
    EXPECT_TRUE(named(neither, k)) << k;
    EXPECT_FALSE(named(reactions, k)) << k;
    EXPECT_FALSE(named(friction, k)) << k;
  }
}

// e is the arm of the compacting rollers' horizontal force; com_height that of the cart's inertial
// force, which the reduced model's quasi-static guide normals leave out.
TEST(KeyEffects, TheRollerDepthAndTheCentreOfMassHeightActOnlyWithTheirForces) {
  const std::vector<std::string> no_rolling = {"carts.geometry.e=0.2", "loads.roller_force_front=0",
                                               "loads.roller_force_rear=0", "loads.rolling_resistance=0"};
  EXPECT_TRUE(named(keysWithoutEffect(scene(no_rolling), "multibody"), "carts.geometry.e"));
  std::vector<std::string> rolling = no_rolling;
  rolling.push_back("loads.rolling_resistance=0.01");
  EXPECT_FALSE(named(keysWithoutEffect(scene(rolling), "multibody"), "carts.geometry.e"));

  const std::vector<std::string> height = {"carts.geometry.com_height=0.3", "loads.guide_friction.coefficient=0",
                                           "reduced.guide_normals=quasi_static"};
  EXPECT_TRUE(named(keysWithoutEffect(scene(height), "reduced"), "carts.geometry.com_height"));
  EXPECT_FALSE(named(keysWithoutEffect(scene(height), "multibody"), "carts.geometry.com_height"));
  std::vector<std::string> kinetostatic = height;
  kinetostatic.back() = "reduced.guide_normals=kinetostatic";
  EXPECT_FALSE(named(keysWithoutEffect(scene(kinetostatic), "reduced"), "carts.geometry.com_height"));
}

// A Kloss law's speed is motor.omega_sync: f_n only scales a converter's frequencies and gives the
// dynamic Kloss law its default T_e.
TEST(KeyEffects, TheSupplyFrequencyIsNamedWhereNoKlossLawReadsIt) {
  EXPECT_TRUE(named(keysWithoutEffect(scene({}), "reduced"), "motor.frequency"));
  EXPECT_FALSE(named(keysWithoutEffect(scene({"initial.crank_speed=0", "motor.start.method=frequency_converter",
                                              "motor.start.ramp_time=3", "motor.start.initial_frequency=5"}),
                                       "reduced"),
                     "motor.frequency"));
  EXPECT_FALSE(named(keysWithoutEffect(scene({"motor.model=kloss_dynamic"}), "reduced"), "motor.frequency"));
  EXPECT_TRUE(named(keysWithoutEffect(scene({"motor.model=kloss_dynamic", "motor.torque_time_constant=0.01"}), "reduced"),
                    "motor.frequency"));
  EXPECT_FALSE(named(keysWithoutEffect(scene({"motor.model=circuit"}), "reduced"), "motor.frequency"));
}

// A key of one motor law's own (the dynamic Kloss law's T_e) is named under every other law, in
// both models, and never under its own law.
TEST(KeyEffects, AMotorLawsOwnKeyIsNamedUnderEveryOtherLaw) {
  const std::string te = "motor.torque_time_constant=0.01";
  for (const std::string model : {"multibody", "reduced"}) {
    EXPECT_TRUE(named(keysWithoutEffect(scene({te}), model), "motor.torque_time_constant")) << model;
    EXPECT_FALSE(named(keysWithoutEffect(scene({"motor.model=kloss_dynamic", te}), model), "motor.torque_time_constant"))
        << model;
  }
}

}  // namespace
}  // namespace rollerdyn

namespace rollerdyn {
namespace {

// A backlash of 0 given under a rigid coupling (a positive one is an error there) and a backlash
// of 0 anywhere change nothing; a positive one under an elastic coupling acts.
TEST(KeyEffects, AZeroBacklashOrOneUnderARigidCouplingIsNamed) {
  EXPECT_TRUE(named(keysWithoutEffect(scene({"reducer.backlash=0"}), "multibody"), "reducer.backlash"));
  EXPECT_TRUE(named(keysWithoutEffect(scene({"coupling.type=rigid", "reducer.backlash=0"}), "reduced"),
                    "reducer.backlash"));
  EXPECT_FALSE(named(keysWithoutEffect(scene({"reducer.backlash=0.001"}), "multibody"), "reducer.backlash"));
}

}  // namespace
}  // namespace rollerdyn
