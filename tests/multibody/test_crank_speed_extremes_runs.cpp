// The crank speed's extremes of a run, and δ with them, do not depend on the output step: they
// come from the integrator's steps (analysis/CrankSpeedExtrema.h), in every integration loop
// (multibody constrained and minimal, reduced CVODE). The scene's minimum and maximum are sharp
// against 5 ms rows (tests/analysis/data/sharp-speed-extremes.yaml); before, the rows alone
// gave extremes 1.5e-3 of ω_max apart between output steps of 5 ms and 0.5 ms, and different
// ones in every revolution.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "analysis/Metrics.h"
#include "analysis/SteadyState.h"
#include "multibody/MultibodySimulation.h"
#include "reduced/ReducedModel.h"
#include "scene/SceneParser.h"

namespace rollerdyn {
namespace {

Scene scene(const std::string& output_step, const std::string& formulation) {
  return parseSceneFile(std::string(ROLLERDYN_SOURCE_DIR) + "/tests/analysis/data/sharp-speed-extremes.yaml",
                        {"simulation.output_step=" + output_step, "simulation.formulation=" + formulation});
}

struct Extremes {
  double min = 0, max = 0, delta = 0;
  bool reached = false;
};

Extremes extremesOf(const Scene& sc, const RunResult& run) {
  const SteadyState ss = detectSteadyState(run, sc.simulation.steady_window_revolutions);
  const WindowMetrics m = computeMetrics(run, ss);
  return {m.omega_min, m.omega_max, m.coefficients.delta, ss.reached};
}

// Both output steps integrate with the same steps (the rows never steer the integrator), so the
// extremes agree to the interpolant's accuracy, far below the simulation.accuracy = 1e-6 the
// steps were taken with; 1e-5 of ω_max leaves room for a window that starts one revolution apart
// and is still 1/150 of what the rows alone differed by.
void expectIndependentOfTheOutputStep(const Extremes& coarse, const Extremes& fine) {
  ASSERT_TRUE(coarse.reached);
  ASSERT_TRUE(fine.reached);
  EXPECT_NEAR(coarse.max, fine.max, 1e-5 * fine.max);
  EXPECT_NEAR(coarse.min, fine.min, 1e-5 * fine.max);
  EXPECT_NEAR(coarse.delta, fine.delta, 1e-5);
}

TEST(CrankSpeedExtremesRuns, TheReducedModelsExtremesDoNotDependOnTheOutputStep) {
  const Scene c = scene("0.005", "constrained"), f = scene("0.001", "constrained");
  expectIndependentOfTheOutputStep(extremesOf(c, runReducedModel(c)), extremesOf(f, runReducedModel(f)));
}

TEST(CrankSpeedExtremesRuns, TheMultibodyExtremesDoNotDependOnTheOutputStep) {
  for (const char* formulation : {"constrained", "minimal"}) {
    SCOPED_TRACE(formulation);
    const Scene c = scene("0.005", formulation), f = scene("0.001", formulation);
    expectIndependentOfTheOutputStep(extremesOf(c, runMultibodyModel(c)), extremesOf(f, runMultibodyModel(f)));
  }
}

}  // namespace
}  // namespace rollerdyn
