// A simulated run (the reduced model's own CVODE integrator) at a point the Floquet analysis marks
// unstable grows by the predicted multiplier per revolution and shows the predicted order in its
// spectrum; at a stable point the departure decays.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "modes/GrowthCheck.h"
#include "scene/SceneParser.h"

using namespace rollerdyn;
using namespace rollerdyn::modes;

namespace {
Scene recuperativeElastic(double c, double k) {
  return parseSceneFile(std::string(ROLLERDYN_SOURCE_DIR) + "/model/recuperative-2cart.yaml",
                        {"coupling.type=elastic", "coupling.stiffness=" + std::to_string(c),
                         "coupling.damping=" + std::to_string(k)});
}
}  // namespace

// Loveikin and Pochka's (2007) two-cart machine with an undamped elastic coupling of 24 kN·m/rad: a
// parametric zone of the stability chart (the complex multiplier pair |μ| = 1.58 per revolution).
// The departure, seeded by the integrator's error (~1e-10 rad), is fitted over the revolutions
// where it stays linear (< 1 % of the mean twist). Tolerance 6 %: with a complex pair the
// departure is |μ|^n·|cos(nθ + β)|, and the cosine's dips bias a least-squares slope over ~25
// revolutions by a few per cent.
TEST(GrowthCheck, UnstablePointGrowsAsPredicted) {
  const GrowthMeasurement g = measureGrowth(recuperativeElastic(24000, 0), 30, 8);
  ASSERT_TRUE(g.ok) << g.failure;
  ASSERT_GE(g.revolutions_fitted, 10);
  EXPECT_GT(g.predicted_modulus, 1.3);
  EXPECT_NEAR(g.measured_growth / g.predicted_modulus, 1.0, 0.06);
  // The growing mode at the predicted order (between whole orders), within the spectrum's
  // resolution of 1/8 order.
  ASSERT_TRUE(std::isfinite(g.peak_order));
  EXPECT_NEAR(g.peak_order, g.predicted_order, 1.0 / 8 + 1e-9);
}

TEST(GrowthCheck, StablePointDecays) {
  const GrowthMeasurement g = measureGrowth(recuperativeElastic(24000, 300), 30, 8);
  ASSERT_TRUE(g.ok) << g.failure;
  EXPECT_LT(g.predicted_modulus, 1.0);
  // No growth: over the 30 revolutions in which the unstable point's departure grows 1e5-fold, this
  // one stays at the integrator's noise (~1e-10 rad at accuracy 1e-11; the mean twist is 0.01 rad).
  ASSERT_GE(g.deviation.size(), 29u);
  for (double d : g.deviation) EXPECT_LT(d, 1e-8);
}
