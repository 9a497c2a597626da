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

}  // namespace
}  // namespace rollerdyn
