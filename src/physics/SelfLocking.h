// How close a crank-slider cart comes to locking in its guides (self-locking) and to the dead
// centre of its rod, from the cart statics of Loveikin, Pochka, Romasevych (2018) eq. (10)
// (reduced/CartStatics.h) and the largest rod angle β_max = asin(r/l) (eq. (31)).
//
// Self-locking. With the guide friction written as k_i·N_i (k_i = ±f by the signs of the
// cart's velocity and of N_i), the cart's equilibrium in (F_rod, N_front, N_rear) has the
// determinant
//     det = -cos β·(2b + (k2 - k1)·d/2) + sin β·((k1 - k2)·p + (k1 + k2)·b),
// det_0 = -2b·cos β without friction. Every force of the solution scales with 1/det, so the
// friction's feedback gain is g = 1 - det/det_0 (the loop amplifies the friction by 1/(1 - g));
// at g = 1 the determinant vanishes: any rod force is eaten by the friction it causes. Per sign
// pattern, with β signed:
//   - both normal forces of the same sign (k1 = k2 = k):       g = k·tan β;
//   - opposite signs (k1 = -k2 = k; the rod's vertical force tips the cart about its guide
//     rollers):                                                g = k·(p·tan β + d/2)/b.
// The largest over the patterns and both signs of β, at the largest rod angle, is the
// self-locking index
//     κ = f·max(tan β_max, (|p|·tan β_max + d/2)/b)
// (≈ f·(p/b)·tan β_max for the papers' carts, p > b, d ≪ p·tan β_max): κ >= 1 locks the cart at
// the rod angles where g >= 1; below, the friction is amplified by up to 1/(1 - κ) over its
// open-loop value f·(|N_front| + |N_rear|) at a fixed rod force. The cart's and rod's inertial
// forces do not change g (they enter the right-hand side, physics/GuideFrictionLoop.h), so κ is
// the same for the quasi-static and the kinetostatic normal forces.
//
// Dead centre. The rod pushes the cart along the guide with cos β of its force, so the rod force
// reaches 1/cos β_max times the cart's horizontal load, and the transmission angle (between rod
// and guide normal) falls to μ_min = 90° - β_max. At r/l -> 1 the rod stands perpendicular to the
// guide at θ = 90° and the mechanism can jam or fold over; a manufacturing error of l - r then
// decides whether it passes at all.
#pragma once

namespace rollerdyn {

struct Scene;

struct LockingMargins {
  bool applicable = false;        // crank drive (a cam pushes along the guide: β = 0)
  double beta_max = 0;            // largest rod angle asin(r/l) [rad]
  double transmission_angle_min = 0;  // μ_min = π/2 - β_max [rad]
  double rod_force_factor = 1;    // 1/cos β_max [-]
  double self_locking_index = 0;  // κ (above) [-]; 0 without guide friction
  double friction_amplification = 1;  // 1/(1 - κ) while κ < 1, infinity from 1 [-]
};

LockingMargins lockingMargins(const Scene& scene);

}  // namespace rollerdyn
