// A switching event that falls on an output row up to round-off: t_on + t_ramp = 0.65 + 2.4 s is
// 3.05 in binary, the output row 610·0.005 s is 4.4e-16 s later. The integrators stop at the
// event, restart there and must count the row as reached: CVODE refuses to step across a gap of a
// few units of round-off (CV_TOO_CLOSE), and both models once ended the run there with an
// integrator failure (a generated machine of the consistency harness).
#include <gtest/gtest.h>

#include <string>

#include "multibody/MultibodySimulation.h"
#include "reduced/ReducedModel.h"
#include "scene/SceneParser.h"

namespace rollerdyn {
namespace {

Scene rampEndingOnARow(const std::string& formulation) {
  return parseSceneFile(std::string(ROLLERDYN_SOURCE_DIR) + "/model/balanced-4cart.yaml",
                        {"initial.crank_speed=0", "motor.start.method=frequency_converter", "motor.start.t_on=0.65",
                         "motor.start.ramp_time=2.4", "motor.start.initial_frequency=5", "simulation.output_step=0.005",
                         "simulation.t_end=3.5", "simulation.formulation=" + formulation});
}

void expectRunsToTheEnd(const RunResult& r, const std::string& what) {
  EXPECT_TRUE(r.stats.complete) << what << ": " << r.stats.status;
  ASSERT_FALSE(r.timeseries.rows.empty()) << what;
  EXPECT_NEAR(r.timeseries.column("t").back(), 3.5, 1e-12) << what << ": " << r.stats.status;
}

TEST(EventOnAnOutputRow, AConverterRampEndingOnARowRunsEveryModelToTheEnd) {
  ASSERT_NE(0.65 + 2.4, 610 * 0.005);  // the case: the two differ by round-off only
  expectRunsToTheEnd(runReducedModel(rampEndingOnARow("minimal")), "reduced model");
  expectRunsToTheEnd(runMultibodyModel(rampEndingOnARow("minimal")), "multibody, minimal coordinates");
  expectRunsToTheEnd(runMultibodyModel(rampEndingOnARow("constrained")), "multibody, constrained");
}

}  // namespace
}  // namespace rollerdyn
