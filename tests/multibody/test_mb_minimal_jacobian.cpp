// The minimal formulation's structured Newton Jacobian (difference quotients for the mechanical
// states only, known diagonal columns for the guide-friction normal-force lags and the energy
// integrals) against CVODE's full difference-quotient Jacobian: the neglected entries change only
// the corrector's iteration matrix, so at a tight accuracy both runs must give the same motion,
// coupling torque and friction normal forces. The expected values come from the full-Jacobian
// run, i.e. CVODE's own Jacobian, not from the structured one under test.
//
// Scene: balanced-4cart (elastic coupling: all four mechanical states; guide friction: eight
// normal-force states), the first second (the start-up, where the normal forces switch sign and
// change fastest), at accuracy 1e-10.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "multibody/MultibodySimulation.h"
#include "scene/SceneParser.h"

namespace rollerdyn {
namespace {

// max_k |a_k - b_k| / max_k |a_k| of one column over the rows both tables share.
double relativeColumnDifference(const Table& a, const Table& b, const std::string& column) {
  const int ia = a.index(column), ib = b.index(column);
  const size_t n = std::min(a.rows.size(), b.rows.size());
  double diff = 0, scale = 0;
  for (size_t k = 0; k < n; ++k) {
    diff = std::max(diff, std::abs(a.rows[k][ia] - b.rows[k][ib]));
    scale = std::max(scale, std::abs(a.rows[k][ia]));
  }
  return scale > 0 ? diff / scale : diff;
}

RunResult runMinimal(bool structured_jacobian) {
  const Scene sc = parseSceneFile(std::string(ROLLERDYN_SOURCE_DIR) + "/model/balanced-4cart.yaml",
                                  {"simulation.t_end=1.0", "simulation.accuracy=1e-10",
                                   "simulation.formulation=minimal"});
  MultibodyOptions options;
  options.structured_jacobian = structured_jacobian;
  const MultibodyModel model(sc, options);
  return simulateMultibody(model);
}

TEST(MinimalJacobian, StructuredJacobianGivesTheFullJacobiansSolution) {
  const RunResult full = runMinimal(false), structured = runMinimal(true);
  ASSERT_TRUE(full.stats.complete) << full.stats.status;
  ASSERT_TRUE(structured.stats.complete) << structured.stats.status;
  ASSERT_EQ(full.timeseries.rows.size(), structured.timeseries.rows.size());
  ASSERT_GT(full.timeseries.rows.size(), 100u);

  EXPECT_LE(relativeColumnDifference(full.timeseries, structured.timeseries, "omega_crank"), 1e-8);
  EXPECT_LE(relativeColumnDifference(full.timeseries, structured.timeseries, "coupling_torque"), 1e-8);
  int carts = 0;
  for (int j = 1; full.reactions.has("N_front_" + std::to_string(j)); ++j, ++carts) {
    const std::string n = std::to_string(j);
    // friction_j is f·(|N̂_front| + |N̂_rear|): the normal-force lag states themselves.
    for (const std::string c : {"N_front_" + n, "N_rear_" + n, "friction_" + n})
      EXPECT_LE(relativeColumnDifference(full.reactions, structured.reactions, c), 1e-8) << c;
  }
  EXPECT_EQ(carts, 4);

  // The structure was used: every Jacobian costs 4 evaluations instead of 16 (4 mechanical
  // states, 8 normal forces, 4 energy integrals), so the run needs fewer evaluations.
  ASSERT_GT(full.stats.jacobian_evaluations, 0);
  ASSERT_GT(structured.stats.jacobian_evaluations, 0);
  EXPECT_LT(structured.stats.realizations, full.stats.realizations);
}

}  // namespace
}  // namespace rollerdyn
