// Which orders of the crank speed excite the drive: the harmonics k·ω of the crank-side reduced
// inertia J_n2(φ2) (parametric excitation) and of the load torque (forced excitation).
//
// From the layout: every cart contributes the same function of its own crank angle θ_j, so a
// harmonic of order k of the whole machine carries the factor Σ_j exp(i·k·θ_j) with the carts'
// effective phases θ_j = j·Δφ, plus π for a cart on the opposite side (its slider-crank is the
// same-side one turned by half a revolution and mirrored: x_B,opposite(θ) = -x_B,same(θ + π), so
// its inertia x_B'² and its load torque are the same-side ones at θ + π). Order k survives when
// that sum is not zero. N equal carts at equal offsets 2π/N on one side: only k·N; unequal
// offsets (crank.angles_deg, crank.angle_error_deg): every order. Carts of different masses or
// loads (carts.mass or loads.* as lists) are not the same function of their crank angle: every
// order survives whatever the phases. The rods' own weight (distributed rods with gravity) does not follow the
// mirror rule (their centre of mass rises and falls the same way on either side) and adds order 1
// per cart with the phases j·Δφ.
//
// Measured: the Fourier series of J_n2(φ2) and of the load torque over one revolution of the
// reduced model (Eigen's FFT, 256 samples), orders whose amplitude exceeds 1e-9 of the largest.
//
// The orders that drive the coupling mode (`forced`): the harmonics of the torque the crank side
// puts against the coupling at a steady crank speed ω, the load torque plus the inertia's own
// torque,
//   Q(φ2) = M_load(φ2, ω) + ½·J_n2'(φ2)·ω²      (the crank equation of ReducedModel.h at φ̈2 = 0),
// whose harmonic k has the amplitude |M_k + ½·i·k·J_k·ω²| (M_k, J_k the complex harmonics). An
// order is kept when that amplitude is at least kForcedOrderShare = 1 % of the largest harmonic:
// the layout decides through the phase sums above (six equal carts at 60°: 6, 12, 18, 24), and
// carts of unequal masses or loads, or crank angles of their own, bring the other orders in with
// the size the difference gives them.
#pragma once

#include <vector>

#include "scene/Scene.h"

namespace rollerdyn {
class ReducedModel;
}  // namespace rollerdyn

namespace rollerdyn::modes {

struct OrderContent {
  int order = 0;
  double layout_factor = 0;     // |Σ_j exp(i·k·θ_j)| / n (1: all carts in phase, 0: cancelled)
  double inertia_amplitude = 0; // amplitude of J_n2's harmonic k [kg·m²]
  double load_amplitude = 0;    // amplitude of the load torque's harmonic k [N·m] at the speed given
  double exciting_torque = 0;   // amplitude of Q's harmonic k (load + ½·J_n2'·ω², see above) [N·m]
};

// The share of the largest harmonic of Q an order needs to count as exciting the coupling mode.
inline constexpr double kForcedOrderShare = 0.01;

struct ExcitationOrders {
  std::vector<int> layout;          // orders 1..max_order that survive the layout's phase sums
                                    // (all of them when the carts' masses or loads differ)
  std::vector<int> inertia;         // orders present in J_n2(φ2) (measured)
  std::vector<int> load;            // orders present in the load torque (measured)
  std::vector<int> all;             // union of inertia and load: the orders the Campbell diagram draws
  std::vector<int> forced;          // orders whose exciting torque is >= kForcedOrderShare of the largest
  double exciting_largest = 0;      // the largest harmonic of Q [N·m]
  double omega = 0;                 // the crank speed Q is taken at [rad/s]
  std::vector<OrderContent> table;  // orders 1..max_order
  double inertia_mean = 0;          // J_n2's mean [kg·m²]
  double inertia_relative_swing = 0;  // (max - min)/mean of J_n2 over a revolution [-]
};

// Orders up to max_order; the load torque at crank speed `omega` [rad/s].
ExcitationOrders excitationOrders(const ReducedModel& model, double omega, int max_order = 24);

// The layout's phase factor for order k (see above) [-].
double layoutFactor(const Scene& scene, int k);

// The orders that drive the crankshaft's own torsional modes (a torsional chain, ChainModes.h):
// each throw carries its own cart's torque Q_j(θ_j) = M_j(θ_j, ω) + ½·J_j'(θ_j)·ω² (the cart's
// loads and its share of J_n2), and no phase sum cancels its harmonics: the layout cancels them
// only where the throws' torques add up, at the coupling. Element k-1: the largest over the carts
// of |Q_j,k| / max_k' |Q_j,k'|, for orders k = 1..max_order [-]. The rods' own weight is left out
// (it adds order 1, far below a shaft's modes).
std::vector<double> throwOrderShares(const ReducedModel& model, double omega, int max_order);

}  // namespace rollerdyn::modes
