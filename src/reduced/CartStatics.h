// Quasi-static (or kinetostatic) equilibrium of ONE cart: rod force and guide reactions,
// Loveikin, Pochka, Romasevych (2018) eq. (10) generalised, solved as a 3x3 linear system (Eigen).
//
// Frame: the cart's LOCAL frame, origin at the rod hinge B, x' = σ·x pointing away from the
// shaft, y up. For a cart on the opposite side (σ = -1) the whole cart is mirrored, so in local
// coordinates Loveikin, Pochka, Romasevych (2018) eq. (10) holds unchanged with the same rod angle β (SliderCrank.h): the
// rod force on the cart is F·(-cos β, sin β) on both sides.
//
// Forces on the cart (Loveikin, Pochka, Romasevych (2018) fig. 3):
//   rod            F·(-cos β, +sin β) at B                      (F > 0 = tension, eq. (14))
//   rollers        H (local +x', both rollers together, from rollerHorizontalForce) at depth e
//                  below B; vertical R1 at x' = p - a, R2 at x' = p + a, both at depth e
//   weight         G = m_B·g at x' = p, m_B = Scene::cartMassWithRodShare() (Loveikin, Pochka, Romasevych (2018) eq. (3))
//   rod weight     distributed rods only: V = m_rod·g/2 downward at B. Quasi-statically a rod with
//                  its centre of mass at mid-length passes the rod-axis force F plus exactly half
//                  its weight to each end (moments about the crank pin), whatever its angle.
//                  Split rods carry that half in m_B already (eq. (3)); massless rods have none.
//   guides         N1 (front, x' = p - b), N2 (rear, x' = p + b), N > 0 when the guide presses
//                  the guide roller DOWN (force (0, -N) on the cart)
//   guide friction φ_f·f·(|N1| + |N2|) along x', acting at the guide-roller contact d/2 ABOVE B
//                  (so its moment about B is -(d/2)·friction, as the -(N1+N2)·f·d/2 term of
//                  eq. (10)). φ_f = frictionDirection(v') = -sign(v'); eq. (10) prints +f, i.e.
//                  φ_f = +1. |N| keeps the friction dissipative if a guide reaction changes sign
//                  (RollerLoads.h contract); while N1, N2 > 0 the system is exactly eq. (10).
//   inertia        optional d'Alembert force Fin = -m_B·a' along x' at height com_height
//                  (0 = quasi-static, as in the papers).
//
// Equations (moments about B, counter-clockwise positive in the local frame):
//   ΣX: -F·cos β + friction + H + Fin = 0
//   ΣY:  F·sin β - N1 - N2 - G - V + R1 + R2 = 0
//   ΣM: -N1·(p - b) - N2·(p + b) - G·p - friction·d/2 + H·e + R1·(p - a) + R2·(p + a)
//       - com_height·Fin = 0
// b = 0 (no guide base given; the scene allows it without guide friction): only N1 + N2 is
// determined (ΣX, ΣY); it is reported split equally and ΣM is not imposed.
// With φ_f = +1, e = 0, V = 0, Fin = 0 the solution is exactly Loveikin, Pochka, Romasevych (2018) eq. (14), (18), (22).
// NOTE: eq. (18) as printed drops the (F01 + F02)·e moment of eq. (10)'s third line; we keep it
// (it shifts N_rear by H·e/(2b), ≈ 4.5 kN for the Loveikin, Pochka, Romasevych (2018) numbers).
#pragma once

namespace rollerdyn {

struct Scene;

struct CartStaticsResult {
  double F_rod = 0;     // rod force [N], > 0 in tension (pulls the cart towards the shaft)
  double N_front = 0;   // N1, front guide reaction [N], > 0 when the guide presses down
  double N_rear = 0;    // N2, rear guide reaction [N]
  double friction = 0;  // guide friction force along the LOCAL x' axis [N]
  bool locked = false;  // the friction's feedback gain reached 1 for the sign pattern of the
                        // solution (physics/SelfLocking.h): the cart locks, the forces are void
  double gain = 0;      // that gain, 1 - det/det_0 (0 without friction) [-]
};

// Solves the cart equilibrium above for cart `cart` (0-based; its own m_B, R_j1, R_j2: Scene::
// cartMassWithRodShare(j), Scene::cartLoads(j)). beta: rod angle β [rad]; horizontal_roller_force:
// H along local +x' [N] (rollerHorizontalForce); friction_direction: φ_f in [-1, 1]
// (frictionDirection); inertial_force_x: Fin along local +x' [N]. Never throws for finite inputs.
CartStaticsResult solveCartStatics(const Scene& scene, int cart, double beta, double horizontal_roller_force,
                                   double friction_direction, double inertial_force_x = 0.0);
// The same for a scene whose carts all have the same mass and loads (std::logic_error otherwise).
CartStaticsResult solveCartStatics(const Scene& scene, double beta, double horizontal_roller_force,
                                   double friction_direction, double inertial_force_x = 0.0);

// The same equilibrium of cart `cart` (0-based) for a GIVEN guide friction force (local x') and a given vertical load V
// of the rod at B (downward on the cart; quasi-statically half the rod's weight for distributed
// rods, above; with the rod's inertia, ReducedModel's kinetostatic normals): no sign logic, the
// three equations solved in closed form. Linear in (friction, H, Fin, V) plus the constant loads:
// the kinetostatic friction loop (physics/GuideFrictionLoop.h) is built from it.
CartStaticsResult cartStaticsWithFriction(const Scene& scene, int cart, double beta, double horizontal_roller_force,
                                          double friction_local, double inertial_force_x, double rod_load_V);

}  // namespace rollerdyn
