// The motor-law table (scene/MotorModels.h) is the one description of each motor.model: its rows
// follow the enumeration, the schema and the run's effect line read their words from it, and its
// classification agrees with the laws makeMotorLaw builds (a law on the Kloss curve peaks at M_kr
// at the critical slip; a machine law cannot be parsed without machine data); a law's own keys
// are scene keys that set their field.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "motor/MotorLawFactory.h"
#include "scene/MotorModels.h"
#include "scene/SceneChoices.h"
#include "scene/SceneParser.h"
#include "scene/SceneSchema.h"
#include "scene/SceneValues.h"
#include "scene/SceneTestSupport.h"

namespace rollerdyn {
namespace {

// The scene tests' minimal scene: the Kloss data only (no catalogue, no circuit).
using test::kMinimalScene;

TEST(MotorModelTable, RowsFollowTheEnumerationAndNameTheSchemasWords) {
  const auto& table = motorModelTable();
  const KeySpec& key = choiceKey("motor.model");
  ASSERT_EQ(table.size(), key.choices.size());
  for (std::size_t i = 0; i < table.size(); ++i) {
    EXPECT_EQ(static_cast<int>(table[i].model), static_cast<int>(i)) << table[i].word;
    EXPECT_EQ(key.choices[i], table[i].word);
    EXPECT_EQ(std::string(toString(table[i].model)), table[i].word);
    EXPECT_NE(key.meaning.find(std::string(table[i].word) + ", " + table[i].meaning), std::string::npos);
    EXPECT_EQ(&motorModelInfo(table[i].model), &table[i]);
  }
}

TEST(MotorModelTable, EveryLawNamesItselfInTheRunsEffects) {
  for (const MotorModelInfo& law : motorModelTable()) {
    const std::string effect = std::string(law.word) + "_motor";
    EXPECT_EQ(effectWords(effect),
              std::string("induction motor, ") + law.effect + " (motor.model: " + law.word + ")");
  }
}

TEST(MotorModelTable, KlossCurveLawsPeakAtTheBreakdownTorqueAtTheCriticalSlip) {
  for (const MotorModelInfo& law : motorModelTable()) {
    if (!law.kloss_curve) continue;
    const Scene sc = parseSceneText(kMinimalScene, "kloss-only.yaml", {std::string("motor.model=") + law.word});
    const auto m = makeMotorLaw(sc);
    const double w_kr = sc.motor.omega_sync * (1.0 - sc.motor.critical_slip);
    EXPECT_NEAR(m->steadyTorque(SupplyState{}, w_kr), sc.motor.breakdown_torque, 1e-9 * sc.motor.breakdown_torque)
        << law.word;
  }
}

TEST(MotorModelTable, MachineLawsNeedTheCatalogueOrTheCircuit) {
  for (const MotorModelInfo& law : motorModelTable()) {
    const std::string set = std::string("motor.model=") + law.word;
    if (law.kloss_curve) {
      EXPECT_NO_THROW(parseSceneText(kMinimalScene, "kloss-only.yaml", {set})) << law.word;
    } else {
      EXPECT_TRUE(isMachineLaw(law.model));
      EXPECT_ANY_THROW(parseSceneText(kMinimalScene, "kloss-only.yaml", {set})) << law.word;
    }
  }
}

// A key of a law's own is declared once, in its row: the schema knows it (so --set accepts it and
// the reference lists it), a file that gives it sets the row's field, one that leaves it out gets
// the schema's default, and the scene's values report it.
TEST(MotorModelTable, LawsOwnKeysAreSchemaKeysThatSetTheirField) {
  int own = 0;
  for (const MotorModelInfo& law : motorModelTable())
    for (const MotorLawKey& k : law.own_keys) {
      ++own;
      const KeySpec spec = k.spec();
      const KeySpec* in_schema = findSceneKey(spec.path);
      ASSERT_NE(in_schema, nullptr) << spec.path;
      EXPECT_EQ(in_schema->unit, spec.unit) << spec.path;
      const Scene absent = parseSceneText(kMinimalScene, "own-key.yaml");
      EXPECT_EQ(absent.induction.*k.field, spec.default_number) << spec.path;
      const double given = 0.0123;  // inside a positive range; the parser checks the range itself
      const Scene sc = parseSceneText(kMinimalScene, "own-key.yaml",
                                      {std::string("motor.model=") + law.word, spec.path + "=0.0123"});
      EXPECT_EQ(sc.induction.*k.field, given) << spec.path;
      EXPECT_EQ(sc.induction.model, law.model) << spec.path;
      bool reported = false;
      for (const auto& [key, value] : sceneValues(sc))
        if (key == spec.path) reported = std::stod(value) == given;
      EXPECT_TRUE(reported) << spec.path;
    }
  EXPECT_GE(own, 1) << "the dynamic Kloss law's T_e is a key of its own";
}

}  // namespace
}  // namespace rollerdyn
