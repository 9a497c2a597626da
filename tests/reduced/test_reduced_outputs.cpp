// The reduced model's output columns against the state each row reports, by the conventions of
// src/analysis/RunResult.h: cart position, velocity and acceleration from the slider-crank
// transfer functions at the row's crank angle, speed and acceleration (a = x_B''·ω² + x_B'·ε),
// the guide reactions, rod force and guide friction (along world x) as the quasi-static cart
// statics of that row (Loveikin, Pochka, Romasevych (2018) eq. (10)-(25), src/reduced/CartStatics.h),
// and the kinetostatic reactions with each cart's d'Alembert force −m_B·a.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "physics/RollerLoads.h"
#include "physics/SliderCrank.h"
#include "reduced/CartStatics.h"
#include "reduced/ReducedModel.h"

namespace rollerdyn {
namespace test {
Scene loveikin2018LikeScene();
}
namespace {

Scene outputScene() {
  Scene s = test::loveikin2018LikeScene();
  s.carts.side = {1, -1, 1, -1};  // both sides
  s.crank.offset = 70.0 * M_PI / 180.0;
  s.rods.model = RodModel::Distributed;
  s.loads.roller_force_direction = RollerForceDirection::OpposesVelocity;
  s.loads.roller_force_front = s.loads.roller_force_rear = 1500.0;  // the motor can carry them
  s.initial.crank_speed = 10.0;
  s.simulation.t_end = 0.6;
  s.simulation.output_step = 0.01;
  return s;
}

TEST(ReducedOutputs, RowsAreTheStateAndTheCartStaticsOfIt) {
  Scene s = outputScene();
  s.reduced.guide_normals = ReducedGuideNormals::QuasiStatic;  // the rows' reactions: the papers' statics
  const RunResult r = runReducedModel(s);
  ASSERT_TRUE(r.stats.complete) << r.stats.status;
  const Table &ts = r.timeseries, &rx = r.reactions;
  ASSERT_EQ(ts.rows.size(), rx.rows.size());
  double largest_eps = 0, largest_friction = 0;
  for (std::size_t i = 1; i < ts.rows.size(); i += 7) {
    const auto& row = ts.rows[i];
    const double phi = row[ts.index("phi_crank")], w = row[ts.index("omega_crank")], eps = row[ts.index("eps_crank")];
    largest_eps = std::max(largest_eps, std::abs(eps));
    for (int j = 0; j < s.carts.count; ++j) {
      const std::string n = std::to_string(j + 1);
      const int sg = s.carts.side[j];
      const SliderCrankPose p = sliderCrankExact(phi + j * s.crank.offset, s.crank.radius, s.rods.length, sg);
      const double v = p.dx_B * w, a = p.d2x_B * w * w + p.dx_B * eps;
      EXPECT_NEAR(row[ts.index("x_cart_" + n)], p.x_B, 1e-12) << "row " << i << " cart " << n;
      EXPECT_NEAR(row[ts.index("v_cart_" + n)], v, 1e-12) << "row " << i << " cart " << n;
      EXPECT_NEAR(row[ts.index("a_cart_" + n)], a, 1e-9 * (1 + std::abs(a))) << "row " << i << " cart " << n;
      // Quasi-static statics at the local velocity v' = σ·v; friction reported along world x.
      const CartStaticsResult q = solveCartStatics(s, p.beta, rollerHorizontalForce(s.loads, sg * v),
                                                   frictionDirection(s.loads, sg * v), 0.0);
      EXPECT_NEAR(rx.rows[i][rx.index("N_front_" + n)], q.N_front, 1e-9 * std::abs(q.N_front)) << "row " << i;
      EXPECT_NEAR(rx.rows[i][rx.index("N_rear_" + n)], q.N_rear, 1e-9 * std::abs(q.N_rear)) << "row " << i;
      EXPECT_NEAR(rx.rows[i][rx.index("F_rod_" + n)], q.F_rod, 1e-9 * (1 + std::abs(q.F_rod))) << "row " << i;
      EXPECT_NEAR(rx.rows[i][rx.index("friction_" + n)], sg * q.friction, 1e-9 * (1 + std::abs(q.friction)))
          << "row " << i << " cart " << n << " (world x)";
      // Friction opposes the cart's world velocity.
      if (std::abs(v) > 0.05) EXPECT_LT(rx.rows[i][rx.index("friction_" + n)] * v, 0.0) << "row " << i;
      largest_friction = std::max(largest_friction, std::abs(q.friction));
    }
  }
  EXPECT_GT(largest_eps, 1.0);       // the ε term of a_cart is exercised
  EXPECT_GT(largest_friction, 10.0);  // and so is the friction column
}

TEST(ReducedOutputs, KinetostaticReactionsAddEachCartsDAlembertForce) {
  const Scene s = outputScene();
  const ReducedModel m(s);
  const double mB = s.cartMassWithRodShare();
  for (double phi : {0.3, 1.7, 4.0})
    for (double eps : {25.0, -40.0}) {
      const double w = 10.0;
      const std::vector<CartEvaluation> kin = m.cartReactions(phi, w, eps, /*include_inertia=*/true);
      for (int j = 0; j < s.carts.count; ++j) {
        const int sg = s.carts.side[j];
        const SliderCrankPose p = sliderCrankExact(phi + j * s.crank.offset, s.crank.radius, s.rods.length, sg);
        const double v = p.dx_B * w, a = p.d2x_B * w * w + p.dx_B * eps;  // world x
        // d'Alembert force along the local axis x' = σ·x: −m_B·σ·a.
        const CartStaticsResult q = solveCartStatics(s, p.beta, rollerHorizontalForce(s.loads, sg * v),
                                                     frictionDirection(s.loads, sg * v), -mB * sg * a);
        EXPECT_NEAR(kin[j].statics.N_front, q.N_front, 1e-9 * std::abs(q.N_front)) << phi << " " << eps << " " << j;
        EXPECT_NEAR(kin[j].statics.N_rear, q.N_rear, 1e-9 * std::abs(q.N_rear)) << phi << " " << eps << " " << j;
        EXPECT_NEAR(kin[j].statics.F_rod, q.F_rod, 1e-9 * (1 + std::abs(q.F_rod))) << phi << " " << eps << " " << j;
      }
    }
}

}  // namespace
}  // namespace rollerdyn
