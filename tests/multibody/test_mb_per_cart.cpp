// Per-cart inputs (docs/per-cart.md) in both formulations of the multibody model and in the
// reduced model:
//  * lists equal to the uniform value give bit-identical runs to the short form (the same
//    numbers reach the same expressions);
//  * on a non-uniform scene (cart 2 empty: no mix under its rollers; cart 3's crank 2° off) the
//    constrained and the minimal formulation agree as they do on the shipped scenes
//    (test_mb_minimal.cpp: 1e-8 in speed and coupling torque at accuracy 1e-10).
// The reduced-against-multibody agreement on the same scene is in tests/validation/
// test_equivalence.cpp.
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

std::string scenePath(const std::string& name) { return std::string(ROLLERDYN_SOURCE_DIR) + "/model/" + name; }

Scene shortScene(std::vector<std::string> overrides) {
  overrides.push_back("simulation.t_end=0.6");
  return parseSceneFile(scenePath("balanced-4cart.yaml"), overrides);
}

// The short form and its per-cart spelling with every list equal to the scene's value.
const std::vector<std::string> kAsLists = {
    "carts.mass=[1000, 1000, 1000, 1000]",
    "loads.roller_force_front=[7962, 7962, 7962, 7962]",
    "loads.roller_normal_rear=[9740, 9740, 9740, 9740]",
    "loads.rolling_resistance=[0, 0, 0, 0]",
    "crank.angle_error_deg=[0, 0, 0, 0]",
};

void expectIdentical(const Table& a, const Table& b, const std::string& what) {
  ASSERT_EQ(a.columns, b.columns) << what;
  ASSERT_EQ(a.rows.size(), b.rows.size()) << what;
  for (size_t i = 0; i < a.rows.size(); ++i)
    for (size_t c = 0; c < a.columns.size(); ++c)
      if (!(std::isnan(a.rows[i][c]) && std::isnan(b.rows[i][c])))
        ASSERT_EQ(a.rows[i][c], b.rows[i][c]) << what << ": " << a.columns[c] << " row " << i;
}

// max_i |a_i - b_i| / max_i |a_i|.
double relDiff(const Table& a, const Table& b, const std::string& column) {
  const int ia = a.index(column), ib = b.index(column);
  const size_t n = std::min(a.rows.size(), b.rows.size());
  double d = 0, scale = 0;
  for (size_t k = 0; k < n; ++k) {
    d = std::max(d, std::abs(a.rows[k][ia] - b.rows[k][ib]));
    scale = std::max(scale, std::abs(a.rows[k][ia]));
  }
  return scale > 0 ? d / scale : d;
}

}  // namespace

TEST(PerCartInputs, UniformListsGiveIdenticalRunsInEveryModel) {
  for (const char* formulation : {"constrained", "minimal"}) {
    const std::string f = std::string("simulation.formulation=") + formulation;
    const Scene shortForm = shortScene({f});
    std::vector<std::string> sets = kAsLists;
    sets.push_back(f);
    const Scene lists = shortScene(sets);
    ASSERT_FALSE(lists.cart_loads.empty());
    const RunResult a = runMultibodyModel(shortForm), b = runMultibodyModel(lists);
    ASSERT_TRUE(a.stats.complete) << a.stats.status;
    expectIdentical(a.timeseries, b.timeseries, std::string("multibody ") + formulation);
    expectIdentical(a.reactions, b.reactions, std::string("multibody reactions ") + formulation);
  }
  const RunResult a = runReducedModel(shortScene({})), b = runReducedModel(shortScene(kAsLists));
  ASSERT_TRUE(a.stats.complete) << a.stats.status;
  expectIdentical(a.timeseries, b.timeseries, "reduced");
}

TEST(PerCartInputs, FormulationsAgreeWithAnEmptyCartAndACrankTwoDegreesOff) {
  // Both formulations with the lagged guide-friction normal force, the one law they share (the
  // constrained formulation cannot solve the friction loop algebraically).
  Scene sc = shortScene({"loads.guide_friction.normal_force=lagged", "loads.roller_force_front[1]=0", "loads.roller_force_rear[1]=0",
                         "loads.roller_normal_front[1]=0", "loads.roller_normal_rear[1]=0",
                         "crank.angle_error_deg[2]=2", "simulation.t_end=1.0", "simulation.accuracy=1e-10"});
  Scene constrained = sc, minimal = sc;
  constrained.simulation.formulation = Formulation::Constrained;
  minimal.simulation.formulation = Formulation::Minimal;
  const RunResult c = runMultibodyModel(constrained), m = runMultibodyModel(minimal);
  ASSERT_TRUE(c.stats.complete) << c.stats.status;
  ASSERT_TRUE(m.stats.complete) << m.stats.status;
  EXPECT_LE(relDiff(c.timeseries, m.timeseries, "omega_crank"), 1e-8);
  EXPECT_LE(relDiff(c.timeseries, m.timeseries, "coupling_torque"), 1e-8);
  for (const std::string& col : c.reactions.columns)
    if (col != "t") EXPECT_LE(relDiff(c.reactions, m.reactions, col), 1e-7) << col;
  EXPECT_GE(m.stats.formulation_self_check, 0.0);
  EXPECT_LT(m.stats.formulation_self_check, 1e-11);
  // The scene really is non-uniform: the empty cart's guide reactions are not the others'.
  const Scene uniform = shortScene({"simulation.t_end=1.0", "simulation.accuracy=1e-10"});
  const RunResult u = runMultibodyModel(uniform);
  EXPECT_GT(relDiff(u.timeseries, m.timeseries, "coupling_torque"), 1e-3);
}

}  // namespace rollerdyn
