// The papers' qualitative conclusions, checked with the reduced model on the shipped scenes
// (the full numbers beside the published tables are in validation/report.md). Only trends the
// papers state in words are asserted; their printed values depend on unstated inputs and are
// not targets.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "compare/ValidationSuite.h"
#include "reduced/ReducedModel.h"
#include "scene/SceneParser.h"

using namespace rollerdyn;
using rollerdyn::validation::RunMetrics;
using rollerdyn::validation::runMetrics;

namespace {

RunMetrics reduced(const std::string& file, const std::vector<std::string>& sets) {
  const Scene sc = parseSceneFile(std::string(ROLLERDYN_SOURCE_DIR) + "/model/" + file, sets);
  return runMetrics(sc, runReducedModel(sc));
}

}  // namespace

TEST(PaperTrends, LoveikinPochka2007OptimalOffsetIsNinetyDegrees) {
  // Loveikin and Pochka (2007) (conclusions and table): of the offsets 0...180°, δ is smallest at Δφ = π/2.
  // A 30° grid is enough to locate it; each run reaches steady state (checked).
  double best = 1e9, at = -1;
  for (double x = 0; x <= 180; x += 30) {
    const RunMetrics m = reduced("recuperative-2cart.yaml", {"crank.offset_deg=" + std::to_string(x)});
    ASSERT_TRUE(m.rotating && m.steady) << x;
    if (m.delta < best) {
      best = m.delta;
      at = x;
    }
  }
  EXPECT_EQ(at, 90);
}

TEST(PaperTrends, EnergyBalancedDrivePaperFlywheelLowersUnevenness) {
  // The energy-balanced drive paper (Table 1 and text): δ, H and k_p fall steadily as the flywheel inertia grows.
  double last_delta = 1e9, last_H = 1e9;
  for (double inertia : {0.0, 100.0, 500.0, 1000.0}) {
    const RunMetrics m = reduced("energy-balanced-3cart.yaml", {"flywheel.inertia=" + std::to_string(inertia)});
    ASSERT_TRUE(m.rotating && m.steady) << inertia;
    EXPECT_LT(m.delta, last_delta) << inertia;
    EXPECT_LT(m.H, last_H) << inertia;
    last_delta = m.delta;
    last_H = m.H;
  }
}

TEST(PaperTrends, Loveikin2018DampingLowersCouplingSwing) {
  // Loveikin, Pochka, Romasevych (2018) (Table 1): at Δφ = 90° the larger damping k = 8000 gives smaller coupling swings
  // than k = 2000 (torque and twist).
  const RunMetrics soft = reduced("balanced-4cart.yaml", {"coupling.damping=2000"});
  const RunMetrics hard = reduced("balanced-4cart.yaml", {"coupling.damping=8000"});
  ASSERT_TRUE(soft.rotating && hard.rotating);
  EXPECT_LT(hard.torque_swing, soft.torque_swing);
  EXPECT_LT(hard.twist_swing, soft.twist_swing);
}
