#include "multibody/MinimalCoordinates.h"

#include <cmath>

#include "physics/CamMotionLaw.h"
#include "physics/SliderCrank.h"

namespace rollerdyn {

MinimalCoordinates::MinimalCoordinates(const MultibodyModel& model, const SimTK::State& s)
    : model_(model) {
  const Scene& sc = model.scene();
  crank_free_ = !model.options().prescribe_crank_speed;
  prescribed_speed_ = model.options().crank_speed;
  twist_free_ = model.elastic();
  cam_ = sc.hasCamDrive();
  q_crank_ = model.crank().getFirstQIndex(s);
  u_crank_ = model.crank().getFirstUIndex(s);
  if (twist_free_) {
    q_twist_ = model.motorSide().getFirstQIndex(s);
    u_twist_ = model.motorSide().getFirstUIndex(s);
  }
  for (size_t j = 0; j < model.carts().size(); ++j)
    loops_.push_back(loopOf(model.carts()[j], s, sc.crankPhase(int(j))));
  const int nu = s.getNU();
  if (crank_free_) columns_.emplace_back(nu, 0.0);
  if (twist_free_) {
    columns_.emplace_back(nu, 0.0);
    columns_.back()[u_twist_] = 1.0;  // the motor side turns relative to the crankshaft
  }
  bias_.resize(nu);
  bias_ = 0.0;
}

MinimalCoordinates::Loop MinimalCoordinates::loopOf(const CartRig& c, const SimTK::State& s, double phase) {
  Loop l;
  l.q_cart = c.cart.getFirstQIndex(s);
  l.u_cart = c.cart.getFirstUIndex(s);
  l.has_rod = !c.rod.isEmptyHandle();
  if (l.has_rod) {
    l.q_rod = c.rod.getFirstQIndex(s);
    l.u_rod = c.rod.getFirstUIndex(s);
  }
  l.side = c.side;
  l.phase = phase;
  return l;
}

// inline: apply's per-cart step in every evaluation of the right-hand side.
inline void MinimalCoordinates::placeLoop(const Loop& l, double phi, double w, SimTK::Vector& q, SimTK::Vector& u,
                                   SimTK::Vector* crank_column) {
  const Scene& sc = model_.scene();
  const double theta = phi + l.phase;
  const SliderCrankPose p = cam_ ? camDrivePose(theta, sc.cam.stroke, l.side)
                                 : sliderCrankExact(theta, sc.crank.radius, sc.rods.length, l.side);
  q[l.q_cart] = p.x_B;
  u[l.u_cart] = p.dx_B * w;
  bias_[l.u_cart] = p.d2x_B * w * w;
  if (crank_column) (*crank_column)[l.u_cart] = p.dx_B;
  if (!l.has_rod) return;
  // Direction A->B = l·(σ·cos β, -sin β): absolute rod angle ψ, rate ψ̇ = -σ·β̇; the rod's
  // pin is on the crankshaft, so its own coordinate is ψ - φ2.
  const double psi = std::atan2(-std::sin(p.beta), l.side * std::cos(p.beta));
  const double rate_per_crank = -l.side * p.dbeta - 1.0;
  q[l.q_rod] = psi - phi;
  u[l.u_rod] = rate_per_crank * w;
  bias_[l.u_rod] = -l.side * p.d2beta * w * w;
  if (crank_column) (*crank_column)[l.u_rod] = rate_per_crank;
}

void MinimalCoordinates::apply(double t, const IndependentState& x, SimTK::State& s) {
  const double phi = x.crank_angle, w = crank_free_ ? x.crank_speed : prescribed_speed_;
  s.updTime() = t;
  SimTK::Vector& q = s.updQ();
  SimTK::Vector& u = s.updU();
  q[q_crank_] = phi;
  u[u_crank_] = w;
  if (twist_free_) {
    q[q_twist_] = x.twist;
    u[u_twist_] = x.twist_rate;
  }
  SimTK::Vector* crank_column = crank_free_ ? &columns_[0] : nullptr;
  if (crank_column) (*crank_column)[u_crank_] = 1.0;  // the motor side rides on the crankshaft
  for (const Loop& l : loops_) placeLoop(l, phi, w, q, u, crank_column);
}

IndependentState MinimalCoordinates::extract(const SimTK::State& s) const {
  IndependentState x;
  x.crank_angle = s.getQ()[q_crank_];
  x.crank_speed = s.getU()[u_crank_];
  if (twist_free_) {
    x.twist = s.getQ()[q_twist_];
    x.twist_rate = s.getU()[u_twist_];
  }
  return x;
}

}  // namespace rollerdyn
