// ReducedModel::cartPass(): the pass over the carts at one (φ2, φ̇2), kept for the evaluations
// that follow at the same crank angle and speed (ReducedModel.h).
#include <cstring>

#include "reduced/ReducedModel.h"

namespace rollerdyn {
namespace {

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// The pass's quasi-static lock: the first cart j that self-locks, with its loop gain.
void noteFirstLock(GuideLoopResult& locked, int j, double gain) {
  if (locked.status != LoopStatus::Solved) return;
  locked.status = LoopStatus::SelfLocking;
  locked.cart = j;
  locked.gain = gain;
}

}  // namespace

const ReducedModel::CartPass& ReducedModel::cartPass(double phi, double w2) const {
  for (const CartPass& p : passes_)
    if (p.valid && sameBits(p.phi, phi) && sameBits(p.omega, w2)) return p;
  CartPass& pass = passes_[size_t(next_pass_)];
  next_pass_ = (next_pass_ + 1) % int(passes_.size());
  ++cart_passes_computed_;
  pass.valid = false;
  pass.phi = phi;
  pass.omega = w2;
  pass.locked = GuideLoopResult{};
  pass.carts.clear();  // keeps its capacity
  sumOverCarts(pass, phi, w2);
  if (usesLoopTerms()) {
    pass.loop.resize(pass.carts.size());
    for (int j = 0; j < cartCount(); ++j) loopTerms(j, pass.carts[size_t(j)], w2, pass.loop[size_t(j)]);
  }
  pass.valid = true;
  return pass;
}

void ReducedModel::sumOverCarts(CartPass& pass, double phi, double w2) const {
  double J = J_crank_, dJ = 0.0, M = 0.0, P_friction = 0.0, P_load = 0.0;
  for (int j = 0; j < cartCount(); ++j) {
    const CartEvaluation c = kinetostatic_ ? cartKinematics(j, phi, w2) : evaluateCart(j, phi, w2, 0.0);
    const SliderCrankPose& p = c.pose;
    J += cartInertia(j, p);
    dJ += cartInertiaDerivative(j, p);
    const double sigma = scene_.carts.side[j];
    const double v = p.dx_B * w2;  // world ẋ_B
    if (kinetostatic_) {
      M += rodGravityTorque(p, c.theta) - sigma * c.roller_force * p.dx_B;
    } else {
      M += rodGravityTorque(p, c.theta) - c.generalized_force;
      P_friction -= sigma * c.statics.friction * v;
      if (c.statics.locked) noteFirstLock(pass.locked, j, c.statics.gain);
    }
    P_load -= sigma * c.roller_force * v;
    pass.carts.push_back(c);
  }
  pass.J = J;
  pass.dJ = dJ;
  pass.M = M;
  pass.P_friction = P_friction;
  pass.P_load = P_load;
}

}  // namespace rollerdyn
