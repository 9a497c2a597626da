// Every model and integrator answers the caller's RunControl the same way (analysis/RunRecorder.h):
// Ctrl-C stops the run at the output row where it is seen, keeping the rows before it, and the
// progress report comes once per output row after the initial state. The reduced model once ran every run to its end.
#include <gtest/gtest.h>

#include <atomic>
#include <string>
#include <vector>

#include "compare/RunModel.h"
#include "scene/SceneParser.h"

namespace rollerdyn {
namespace {

struct Case {
  const char* what;
  const char* model;
  std::vector<std::string> sets;
};

Scene sceneOf(const Case& c) {
  std::vector<std::string> sets = {"simulation.t_end=1.0", "simulation.output_step=0.01"};
  sets.insert(sets.end(), c.sets.begin(), c.sets.end());
  return parseSceneFile(std::string(ROLLERDYN_SOURCE_DIR) + "/model/recuperative-2cart.yaml", sets);
}

const std::vector<Case>& everyModel() {
  static const std::vector<Case> cases = {
      {"multibody, minimal coordinates", "multibody", {"simulation.formulation=minimal"}},
      {"multibody, constrained", "multibody",
       {"simulation.formulation=constrained", "loads.guide_friction.normal_force=lagged"}},
      {"reduced, CVODE", "reduced", {}},
      {"reduced, Baranov's scheme", "reduced", {"coupling.type=rigid", "reduced.integrator=baranov"}},
  };
  return cases;
}

TEST(RunControlEveryModel, CtrlCStopsEveryModelAtTheRowWhereItIsSeen) {
  for (const Case& c : everyModel()) {
    std::atomic<bool> stop{false};
    std::vector<double> reported;
    RunControl control;
    control.interrupt = &stop;
    control.progress = [&](double t, double t_end) {
      reported.push_back(t);
      EXPECT_EQ(t_end, 1.0) << c.what;
      if (t >= 0.25 - 1e-9) stop = true;  // Ctrl-C while the row at t = 0.25 s is reported
    };
    const RunResult run = runModel(sceneOf(c), c.model, control);
    EXPECT_FALSE(run.stats.complete) << c.what;
    EXPECT_EQ(run.stats.status, "interrupted at t = 0.25 s") << c.what;
    ASSERT_EQ(run.timeseries.rows.size(), 26u) << c.what;  // t = 0, 0.01, ..., 0.25
    EXPECT_NEAR(run.timeseries.rows.back()[0], 0.25, 1e-12) << c.what;
    EXPECT_EQ(reported.size(), 25u) << c.what;  // one report per row after the initial state
  }
}

TEST(RunControlEveryModel, ProgressOnlyFollowsARunThatReachesItsEnd) {
  for (const Case& c : everyModel()) {
    long reports = 0;
    double last = -1;
    RunControl control;
    control.progress = [&](double t, double) {
      EXPECT_GT(t, last) << c.what;
      last = t;
      ++reports;
    };
    const RunResult run = runModel(sceneOf(c), c.model, control);
    EXPECT_TRUE(run.stats.complete) << c.what << ": " << run.stats.status;
    EXPECT_EQ(reports, long(run.timeseries.rows.size()) - 1) << c.what;  // every row but the initial state
    EXPECT_NEAR(last, 1.0, 1e-12) << c.what;
  }
}

}  // namespace
}  // namespace rollerdyn
