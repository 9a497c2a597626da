// Cart statics: Loveikin, Pochka, Romasevych (2018) eq. (10), closed forms (14), (18), (22).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "reduced/CartStatics.h"
#include "scene/Scene.h"

namespace rollerdyn {
namespace test {
Scene loveikin2018LikeScene();
}

namespace {

// Relative error; `floor` stops a reaction that passes through zero (N1 = R1 + R2 + F·sin β -
// N2 - G is a difference of ~10⁴ N terms) from turning round-off into a "relative" error.
double relErr(double a, double b, double floor = 1.0) {
  return std::abs(a - b) / std::max(std::abs(b), floor);
}

TEST(CartStatics, ReproducesLoveikin2018ClosedFormsWithZeroDepth) {
  Scene s = test::loveikin2018LikeScene();
  s.carts.geometry.e = 0.0;  // eq. (18) has no (F01 + F02)·e term
  const double f = s.loads.guide_friction;
  ASSERT_EQ(f, 0.008);
  const CartGeometry& g = s.carts.geometry;
  const double R1 = s.loads.roller_normal_front, R2 = s.loads.roller_normal_rear;
  const double F01 = s.loads.roller_force_front, F02 = s.loads.roller_force_rear;
  const double G = (1000.0 + 64.0 / 2) * 9.81;  // m_B = m'_B + m_rod/2, eq. (3)
  const double fd2 = f * g.d / 2;
  int compared = 0;
  for (double beta = -0.2527; beta <= 0.2527; beta += 0.0023) {
    const CartStaticsResult r = solveCartStatics(s, beta, F01 + F02, +1.0);
    // Loveikin, Pochka, Romasevych (2018) eq. (14)
    const double F = ((R1 + R2 - G) * f + F01 + F02) / (std::cos(beta) - f * std::sin(beta));
    // eq. (18)
    const double N2 = (R1 * (g.b - g.a - fd2) + R2 * (g.b + g.a - fd2) - G * (g.b - fd2) +
                       F * std::sin(beta) * (g.b - g.p - fd2)) / (2 * g.b);
    // eq. (22)
    const double N1 = R1 + R2 + F * std::sin(beta) - N2 - G;
    // Eq. (10) takes the friction as f·(N1 + N2); that is f·(|N1| + |N2|) only while both guide
    // reactions are positive. At the extreme rod angle β < -0.24 rad the Loveikin, Pochka, Romasevych (2018) numbers give
    // N1 < 0 (front guide roller lifted against the upper guide) and eq. (14)-(22) would count
    // that reaction's friction as negative; there the model keeps friction dissipative.
    if (N1 > 0 && N2 > 0) {
      ++compared;
      EXPECT_LT(relErr(r.F_rod, F), 1e-12) << "beta " << beta;
      EXPECT_LT(relErr(r.N_rear, N2, G), 1e-12) << "beta " << beta;
      EXPECT_LT(relErr(r.N_front, N1, G), 1e-12) << "beta " << beta;
      EXPECT_LT(relErr(r.friction, f * (N1 + N2)), 1e-12);
    } else {
      EXPECT_LT(beta, -0.2);
      EXPECT_LT(r.N_front, 0.0);
      EXPECT_NEAR(r.friction, f * (std::abs(r.N_front) + std::abs(r.N_rear)), 1e-9);
    }
  }
  EXPECT_GT(compared, 200);
}

// Residual of Loveikin, Pochka, Romasevych (2018) eq. (10) generalised (see CartStatics.h), written out independently.
void expectEquilibrium(const Scene& s, double beta, double H, double phi_f, double Fin,
                       const CartStaticsResult& r) {
  const CartGeometry& g = s.carts.geometry;
  const double f = s.loads.guide_friction;
  const double R1 = s.loads.roller_normal_front, R2 = s.loads.roller_normal_rear;
  const double G = s.cartMassWithRodShare() * s.loads.gravity;
  const double V = s.rods.model == RodModel::Distributed ? s.rods.mass * s.loads.gravity / 2 : 0.0;
  const double N1 = r.N_front, N2 = r.N_rear, F = r.F_rod;
  const double fr = phi_f * f * (std::abs(N1) + std::abs(N2));
  const double X = -F * std::cos(beta) + fr + H + Fin;
  const double Y = F * std::sin(beta) - N1 - N2 - G - V + R1 + R2;
  const double M = -N1 * (g.p - g.b) - N2 * (g.p + g.b) - G * g.p - fr * g.d / 2 + H * g.e +
                   R1 * (g.p - g.a) + R2 * (g.p + g.a) - g.com_height * Fin;
  const double scale = std::abs(H) + std::abs(Fin) + R1 + R2 + G + std::abs(F);
  EXPECT_LT(std::abs(X) / scale, 1e-13);
  EXPECT_LT(std::abs(Y) / scale, 1e-13);
  EXPECT_LT(std::abs(M) / scale, 1e-13);
  EXPECT_NEAR(r.friction, fr, 1e-12 * scale);
}

// Random rod angle, rod force, friction (up to 0.1), inertia force, centre-of-mass height and
// front and rear roller forces: the solution satisfies every equation of the balance.
TEST(CartStatics, EquilibriumResidualVanishesForRandomInputsWithDepth) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (RodModel model : {RodModel::Split, RodModel::Distributed, RodModel::Massless}) {
    Scene s = test::loveikin2018LikeScene();
    s.rods.model = model;
    ASSERT_NE(s.carts.geometry.e, 0.0);
    for (int i = 0; i < 500; ++i) {
      s.loads.guide_friction = 0.1 * (0.5 + 0.5 * U(rng));  // up to 0.1: stress the sign logic
      s.carts.geometry.com_height = 0.5 * U(rng);
      // Front and rear compacting rollers pressing with different forces, so that each one's
      // lever arm (p - a front, p + a rear) shows in the moment balance.
      s.loads.roller_normal_front = 20000 * (0.5 + 0.5 * U(rng));
      s.loads.roller_normal_rear = 20000 * (0.5 + 0.5 * U(rng));
      const double beta = 0.25 * U(rng);
      const double H = 30000 * U(rng);
      const double phi_f = U(rng);
      const double Fin = 30000 * U(rng);
      const CartStaticsResult r = solveCartStatics(s, beta, H, phi_f, Fin);
      expectEquilibrium(s, beta, H, phi_f, Fin, r);
    }
  }
}

TEST(CartStatics, DepthTermShiftsRearReactionByHeOver2b) {
  // Keeping eq. (10)'s (F01 + F02)·e moment (dropped by eq. (18)) with friction off moves H·e/(2b)
  // from the front to the rear guide.
  Scene s = test::loveikin2018LikeScene();
  s.loads.guide_friction = 0.0;
  const double H = 15924, beta = 0.1;
  const CartStaticsResult with_e = solveCartStatics(s, beta, H, 1.0);
  s.carts.geometry.e = 0.0;
  const CartStaticsResult no_e = solveCartStatics(s, beta, H, 1.0);
  const double shift = H * 0.21 / (2 * 0.37);
  EXPECT_NEAR(with_e.N_rear - no_e.N_rear, shift, 1e-9 * shift);
  EXPECT_NEAR(with_e.N_front - no_e.N_front, -shift, 1e-9 * shift);
  EXPECT_NEAR(with_e.F_rod, no_e.F_rod, 1e-9 * no_e.F_rod);
}

TEST(CartStatics, FrictionOpposesTheGivenDirectionEvenWhenAReactionIsNegative) {
  Scene s = test::loveikin2018LikeScene();
  // Large outward roller force at depth e lifts the front guide roller: N_front < 0.
  const CartStaticsResult r = solveCartStatics(s, 0.0, 60000, -1.0);
  EXPECT_LT(r.N_front, 0.0);
  EXPECT_LT(r.friction, 0.0);  // φ_f = -1: friction along -x' with magnitude f·(|N1| + |N2|)
  EXPECT_NEAR(r.friction, -0.008 * (std::abs(r.N_front) + std::abs(r.N_rear)), 1e-9);
}

TEST(CartStatics, WithoutGuideBaseOnlyTheSumOfReactionsIsDetermined) {
  // b = 0 is a valid scene when there is no guide friction (geometry not given, Loveikin and Pochka (2007)).
  Scene s = test::loveikin2018LikeScene();
  s.carts.geometry.b = 0.0;
  for (double f : {0.0, 0.008}) {
    s.loads.guide_friction = f;
    const double beta = 0.2, H = -7000.0;
    const CartStaticsResult r = solveCartStatics(s, beta, H, 1.0);
    ASSERT_TRUE(std::isfinite(r.F_rod) && std::isfinite(r.N_front) && std::isfinite(r.N_rear));
    const double S = r.N_front + r.N_rear, G = s.cartMassWithRodShare() * 9.81;
    EXPECT_NEAR(-r.F_rod * std::cos(beta) + r.friction + H, 0.0, 1e-9);
    EXPECT_NEAR(r.F_rod * std::sin(beta) - S - G + 2 * 9740, 0.0, 1e-9);
    EXPECT_NEAR(r.friction, f * std::abs(S), 1e-9);
    EXPECT_EQ(r.N_front, r.N_rear);
  }
}

}  // namespace
}  // namespace rollerdyn

namespace rollerdyn {
TEST(CartStatics, EachCartUsesItsOwnMassAndLoads) {
  // Cart j of a scene with per-cart values must see exactly what a uniform scene with cart j's
  // values gives every cart.
  Scene lists = test::loveikin2018LikeScene();
  lists.carts.masses = {1000, 400, 1000, 700};
  lists.carts.mass = std::nan("");
  const Loads& L = lists.loads;
  lists.cart_loads = {{L.roller_force_front, L.roller_force_rear, L.roller_normal_front, L.roller_normal_rear, 0.0},
                      {0, 0, 0, 0, 0},
                      {L.roller_force_front, 0.5 * L.roller_force_rear, 2000, 3000, 0.0},
                      {L.roller_force_front, L.roller_force_rear, L.roller_normal_front, L.roller_normal_rear, 0.0}};
  for (int j = 0; j < 4; ++j) {
    Scene one = test::loveikin2018LikeScene();
    one.carts.mass = lists.carts.masses[j];
    const CartLoads& c = lists.cart_loads[j];
    one.loads.roller_force_front = c.roller_force_front;
    one.loads.roller_force_rear = c.roller_force_rear;
    one.loads.roller_normal_front = c.roller_normal_front;
    one.loads.roller_normal_rear = c.roller_normal_rear;
    for (double beta : {-0.2, 0.0, 0.13}) {
      const double H = c.roller_force_front + c.roller_force_rear;
      const CartStaticsResult a = solveCartStatics(lists, j, beta, H, 1.0, 350.0);
      const CartStaticsResult b = solveCartStatics(one, beta, H, 1.0, 350.0);
      EXPECT_EQ(a.F_rod, b.F_rod) << "cart " << j + 1;
      EXPECT_EQ(a.N_front, b.N_front) << "cart " << j + 1;
      EXPECT_EQ(a.N_rear, b.N_rear) << "cart " << j + 1;
      EXPECT_EQ(a.friction, b.friction) << "cart " << j + 1;
    }
  }
  EXPECT_THROW(solveCartStatics(lists, 0.0, 0.0, 1.0), std::logic_error);  // which cart?
}
}  // namespace rollerdyn
