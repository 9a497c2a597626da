// reducer.backlash: read in radians, 0 by default, rejected where it cannot act (a rigid coupling
// has no contact stiffness) or is negative, with the key named.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "SceneTestSupport.h"
#include "scene/KeyEffects.h"
#include "scene/SceneParser.h"

namespace rollerdyn {
namespace {

using test::expectSceneError;
using test::kMinimalScene;
using test::replaced;

std::string elasticScene() { return replaced("  type: rigid", "  type: elastic\n  stiffness: 200000\n  damping: 8000"); }

TEST(SceneBacklash, DefaultsToNoBacklash) {
  const Scene s = parseSceneText(elasticScene(), "test.yaml");
  EXPECT_EQ(s.reducer.backlash, 0.0);
  EXPECT_FALSE(s.hasBacklash());
}

TEST(SceneBacklash, ReadsTheTotalBacklashInRadians) {
  const Scene s = parseSceneText(elasticScene(), "test.yaml", {"reducer.backlash=0.0017453"});
  EXPECT_DOUBLE_EQ(s.reducer.backlash, 0.0017453);
  EXPECT_TRUE(s.hasBacklash());
  const std::vector<std::string> e = s.effects();
  EXPECT_NE(std::find(e.begin(), e.end(), "backlash"), e.end());
}

TEST(SceneBacklash, BacklashWithARigidCouplingIsAnErrorNamingTheKey) {
  expectSceneError(kMinimalScene, {"reducer.backlash: expected 0 with coupling.type: rigid", "coupling.stiffness",
                                   "got 0.002"},
                   {"reducer.backlash=0.002"});
}

TEST(SceneBacklash, NegativeBacklashIsRejected) {
  expectSceneError(elasticScene(), {"reducer.backlash: expected a number >= 0 [rad]"}, {"reducer.backlash=-0.001"});
}

}  // namespace
}  // namespace rollerdyn
