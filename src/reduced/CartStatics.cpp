#include "reduced/CartStatics.h"

#include <cmath>
#include <stdexcept>

#include <Eigen/Dense>

#include "scene/Scene.h"

namespace rollerdyn {

namespace {

// One cart's equilibrium: the right-hand side of Loveikin, Pochka, Romasevych (2018) eq. (10)
// (generalised, unknowns (F, N1, N2)), the rod angle's cosine and sine, and the friction's
// coefficient f and direction φ_f.
struct CartEquilibrium {
  const CartGeometry& g;
  double f, phi_f, cb, sb;
  Eigen::Vector3d rhs;
};

CartEquilibrium cartEquilibrium(const Scene& scene, int cart, double beta, double H, double phi_f, double Fin) {
  const CartGeometry& g = scene.carts.geometry;
  const Loads L = scene.cartLoads(cart);
  const double f = L.guide_friction;
  const double R1 = L.roller_normal_front, R2 = L.roller_normal_rear;
  const double G = scene.cartMassWithRodShare(cart) * L.gravity;  // Loveikin, Pochka, Romasevych (2018) eq. (3), G at x' = p
  // Distributed rod: half its weight reaches the cart at B (see header).
  const double V = (scene.rods.model == RodModel::Distributed) ? 0.5 * scene.rods.mass * L.gravity : 0.0;
  const double cb = std::cos(beta), sb = std::sin(beta);

  // Right-hand side of Loveikin, Pochka, Romasevych (2018) eq. (10) (generalised), unknowns (F, N1, N2).
  const Eigen::Vector3d rhs(-(H + Fin),                                   // ΣX
                            G + V - R1 - R2,                              // ΣY
                            G * g.p - H * g.e - R1 * (g.p - g.a) - R2 * (g.p + g.a) +
                                g.com_height * Fin);                      // ΣM about B
  return {g, f, phi_f, cb, sb, rhs};
}

// No guide-roller base (b = 0, which the scene allows when there is no guide friction):
// the two guide reactions act at one point, so only their sum S = N1 + N2 is determined
// (ΣX, ΣY); it is reported split equally and the moment equation is not imposed.
CartStaticsResult solveWithoutGuideBase(const CartEquilibrium& e) {
  const double phi_f = e.phi_f, f = e.f, cb = e.cb, sb = e.sb;
  double sS = 1.0;
  double F = 0.0, S = 0.0;
  for (int attempt = 0; attempt < 2; ++attempt) {
    const double k = phi_f * f * sS;
    Eigen::Matrix2d A2;
    A2 << -cb, k, sb, -1.0;
    const Eigen::Vector2d x2 = A2.partialPivLu().solve(e.rhs.head<2>());
    F = x2(0);
    S = x2(1);
    const double nS = (S < 0.0) ? -1.0 : 1.0;
    if (f == 0.0 || nS == sS) break;
    sS = nS;
  }
  return {F, 0.5 * S, 0.5 * S, phi_f * f * std::abs(S)};
}

// friction = φ_f·f·(s1·N1 + s2·N2) with s_i = sign(N_i): piecewise linear in N. Start from the
// paper's case N1, N2 > 0 (s = +1) and flip a sign when the solution contradicts it; with the
// small friction coefficients of guide rollers this settles in at most two re-solves.
// The solve runs for every cart in every right-hand-side evaluation, where Eigen's pivoting LU
// was over half of a cart's cost; Eigen's fixed-size 3x3 inverse (cofactors, no pivoting) is
// enough here because the matrix is far from singular: its determinant is
// -cos β·(2b - (k1 - k2)·d/2) + O(f), with cos β ≥ √(1 - (r/l)²) > 0 and f·d < 2b for any
// real guide. computeInverseWithCheck still guards a degenerate input with the LU.
// Returns (F, N1, N2).
Eigen::Vector3d solveForSignPattern(const CartEquilibrium& e) {
  const CartGeometry& g = e.g;
  const double phi_f = e.phi_f, f = e.f, cb = e.cb, sb = e.sb;
  double s1 = 1.0, s2 = 1.0;
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  for (int attempt = 0; attempt < 4; ++attempt) {
    const double k1 = phi_f * f * s1, k2 = phi_f * f * s2;  // friction per unit N_i
    Eigen::Matrix3d A;
    A << -cb, k1, k2,                                            // ΣX
        sb, -1.0, -1.0,                                          // ΣY
        0.0, -(g.p - g.b) - k1 * 0.5 * g.d, -(g.p + g.b) - k2 * 0.5 * g.d;  // ΣM
    Eigen::Matrix3d A_inv;
    bool invertible = false;
    A.computeInverseWithCheck(A_inv, invertible);
    x = invertible ? Eigen::Vector3d(A_inv * e.rhs) : Eigen::Vector3d(A.partialPivLu().solve(e.rhs));
    const double n1 = (x(1) < 0.0) ? -1.0 : 1.0, n2 = (x(2) < 0.0) ? -1.0 : 1.0;
    if (f == 0.0 || (n1 == s1 && n2 == s2)) break;
    s1 = n1;
    s2 = n2;
  }
  return x;
}

// Self-locking (physics/SelfLocking.h): for the sign pattern of the solution, the determinant
// -cos β·(2b + (k2 - k1)·d/2) + sin β·((k1 - k2)·p + (k1 + k2)·b) has left the sign of its
// friction-free value -2b·cos β (< 0).
void judgeSelfLocking(const CartEquilibrium& e, CartStaticsResult& res) {
  const CartGeometry& g = e.g;
  const double phi_f = e.phi_f, f = e.f, cb = e.cb, sb = e.sb;
  const double k1 = phi_f * f * ((res.N_front < 0.0) ? -1.0 : 1.0), k2 = phi_f * f * ((res.N_rear < 0.0) ? -1.0 : 1.0);
  const double det = -cb * (2.0 * g.b + (k2 - k1) * 0.5 * g.d) + sb * ((k1 - k2) * g.p + (k1 + k2) * g.b);
  res.gain = 1.0 - det / (-2.0 * g.b * cb);
  res.locked = f > 0.0 && !(det < 0.0);
}

}  // namespace

CartStaticsResult solveCartStatics(const Scene& scene, double beta, double H, double phi_f,
                                   double Fin) {
  if (!scene.cartsIdentical())
    throw std::logic_error("solveCartStatics: the carts' masses or loads differ; say which cart");
  return solveCartStatics(scene, 0, beta, H, phi_f, Fin);
}

CartStaticsResult solveCartStatics(const Scene& scene, int cart, double beta, double H, double phi_f,
                                   double Fin) {
  const CartEquilibrium e = cartEquilibrium(scene, cart, beta, H, phi_f, Fin);
  if (!(e.g.b > 0.0)) return solveWithoutGuideBase(e);
  const Eigen::Vector3d x = solveForSignPattern(e);
  CartStaticsResult res;
  res.F_rod = x(0);
  res.N_front = x(1);
  res.N_rear = x(2);
  res.friction = e.phi_f * e.f * (std::abs(x(1)) + std::abs(x(2)));
  judgeSelfLocking(e, res);
  return res;
}

CartStaticsResult cartStaticsWithFriction(const Scene& scene, int cart, double beta, double H, double fr,
                                          double Fin, double V) {
  const CartGeometry& g = scene.carts.geometry;
  const Loads L = scene.cartLoads(cart);
  const double R1 = L.roller_normal_front, R2 = L.roller_normal_rear;
  const double G = scene.cartMassWithRodShare(cart) * L.gravity;
  CartStaticsResult res;
  // ΣX: -F·cos β + friction + H + Fin = 0
  res.F_rod = (fr + H + Fin) / std::cos(beta);
  // ΣY: F·sin β - N1 - N2 - G - V + R1 + R2 = 0  ->  S = N1 + N2
  const double S = res.F_rod * std::sin(beta) - G - V + R1 + R2;
  // ΣM about B: N1·(p - b) + N2·(p + b) = Mn
  const double Mn = -G * g.p - fr * 0.5 * g.d + H * g.e + R1 * (g.p - g.a) + R2 * (g.p + g.a) -
                    g.com_height * Fin;
  if (g.b > 0.0) {
    res.N_front = (S * (g.p + g.b) - Mn) / (2.0 * g.b);
    res.N_rear = (Mn - S * (g.p - g.b)) / (2.0 * g.b);
  } else {
    res.N_front = res.N_rear = 0.5 * S;  // no guide base: only the sum is determined
  }
  res.friction = fr;
  return res;
}

}  // namespace rollerdyn
