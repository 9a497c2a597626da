// The minimal formulation's structured Newton Jacobian (difference quotients for the mechanical
// states only; known columns for the guide-friction normal-force lags, i.e. their diagonal and
// the friction-dissipation rate's dependence on them, and for the energy integrals) against
// CVODE's full difference-quotient Jacobian: the neglected entries change only
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

#include "multibody/MultibodyModel.h"
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
                                   "simulation.formulation=minimal", "loads.guide_friction.normal_force=lagged"});
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

// The one state-dependent known entry: ∂(friction-dissipation rate)/∂N̂, against central
// differences of the rate the model integrates (MultibodyModel::auxiliaryRates), at a running
// state with carts moving both ways.
TEST(MinimalJacobian, FrictionPowerGradientMatchesDifferencesOfTheDissipationRate) {
  const Scene sc = parseSceneFile(std::string(ROLLERDYN_SOURCE_DIR) + "/model/balanced-4cart.yaml",
                                  {"loads.guide_friction.normal_force=lagged"});
  const MultibodyModel model(sc);
  SimTK::State s = model.assembledState(0.7, 10.4, 1e-3);
  const SimTK::MultibodySystem& system = model.system();
  const int n_normals = 2 * sc.carts.count;
  const int row = n_normals + 2;  // z = [N̂ ..., motor work, damping, friction dissipation, load work]
  ASSERT_EQ(model.forces().getZ(s).size(), n_normals + 4);
  const SimTK::Vector gradient = model.frictionPowerGradient(s);
  ASSERT_EQ(gradient.size(), n_normals);
  const SimTK::Vector normals_now(n_normals, 0.0);  // N does not enter the dissipation rate
  auto rate = [&](const SimTK::State& st) {
    SimTK::Vector zdot;
    model.auxiliaryRates(st, normals_now, zdot);
    return zdot[row];
  };
  int moving = 0;
  for (int k = 0; k < n_normals; ++k) {
    const double n_k = model.forces().getZ(s)[k], delta = 1e-3 * std::max(std::abs(n_k), 1.0);
    ASSERT_GT(std::abs(n_k), delta);  // away from the kink of |N̂| at 0
    SimTK::State plus = s, minus = s;
    model.forces().updZ(plus)[k] += delta;
    model.forces().updZ(minus)[k] -= delta;
    system.realize(plus, SimTK::Stage::Velocity);
    system.realize(minus, SimTK::Stage::Velocity);
    const double difference = (rate(plus) - rate(minus)) / (2.0 * delta);
    EXPECT_NEAR(gradient[k], difference, 1e-9 * std::max(std::abs(difference), 1.0)) << k;
    // Dissipated power grows with |N̂|.
    EXPECT_GE(gradient[k] * (n_k > 0 ? 1.0 : -1.0), 0.0) << k;
    moving += std::abs(gradient[k]) > 1e-3;
  }
  EXPECT_GT(moving, 0);  // the state exercises the law (carts not at rest)
  const Scene no_friction = parseSceneFile(std::string(ROLLERDYN_SOURCE_DIR) + "/model/balanced-4cart.yaml",
                                           {"loads.guide_friction.coefficient=0"});
  const MultibodyModel frictionless(no_friction);
  EXPECT_EQ(frictionless.frictionPowerGradient(frictionless.initialState()).size(), 0);
}

}  // namespace
}  // namespace rollerdyn
