// simulation.reactions: false leaves out the joint reactions and nothing else. The expected
// values are the same scene's run WITH reactions: the motion may not change (the integration
// never depends on the output rows), the reactions table must be empty, and in the minimal
// formulation the self-check against Simbody's constrained solve must still run (on a subset of
// the rows) and sit at round-off.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "multibody/MultibodySimulation.h"
#include "reduced/ReducedModel.h"
#include "scene/SceneParser.h"

namespace rollerdyn {
namespace {

Scene scene(const std::string& file, const std::string& formulation, bool reactions) {
  return parseSceneFile(std::string(ROLLERDYN_SOURCE_DIR) + "/model/" + file,
                        {"simulation.t_end=1.0", "simulation.formulation=" + formulation,
                         std::string("simulation.reactions=") + (reactions ? "true" : "false")});
}

// Largest |a - b| over all rows and columns, relative to the column's largest |a| (absolute
// where the column vanishes).
double largestRelativeDifference(const Table& a, const Table& b) {
  EXPECT_EQ(a.columns, b.columns);
  EXPECT_EQ(a.rows.size(), b.rows.size());
  double worst = 0;
  for (std::size_t c = 0; c < a.columns.size(); ++c) {
    double diff = 0, scale = 0;
    for (std::size_t k = 0; k < std::min(a.rows.size(), b.rows.size()); ++k) {
      diff = std::max(diff, std::abs(a.rows[k][c] - b.rows[k][c]));
      scale = std::max(scale, std::abs(a.rows[k][c]));
    }
    worst = std::max(worst, scale > 0 ? diff / scale : diff);
  }
  return worst;
}

TEST(ReactionsOff, SceneKeyDefaultsToReactionsAndRejectsNonFlags) {
  const std::string path = std::string(ROLLERDYN_SOURCE_DIR) + "/model/balanced-4cart.yaml";
  EXPECT_TRUE(parseSceneFile(path, {}).simulation.reactions);
  EXPECT_FALSE(parseSceneFile(path, {"simulation.reactions=false"}).simulation.reactions);
  try {
    parseSceneFile(path, {"simulation.reactions=sometimes"});
    ADD_FAILURE() << "a non-flag value was accepted";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("simulation.reactions"), std::string::npos) << e.what();
  }
}

TEST(ReactionsOff, MinimalFormulationSameMotionNoReactionsSelfCheckStillRuns) {
  for (const char* file : {"balanced-4cart.yaml", "recuperative-2cart.yaml", "cam-drive.yaml"}) {
    SCOPED_TRACE(file);
    const RunResult with = runMultibodyModel(scene(file, "minimal", true));
    const RunResult without = runMultibodyModel(scene(file, "minimal", false));
    ASSERT_TRUE(with.stats.complete && without.stats.complete);
    EXPECT_TRUE(without.reactions.columns.empty());
    EXPECT_TRUE(without.reactions.rows.empty());
    // Same integration (identical steps). The rows' accelerations come from the projected
    // equations instead of Simbody's constrained solve: the two agree to round-off
    // (formulation_self_check ~1e-13), hence 1e-10 and not exact equality.
    EXPECT_EQ(with.stats.steps, without.stats.steps);
    EXPECT_LT(largestRelativeDifference(with.timeseries, without.timeseries), 1e-10);
    // The self-check ran (it is 0 only if it never did) and sits at round-off.
    EXPECT_GT(without.stats.formulation_self_check, 0.0);
    EXPECT_LT(without.stats.formulation_self_check, 1e-10);
    // The energy audit closes on the same final state.
    EXPECT_NEAR(with.energy.residual(), without.energy.residual(),
                1e-9 * std::max(1.0, std::abs(with.energy.motor_work)));
  }
}

TEST(ReactionsOff, ConstrainedFormulationSameMotionNoReactions) {
  const RunResult with = runMultibodyModel(scene("recuperative-2cart.yaml", "constrained", true));
  const RunResult without = runMultibodyModel(scene("recuperative-2cart.yaml", "constrained", false));
  ASSERT_TRUE(with.stats.complete && without.stats.complete);
  EXPECT_TRUE(without.reactions.rows.empty());
  // Output rows never feed back into Simbody's integration: identical values.
  EXPECT_EQ(largestRelativeDifference(with.timeseries, without.timeseries), 0.0);
}

TEST(ReactionsOff, ReducedModelSameMotionNoReactions) {
  const RunResult with = runReducedModel(scene("balanced-4cart.yaml", "minimal", true));
  const RunResult without = runReducedModel(scene("balanced-4cart.yaml", "minimal", false));
  ASSERT_FALSE(with.reactions.rows.empty());
  EXPECT_TRUE(without.reactions.columns.empty());
  EXPECT_TRUE(without.reactions.rows.empty());
  EXPECT_EQ(largestRelativeDifference(with.timeseries, without.timeseries), 0.0);
}

}  // namespace
}  // namespace rollerdyn
