// The report's parameter table: every schema key with the value used and where it came from.
#include <gtest/gtest.h>

#include <map>

#include "report/SceneTable.h"
#include "scene/SceneError.h"
#include "scene/SceneParser.h"

namespace rollerdyn {
namespace {

const std::string kScene = std::string(ROLLERDYN_SOURCE_DIR) + "/model/balanced-4cart.yaml";

std::map<std::string, SceneParameterRow> byKey(const std::vector<SceneParameterRow>& rows) {
  std::map<std::string, SceneParameterRow> m;
  for (const auto& r : rows) m[r.key] = r;
  return m;
}

TEST(SceneTable, ValuesUnitsAndOrigins) {
  const auto rows = byKey(sceneParameterRows(kScene, {"crank.offset_deg=60", "carts.sides=[same, opposite, same, opposite]"}));
  ASSERT_TRUE(rows.count("crank.offset_deg"));
  EXPECT_EQ(rows.at("crank.offset_deg").value, "60");
  EXPECT_EQ(rows.at("crank.offset_deg").unit, "deg");
  EXPECT_EQ(rows.at("crank.offset_deg").origin, "--set #1");
  EXPECT_EQ(rows.at("carts.sides").value, "[same, opposite, same, opposite]");
  EXPECT_EQ(rows.at("carts.sides").origin, "--set #2");
  EXPECT_EQ(rows.at("crank.radius").value, "0.2");
  EXPECT_EQ(rows.at("crank.radius").origin, "file");
  EXPECT_EQ(rows.at("crank.radius").unit, "m");
  EXPECT_FALSE(rows.at("crank.radius").meaning.empty());
  EXPECT_FALSE(rows.count("source")) << "the citation heads the report instead";
  for (const auto& [key, row] : rows) EXPECT_FALSE(row.origin.empty()) << key;
}

TEST(SceneTable, OmittedOptionalKeysShowTheirDefault) {
  const auto rows = byKey(sceneParameterRows(kScene, {}));
  bool some_default = false;
  for (const auto& [key, row] : rows) some_default |= row.origin == "default";
  EXPECT_TRUE(some_default);
}

TEST(SceneTable, DerivedQuantitiesComeFromTheScene) {
  const Scene s = parseSceneFile(kScene);
  const auto rows = byKey(derivedParameterRows(s));
  ASSERT_TRUE(rows.count("critical slip s_kr"));
  EXPECT_NEAR(std::stod(rows.at("critical slip s_kr").value), s.motor.critical_slip, 1e-6);
  EXPECT_NEAR(std::stod(rows.at("motor-side inertia J_n1").value), s.motorSideInertia(), 1e-6 * s.motorSideInertia());
}

TEST(SceneTable, BadOverrideIsASceneError) {
  EXPECT_THROW(sceneParameterRows(kScene, {"carts.cuont=3"}), SceneError);
}

}  // namespace
}  // namespace rollerdyn
