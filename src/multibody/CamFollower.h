// Cam drive with optimal reversal of Loveikin and Pochka in the multibody model: the cart's slider coordinate follows the cam
// angle of the crankshaft, x_B - σ·x(θ) = 0 with θ = φ2 + j·Δφ (physics/CamMotionLaw.h, Loveikin and Pochka (cam drive paper)
// eq. (32)-(34), (41)-(43)). Used as the Function of a Constraint::CoordinateCoupler, which takes
// the place of the rod: one holonomic equation between the crankshaft's and the cart's q. The
// law is C³ in θ, so the function and the first and second partial derivatives Simbody needs for
// the velocity and acceleration constraints are continuous.
#pragma once

#include "Simbody.h"
#include "physics/CamMotionLaw.h"

namespace rollerdyn {

class CamFollowerFunction : public SimTK::Function {
 public:
  // Arguments: x[0] = crankshaft angle φ2 [rad], x[1] = cart slider coordinate x_B [m].
  CamFollowerFunction(double stroke, int side, double phase)
      : stroke_(stroke), side_(side), phase_(phase) {}

  SimTK::Real calcValue(const SimTK::Vector& x) const override {
    return x[1] - side_ * camMotion(x[0] + phase_, stroke_).x;
  }
  SimTK::Real calcDerivative(const SimTK::Array_<int>& d, const SimTK::Vector& x) const override {
    // Only the crank angle enters non-linearly; ∂/∂x_B = 1, every other mixed derivative is 0.
    int n_crank = 0, n_cart = 0;
    for (int c : d) (c == 0 ? n_crank : n_cart) += 1;
    if (n_cart == 1 && n_crank == 0) return 1.0;
    if (n_cart > 0) return 0.0;
    const CamMotionSample c = camMotion(x[0] + phase_, stroke_);
    switch (n_crank) {
      case 1: return -side_ * c.dx;
      case 2: return -side_ * c.d2x;
      case 3: return -side_ * c.d3x;
      default: return 0.0;
    }
  }
  int getArgumentSize() const override { return 2; }
  int getMaxDerivativeOrder() const override { return 3; }

 private:
  double stroke_;
  int side_;
  double phase_;
};

}  // namespace rollerdyn
