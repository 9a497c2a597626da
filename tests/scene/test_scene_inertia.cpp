// The inertias a Scene sums for both models, against Loveikin, Pochka, Romasevych (2018) eq. (1)-(3)
// written out here: the motor side (J_p + J_m + J_red)·δ·u² with a motor-shaft flywheel counted
// u² times, the crankshaft n·J'_K + J_shaft with a crankshaft flywheel counted once, and a cart's
// mass with half the rod for split rods.
#include <gtest/gtest.h>

#include "support/Loveikin2018Scene.h"

namespace rollerdyn {
namespace {

TEST(SceneInertia, FlywheelCountsOnItsShaftAndEq1To3) {
  Scene s = test_scenes::loveikin2018Scene();
  s.crank.inertia_per_crank = 0.7;
  s.crank.shaft_inertia = 3.0;
  s.reducer.delta = 1.1;
  const double u = 9.8, n = 4, Jm = (0.4 + 0.32 + 0.046) * 1.1 * u * u, Jc = n * 0.7 + 3.0;
  s.flywheel = {50.0, FlywheelLocation::MotorShaft};
  EXPECT_NEAR(s.motorSideInertia(), Jm + 50.0 * 1.1 * u * u, 1e-12 * Jm);
  EXPECT_NEAR(s.crankSideInertia(), Jc, 1e-12 * Jc);
  s.flywheel = {50.0, FlywheelLocation::Crankshaft};
  EXPECT_NEAR(s.motorSideInertia(), Jm, 1e-12 * Jm);
  EXPECT_NEAR(s.crankSideInertia(), Jc + 50.0, 1e-12 * Jc);
  s.rods.model = RodModel::Split;
  EXPECT_EQ(s.cartMassWithRodShare(), 1000.0 + 32.0);  // eq. (3): m_B = m'_B + m_rod/2
  s.rods.model = RodModel::Distributed;
  EXPECT_EQ(s.cartMassWithRodShare(), 1000.0);
}

}  // namespace
}  // namespace rollerdyn
