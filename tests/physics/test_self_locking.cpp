// The self-locking index of physics/SelfLocking.h against the determinant of the cart statics
// computed independently (the 3x3 matrix of reduced/CartStatics.h's equations, expanded by the rule
// of Sarrus) over every sign pattern of the friction, and its dead-centre figures.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "physics/SelfLocking.h"
#include "scene/SceneParser.h"

namespace rollerdyn {
namespace {

Scene scene(std::vector<std::string> sets) {
  return parseSceneFile(std::string(ROLLERDYN_SOURCE_DIR) + "/model/balanced-4cart.yaml", sets);
}

// Determinant of the cart statics' matrix (rows ΣX, ΣY, ΣM; unknowns F_rod, N_front, N_rear)
// with friction k_i per unit N_i, by the rule of Sarrus.
double statics(const CartGeometry& g, double beta, double k1, double k2) {
  const double a[3][3] = {{-std::cos(beta), k1, k2},
                          {std::sin(beta), -1.0, -1.0},
                          {0.0, -(g.p - g.b) - k1 * 0.5 * g.d, -(g.p + g.b) - k2 * 0.5 * g.d}};
  return a[0][0] * a[1][1] * a[2][2] + a[0][1] * a[1][2] * a[2][0] + a[0][2] * a[1][0] * a[2][1] -
         a[0][2] * a[1][1] * a[2][0] - a[0][0] * a[1][2] * a[2][1] - a[0][1] * a[1][0] * a[2][2];
}

// Largest friction gain 1 - det/det0 over the friction's sign patterns at rod angle ±β.
double worstGain(const Scene& sc, double beta) {
  const CartGeometry& g = sc.carts.geometry;
  const double f = sc.loads.guide_friction;
  double worst = 0;
  for (double k1 : {-f, f})
    for (double k2 : {-f, f})
      for (double b : {-beta, beta})  // both signs of β occur in a revolution
        worst = std::max(worst, 1.0 - statics(g, b, k1, k2) / statics(g, b, 0.0, 0.0));
  return worst;
}

TEST(SelfLocking, IndexIsTheWorstDeterminantGainAtTheLargestRodAngle) {
  for (const char* l : {"0.8", "0.4", "0.25", "0.2105263157894737"})
    for (const char* f : {"0.008", "0.1", "0.3"}) {
      const Scene sc = scene({std::string("rods.length=") + l, std::string("loads.guide_friction.coefficient=") + f});
      const LockingMargins m = lockingMargins(sc);
      ASSERT_TRUE(m.applicable);
      EXPECT_NEAR(m.self_locking_index, worstGain(sc, m.beta_max), 1e-12) << "l = " << l << ", f = " << f;
    }
  // The numbers of docs/friction-and-reactions.md.
  EXPECT_NEAR(lockingMargins(scene({})).self_locking_index, 0.0034, 5e-5);
  EXPECT_NEAR(lockingMargins(scene({"rods.length=0.2105263157894737"})).self_locking_index, 0.0347, 5e-5);
  EXPECT_NEAR(lockingMargins(scene({"rods.length=0.2105263157894737", "loads.guide_friction.coefficient=0.3"}))
                  .self_locking_index,
              1.30, 0.005);
}

TEST(SelfLocking, DeadCentreFigures) {
  const LockingMargins m = lockingMargins(scene({"rods.length=0.20100502512562815"}));  // r/l = 0.995
  EXPECT_NEAR(m.beta_max * 180 / M_PI, 84.27, 0.01);
  EXPECT_NEAR(m.transmission_angle_min * 180 / M_PI, 5.73, 0.01);
  EXPECT_NEAR(m.rod_force_factor, 10.01, 0.01);
  EXPECT_FALSE(lockingMargins(parseSceneFile(std::string(ROLLERDYN_SOURCE_DIR) + "/model/cam-drive.yaml", {})).applicable);
}

}  // namespace
}  // namespace rollerdyn
