// The algebraic loop of the guide friction, solved directly: ONE law for both models (the
// multibody model's minimal formulation with loads.guide_friction.normal_force = algebraic, the
// reduced model with reduced.guide_normals = kinetostatic).
//
// The guide friction on cart j is F_j = c_j·(|N_front,j| + |N_rear,j|) along world x, with
// c_j = σ_j·f·φ_f(v'_j) (f: friction coefficient, φ_f = -tanh(v'/v_s): physics/RollerLoads.h).
// Its normal forces are guide reactions, which depend on the friction through two paths, both
// linear once the crank acceleration ε is named:
//   - the cart's own free body at a given ε: the friction changes the rod force and its moment
//     about the hinge (Loveikin, Pochka, Romasevych (2018) eq. (10) with the d'Alembert force of
//     the cart and the rod's inertial load at its hinge),
//   - the crank equation: the friction's generalized force x_B'·F_j changes ε, hence every cart's
//     inertial force.
// So, per cart, N_j = n0_j + n_eps_j·ε + n_F_j·F_j (front, rear), and ε = ε0 + Σ_j w_j·F_j. For a
// fixed sign pattern s of the normal forces the friction is linear, F_j = c_j·s_j·N_j, so
//   F_j = α_j + β_j·ε,  α_j = c_j·s_j·n0_j / D_j,  β_j = c_j·s_j·n_eps_j / D_j,  D_j = 1 - c_j·s_j·n_F_j
//   ε = (ε0 + Σ w_j·α_j) / E,  E = 1 - Σ w_j·β_j
// (the "equation in ε", piecewise linear in the signs): one solve per sign pattern. The signs are
// then checked against the solution and the wrong ones flipped; with the small f of guide rollers
// the first pattern (the signs of the normal forces without friction) is wrong only where a normal
// force crosses zero, and a flip settles it in one more pass (test: at most 6 passes over 500
// random loops with f up to 0.1).
//
// When the loop has no unique solution. The map F -> c·|N(F)| is a contraction when
// |c_j|·(|n_F_j| + |n_eps_j|·Σ|w|) < 1, i.e. for f well below the self-locking limit
// (Scene-level margin: physics/SelfLocking.h); then the solution exists, is unique and continuous
// in the state. D_j <= 0 means the cart's own friction grows at least as fast as the rod force
// that causes it: the cart locks in its guides (self-locking); E <= 0 means friction makes the
// machine's effective inertia non-positive (Painlevé's paradox: the motion is undetermined).
// Both are reported (LoopStatus), never iterated: the caller ends the run with a clear status.
// A sign pattern that does not settle in kMaxSignPasses falls back to the fixed-point iteration
// F <- c·|N(F)|, at most kMaxFixedPointPasses, which converges wherever the map contracts;
// otherwise the loop reports NotSettled.
#pragma once

#include <string>
#include <vector>

namespace rollerdyn {

// One cart's share of the loop (see above). Units: N, N/(rad/s²), -, rad/s² per N.
struct GuideLoopCart {
  double n0[2] = {0, 0};     // normal forces (front, rear) at ε = 0 without friction [N]
  double n_eps[2] = {0, 0};  // ∂N/∂ε [N·s²/rad]
  double n_F[2] = {0, 0};    // ∂N/∂F_j, F_j this cart's friction along world x [-]
  double c = 0;              // friction per unit |N_front| + |N_rear| along world x: σ·f·φ_f [-]
  double w = 0;              // ∂ε/∂F_j: the crank acceleration per newton of this cart's friction
                             // [rad/s² per N] (0 where the crank speed is prescribed)
};

enum class LoopStatus {
  Solved,         // friction, normal forces and ε consistent
  SelfLocking,    // some D_j <= 0: the cart's friction feeds back on itself at gain >= 1
  Undetermined,   // E <= 0: friction makes the effective inertia non-positive
  NotSettled,     // neither the sign passes nor the fixed-point iteration converged
};

struct GuideLoopResult {
  LoopStatus status = LoopStatus::Solved;
  double eps = 0;               // ε [rad/s²]
  int cart = -1;                // the cart that locks (SelfLocking), 0-based; -1 otherwise
  int passes = 0;               // linear solves (sign passes + fixed-point iterations)
  double gain = 0;              // SelfLocking: c_j·s_j·n_F_j of that cart; Undetermined: Σ w_j·β_j
};

// Solves the loop for carts[0..n) and the crank acceleration without friction eps0. Writes the
// friction forces F_j [N] (world x) into friction[0..n) and the normal forces (front, rear) into
// normals[0..2n). Allocation-free; never throws. With every c_j = 0 it returns the friction-free
// values in one pass.
GuideLoopResult solveGuideFrictionLoop(const GuideLoopCart* carts, int n, double eps0, double* friction,
                                       double* normals);

// A sentence for a run's status: what failed, for which cart (1-based), with the gain.
std::string describeLoopFailure(const GuideLoopResult& r);

}  // namespace rollerdyn
