// A crank side without inertia behind an elastic coupling: J_n2(φ) = Σ m_B·x_B'(φ)² vanishes at
// the dead centres, where the crank's equation divides by it. The reduced model refuses it with
// the multibody model's sentence instead of crawling towards the singularity (a one-cart drive the
// flywheel-by-runs tried without a flywheel ran for minutes).
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "reduced/ReducedModel.h"
#include "scene/SceneParser.h"

namespace rollerdyn {
namespace {

Scene oneCart(const std::vector<std::string>& more) {
  std::vector<std::string> sets = {"carts.count=1", "rods.model=massless", "crank.inertia_per_crank=0",
                                   "crank.shaft_inertia=0", "flywheel.inertia=0", "coupling.type=elastic"};
  sets.insert(sets.end(), more.begin(), more.end());
  return parseSceneFile(std::string(ROLLERDYN_SOURCE_DIR) + "/model/balanced-4cart.yaml", sets);
}

TEST(ReducedCrankInertia, ACrankSideWithoutInertiaBehindAnElasticCouplingIsRefused) {
  EXPECT_NO_THROW(ReducedModel(oneCart({})));  // its kinematics and loads can still be read
  try {
    runReducedModel(oneCart({"simulation.t_end=0.5"}));
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("the crankshaft has no inertia of its own"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(runReducedModel(oneCart({"simulation.t_end=0.5", "crank.shaft_inertia=1"})));
  EXPECT_NO_THROW(runReducedModel(oneCart({"simulation.t_end=0.5", "flywheel.inertia=5"})));
  // The motor side lends its inertia to a rigid drive.
  EXPECT_NO_THROW(runReducedModel(oneCart({"simulation.t_end=0.5", "coupling.type=rigid"})));
}

}  // namespace
}  // namespace rollerdyn
