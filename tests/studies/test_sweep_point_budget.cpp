// CPU budget per sweep point (src/studies/SweepPointBudget.h): a point over budget becomes a
// `timeout` row, one within it has the numbers of the same point run in this process.
#include <gtest/gtest.h>

#include <cmath>

#include "studies/SweepPointBudget.h"

namespace rollerdyn {
namespace {

const std::string kScene = std::string(ROLLERDYN_SOURCE_DIR) + "/model/recuperative-2cart.yaml";

TEST(SweepPointBudget, WithinBudgetTheRowIsTheInProcessRow) {
  SweepOptions o;
  o.scene_path = kScene;
  o.base_overrides = {"simulation.t_end=4", "simulation.steady_window_revolutions=2"};
  o.params = {parseSweepValues("crank.offset_deg", "90")};
  o.model = "reduced";
  const SweepPoint here = runSweepPoint(o, {"90"}, {90.0});
  const SweepPoint child = runSweepPointWithBudget(o, {"90"}, {90.0}, 20.0);
  ASSERT_TRUE(here.complete) << here.status;
  EXPECT_EQ(child.status, here.status);
  for (std::size_t k = 0; k < here.metrics.size(); ++k) {
    if (std::isnan(here.metrics[k])) EXPECT_TRUE(std::isnan(child.metrics[k])) << k;
    else EXPECT_EQ(child.metrics[k], here.metrics[k]) << k;
  }
}

TEST(SweepPointBudget, OverBudgetIsATimeoutRow) {
  // About 5 s of CPU in the multibody model (about 0.01 s per simulated second here), 1 s allowed.
  SweepOptions o;
  o.scene_path = kScene;
  o.base_overrides = {"simulation.t_end=500"};
  o.params = {parseSweepValues("crank.offset_deg", "90")};
  o.model = "multibody";
  const SweepPoint p = runSweepPointWithBudget(o, {"90"}, {90.0}, 1.0);
  EXPECT_EQ(p.status.rfind("timeout: CPU budget 1 s exceeded", 0), 0u) << p.status;
  EXPECT_FALSE(p.complete);
  EXPECT_TRUE(std::isnan(p.metric("delta")));
  // The kernel stops it at the budget (SIGXCPU): it used about 1 s, not the 5 s the run needs
  // (getrusage's user + system split is sampled at scheduler ticks, so it may read a bit less).
  EXPECT_GE(p.cpu_seconds, 0.5);
  EXPECT_LT(p.cpu_seconds, 2.5);
  EXPECT_EQ(p.texts, std::vector<std::string>{"90"});
}

}  // namespace
}  // namespace rollerdyn
