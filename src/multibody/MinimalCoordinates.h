// The map from the independent coordinates of the multibody model to all of its coordinates:
// generalized coordinate partitioning with the loops solved in closed form.
//
// Independent coordinates ν (what the minimal formulation integrates): the crank angle φ2 and
// speed φ̇2 (unless the crank speed is prescribed, MultibodyOptions) and, with an elastic
// coupling, the twist φ1 - φ2 and its rate. Every other coordinate follows from them through
// one loop per cart, in closed form (physics/SliderCrank.h: Loveikin, Pochka, Romasevych (2018)
// eq. (31), (40)-(47); physics/CamMotionLaw.h: Loveikin and Pochka (cam drive paper) eq. (32)-(34),
// (41)-(43)), at the cart's crank angle θ = φ2 + j·Δφ:
//   cart   q = x_B(θ),   u = x_B'·φ̇2,            u̇ = x_B'·φ̈2 + x_B''·φ̇2²
//   rod    q = ψ(θ) - φ2 with ψ the absolute rod angle, u = -(σ·β' + 1)·φ̇2,
//          u̇ = -(σ·β' + 1)·φ̈2 - σ·β''·φ̇2²                                 [distributed rods]
// so u = N·ν̇_speeds and u̇ = N·ν̈ + Ṅ·ν̇ with N (columns: one per free speed) and the bias Ṅ·ν̇
// (the φ̇2² terms) known per cart in O(1). The columns of N span the null space of the velocity
// constraints, which is what makes Nᵀ·(constraint forces) = 0 in the projected equations
// (MinimalDynamics.h). The carts' positions are exact to round-off, so no projection is needed.
#pragma once

#include <vector>

#include "Simbody.h"
#include "multibody/MultibodyModel.h"

namespace rollerdyn {

// Values of the independent coordinates.
struct IndependentState {
  double crank_angle = 0;  // φ2 [rad]
  double crank_speed = 0;  // φ̇2 [rad/s] (the prescribed speed when it is prescribed)
  double twist = 0;        // φ1 - φ2 [rad] (0 for a rigid coupling)
  double twist_rate = 0;   // φ̇1 - φ̇2 [rad/s]
};

class MinimalCoordinates {
 public:
  // `state` realized to Model stage (its q, u layout is used).
  MinimalCoordinates(const MultibodyModel& model, const SimTK::State& state);

  bool crankFree() const { return crank_free_; }   // crank speed integrated (not prescribed)
  bool twistFree() const { return twist_free_; }   // elastic coupling
  int freeSpeeds() const { return int(columns_.size()); }  // columns of N: 0, 1 or 2

  // Writes every q and u of `s` (and its time) from ν, and fills N and the bias Ṅ·ν̇.
  void apply(double t, const IndependentState& x, SimTK::State& s);
  // The independent coordinates of a state (the crank's and motor side's own q and u).
  IndependentState extract(const SimTK::State& s) const;

  const SimTK::Vector& column(int c) const { return columns_[c]; }  // N's column c, length nu
  const SimTK::Vector& bias() const { return bias_; }  // Ṅ·ν̇: u̇ when ν̈ = 0 [rad/s², m/s²]

 private:
  struct Loop {
    SimTK::QIndex q_cart;
    SimTK::UIndex u_cart;
    bool has_rod = false;
    SimTK::QIndex q_rod;
    SimTK::UIndex u_rod;
    int side = 1;
    double phase = 0;  // j·Δφ [rad]
  };
  // Cart c's loop: its coordinates' indices in s, side and crank phase [rad].
  static Loop loopOf(const CartRig& c, const SimTK::State& s, double phase);
  // One loop's q and u at crank angle φ2 and speed ω2, its entries of N's crank column (when the
  // crank is free) and of the bias.
  void placeLoop(const Loop& l, double phi, double w, SimTK::Vector& q, SimTK::Vector& u,
                 SimTK::Vector* crank_column);
  const MultibodyModel& model_;
  bool crank_free_ = true, twist_free_ = false, cam_ = false;
  double prescribed_speed_ = 0;
  SimTK::QIndex q_crank_, q_twist_;
  SimTK::UIndex u_crank_, u_twist_;
  std::vector<Loop> loops_;
  std::vector<SimTK::Vector> columns_;  // N, column 0 = crank speed (if free), then twist rate
  SimTK::Vector bias_;
};

}  // namespace rollerdyn
