// The stability charts' rows are computed on parallel threads: the chart is the same, point for
// point and bit for bit, as the one computed row after row on one thread.
#include <cmath>

#include <gtest/gtest.h>

#include "modes/DriveOrbit.h"
#include "modes/StabilityChart.h"
#include "scene/SceneParser.h"
#include "reduced/ReducedModel.h"

using namespace rollerdyn;
using namespace rollerdyn::modes;

namespace {

// Equal, or both NaN.
bool same(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

void expectSameCharts(const StabilityChart& a, const StabilityChart& b) {
  ASSERT_EQ(a.grid.size(), b.grid.size());
  for (size_t iy = 0; iy < a.grid.size(); ++iy) {
    ASSERT_EQ(a.grid[iy].size(), b.grid[iy].size());
    for (size_t ic = 0; ic < a.grid[iy].size(); ++ic) {
      const StabilityPoint &p = a.grid[iy][ic], &q = b.grid[iy][ic];
      EXPECT_EQ(p.c, q.c);
      EXPECT_EQ(p.y, q.y);
      EXPECT_EQ(p.found, q.found) << iy << "," << ic;
      EXPECT_TRUE(same(p.omega_mean, q.omega_mean)) << iy << "," << ic;
      EXPECT_TRUE(same(p.max_modulus, q.max_modulus)) << iy << "," << ic << ": " << p.max_modulus << " " << q.max_modulus;
      EXPECT_TRUE(same(p.torsional_damping_ratio, q.torsional_damping_ratio)) << iy << "," << ic;
      EXPECT_EQ(p.verdict, q.verdict);
    }
  }
  EXPECT_EQ(a.unstable_points, b.unstable_points);
  EXPECT_EQ(a.zones.size(), b.zones.size());
}

}  // namespace

TEST(StabilityChart, RowsOnParallelThreadsGiveTheSameChartAsOneThread) {
  // Loveikin and Pochka's (2007) two-cart machine with an elastic coupling: a grid around
  // 24 kN·m/rad that holds stable and unstable points.
  const Scene scene = parseSceneFile(std::string(ROLLERDYN_SOURCE_DIR) + "/model/recuperative-2cart.yaml",
                                     {"coupling.type=elastic", "coupling.stiffness=24000", "coupling.damping=0"});
  const SteadyGuess g = steadyGuess(ReducedModel(scene));
  ASSERT_TRUE(g.ok);
  const std::vector<double> c = geometricGrid(12000, 48000, 3);
  const std::vector<double> w = linearGrid(0.8 * g.omega, 1.1 * g.omega, 3);
  expectSameCharts(chartOverSpeed(scene, g.omega, c, w, 0.0, 1), chartOverSpeed(scene, g.omega, c, w, 0.0, 3));
  const std::vector<double> k = linearGrid(0.0, 200.0, 3);
  expectSameCharts(chartOverDamping(scene, g.omega, c, k, 1), chartOverDamping(scene, g.omega, c, k, 3));
}
