// The kinetostatic cart statics (a given guide friction force, the reduced model's kinetostatic
// normals) against the cart's balance solved by hand with the moments taken about the REAR guide
// roller's contact point Q = (p + b, d/2) instead of the rod hinge B: there the rear reaction N2
// and the guide friction (acting at the guide-roller contact, d/2 above B: Loveikin, Pochka,
// Romasevych (2018) eq. (10), the −(N1 + N2)·f·d/2 term) have no moment, and the guide roller's
// radius d/2 enters through the other forces' arms. A friction moment arm d instead of d/2 moves
// the guide reactions by friction·d/(4b).
#include <gtest/gtest.h>

#include <cmath>

#include "reduced/CartStatics.h"
#include "scene/Scene.h"

namespace rollerdyn {
namespace test {
Scene loveikin2018LikeScene();
}

namespace {

struct HandStatics {
  double F, N1, N2;
};

// Forces on the cart in its local frame (origin B, x' away from the shaft, y up), CartStatics.h:
// rod F·(−cos β, sin β) and rod load (0, −V) at B; roller forces (H, 0), (0, R1), (0, R2) at
// depth e, R1 at x' = p − a, R2 at p + a; weight (0, −G) at p; guides (0, −N1) at p − b,
// (0, −N2) at p + b; friction (fr, 0) at height d/2; inertia (Fin, 0) at height h.
HandStatics handSolve(double a, double b, double p, double e, double d, double h, double G, double R1, double R2,
                      double beta, double H, double fr, double Fin, double V) {
  HandStatics s;
  s.F = (fr + H + Fin) / std::cos(beta);  // ΣX
  const double qx = p + b, qy = d / 2;    // rear guide roller's contact point
  // Moment about Q of a force (fx, fy) at (x, y): (x − qx)·fy − (y − qy)·fx; ΣM_Q = 0 with N2 and
  // the friction through Q, N1's arm (p − b) − qx = −2b: −2b·(−N1) = 2b·N1.
  const double others = (0 - qx) * (s.F * std::sin(beta)) - (0 - qy) * (-s.F * std::cos(beta))  // rod
                        + (0 - qx) * (-V)                                                     // rod load
                        - (-e - qy) * H                                                       // rollers, x
                        + (p - a - qx) * R1 + (p + a - qx) * R2                               // rollers, y
                        + (p - qx) * (-G)                                                     // weight
                        - (h - qy) * Fin;                                                     // inertia
  s.N1 = -others / (2 * b);
  s.N2 = s.F * std::sin(beta) - G - V + R1 + R2 - s.N1;  // ΣY
  return s;
}

TEST(CartStaticsFrictionArm, KinetostaticNormalsMatchTheBalanceAboutTheRearGuideContact) {
  Scene s = test::loveikin2018LikeScene();
  ASSERT_EQ(s.rods.model, RodModel::Split);
  ASSERT_EQ(s.carts.mass, 1000.0);
  ASSERT_EQ(s.rods.mass, 64.0);
  const double G = (1000.0 + 64.0 / 2) * 9.81;  // m_B = m'_B + m_rod/2, eq. (3)
  const double R1 = 9740, R2 = 9740;
  const double a = 0.27, b = 0.37, p = 0.52, e = 0.21, h = 0.3;
  // The paper's guide roller d = 0.046 m and a large one (0.3 m), where the arm matters more.
  for (double d : {0.046, 0.3}) {
    s.carts.geometry.d = d;
    for (double beta : {-0.2, 0.0, 0.15})
      for (double fr : {-2500.0, 0.0, 4000.0})       // given guide friction along x' [N]
        for (double Fin : {-3000.0, 0.0, 5000.0}) {  // d'Alembert force [N]
          const double H = 15924, V = 120;
          const CartStaticsResult r = cartStaticsWithFriction(s, 0, beta, H, fr, Fin, V);
          const HandStatics ref = handSolve(a, b, p, e, d, h, G, R1, R2, beta, H, fr, Fin, V);
          const double tol = 1e-9 * (G + R1 + R2 + std::abs(H));
          EXPECT_NEAR(r.F_rod, ref.F, tol) << "d " << d << " β " << beta << " friction " << fr;
          EXPECT_NEAR(r.N_front, ref.N1, tol) << "d " << d << " β " << beta << " friction " << fr << " Fin " << Fin;
          EXPECT_NEAR(r.N_rear, ref.N2, tol) << "d " << d << " β " << beta << " friction " << fr << " Fin " << Fin;
          EXPECT_EQ(r.friction, fr);
        }
  }
  // Where d matters: the friction's moment about B, −fr·d/2, moves fr·d/(4b) from the rear to the
  // front guide; d = 0.3 m, fr = 4000 N: 810.8 N.
  s.carts.geometry.d = 0.3;
  const CartStaticsResult with_d = cartStaticsWithFriction(s, 0, 0.1, 15924, 4000, 0, 0);
  s.carts.geometry.d = 0.0;
  const CartStaticsResult no_d = cartStaticsWithFriction(s, 0, 0.1, 15924, 4000, 0, 0);
  const double shift = 4000 * 0.3 / (4 * 0.37);
  EXPECT_NEAR(with_d.N_front - no_d.N_front, shift, 1e-9 * shift);
  EXPECT_NEAR(with_d.N_rear - no_d.N_rear, -shift, 1e-9 * shift);
}

// The quasi-static statics (the friction f·(N1 + N2) follows from the normals, φ_f = +1): with
// k = f the balance ΣX, ΣY gives F = (k·(R1 + R2 − G) + H + Fin)/(cos β − k·sin β), Loveikin,
// Pochka, Romasevych (2018) eq. (14) with the inertia force added, the friction k·(N1 + N2) =
// F·cos β − H − Fin, and the normals from the moments about Q as above.
TEST(CartStaticsFrictionArm, QuasiStaticNormalsMatchTheBalanceAboutTheRearGuideContact) {
  Scene s = test::loveikin2018LikeScene();
  ASSERT_EQ(s.rods.model, RodModel::Split);  // no rod load V at B
  const double G = (1000.0 + 64.0 / 2) * 9.81;
  const double R1 = 9740, R2 = 9740;
  const double a = 0.27, b = 0.37, p = 0.52, e = 0.21, h = 0.3;
  int compared = 0;
  for (double d : {0.046, 0.3}) {
    s.carts.geometry.d = d;
    for (double f : {0.008, 0.1}) {
      s.loads.guide_friction = f;
      for (double beta : {-0.2, 0.0, 0.15})
        for (double H : {2000.0, 8000.0})
          for (double Fin : {-1500.0, 0.0, 1500.0}) {
            const double F = (f * (R1 + R2 - G) + H + Fin) / (std::cos(beta) - f * std::sin(beta));
            const double fr = F * std::cos(beta) - H - Fin;
            const HandStatics ref = handSolve(a, b, p, e, d, h, G, R1, R2, beta, H, fr, Fin, 0.0);
            ASSERT_NEAR(ref.F, F, 1e-9 * F);
            if (!(ref.N1 > 0 && ref.N2 > 0)) continue;  // eq. (14) holds while both guides press down
            ++compared;
            const CartStaticsResult r = solveCartStatics(s, beta, H, +1.0, Fin);
            const double tol = 1e-9 * (G + R1 + R2 + H);
            EXPECT_NEAR(r.F_rod, ref.F, tol) << "d " << d << " f " << f << " β " << beta << " H " << H;
            EXPECT_NEAR(r.N_front, ref.N1, tol) << "d " << d << " f " << f << " β " << beta << " H " << H << " Fin " << Fin;
            EXPECT_NEAR(r.N_rear, ref.N2, tol) << "d " << d << " f " << f << " β " << beta << " H " << H << " Fin " << Fin;
            EXPECT_NEAR(r.friction, fr, tol);
          }
    }
  }
  EXPECT_EQ(compared, 72);  // every case here has both guides pressing down
}

}  // namespace
}  // namespace rollerdyn
