// Closed-form kinematics of one crank-slider of the installation, as a function of its crank
// angle θ = φ2 + j·Δφ (Loveikin, Pochka, Romasevych (2018) eq. (31), (40)-(47); truncated series eq. (52)-(57); Loveikin and Pochka (2007)
// eq. (6) and the rod terms of eq. (9)).
//
// Geometry (plane z = const, origin on the shaft axis, x along the guides, y up):
//   crank pin  A = r·(cos θ, sin θ)
//   cart hinge B = (x_B, 0),  x_B = r·cos θ + σ·l·cos β,  sin β = (r/l)·sin θ
// σ = +1 puts the cart on the +x side of the shaft (Loveikin, Pochka, Romasevych (2018), all carts), σ = -1 on the -x side
// (Loveikin and Pochka (2007), second cart). β is the rod angle of Loveikin, Pochka, Romasevych (2018) eq. (31): signed, |β| < π/2.
// The rod's absolute rotation rate is ω_rod = -σ·β̇ (direction B->A turns against β for σ = +1).
//
// Both the reduced model and the multibody model's initial assembly use this one function, so
// both models start from, and are compared on, the same geometry.
#pragma once

namespace rollerdyn {

struct SliderCrankPose {
  double x_B;        // cart hinge position along x [m]
  double dx_B;       // ∂x_B/∂θ [m/rad]                       (first transfer function)
  double d2x_B;      // ∂²x_B/∂θ² [m/rad²]                   (second transfer function)
  double beta;       // rod angle β [rad], sin β = (r/l)·sin θ
  double dbeta;      // ∂β/∂θ [-]
  double d2beta;     // ∂²β/∂θ² [1/rad]
  double x_S, y_S;   // rod centre of mass (mid-length) [m]
  double dx_S, dy_S;     // ∂(x_S, y_S)/∂θ [m/rad]
  double d2x_S, d2y_S;   // ∂²(x_S, y_S)/∂θ² [m/rad²]
};

// Exact kinematics. Preconditions (checked, std::invalid_argument): r > 0, l > r, σ = ±1.
SliderCrankPose sliderCrankExact(double theta, double r, double l, int side);

// The papers' truncated series for x_B (binomial series of cos β cut after the second term,
// eq. (52)-(57)); β and its derivatives stay exact because the papers do not truncate them.
SliderCrankPose sliderCrankTruncated(double theta, double r, double l, int side);

}  // namespace rollerdyn
