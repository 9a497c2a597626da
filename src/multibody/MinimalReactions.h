// Every reaction column of the multibody model (reactions.csv, io/OutputColumns.h: same
// frames, signs and order as MultibodyModel::observeReactions) from the minimal formulation's
// O(n) inverse-dynamics pass, without Simbody's constrained solve:
//   - guide normal forces: the cart's free body (MinimalDynamics::guideNormals);
//   - rod force F_rod: the loop force on the cart at B (MinimalDynamics::loopForce: its x
//     component is the cart's generalized constraint force, its y component the rod's moment
//     balance about the crank pin) along B -> A; a cam's force is horizontal;
//   - friction: the friction the model applied;
//   - crank pin: the rod's free body, -F_loop - m_rod·a_S + m_rod·g (distributed rods; the rod's
//     centre-of-mass acceleration a_S from Simbody's O(n) body accelerations at the known u̇);
//     -F_loop for split and massless rods (a massless link); the cam's pusher force on the cam;
//   - main bearing: the crankshaft subtree's free body (crankshaft, motor side, distributed rods),
//     Σ (m_b·a_b - applied force on b) minus the loop forces the carts put on it;
//   - coupling torque: MultibodyModel::couplingTorque with the projected u̇.
// Each is linear in the accelerations and forces the projected equations already gave, so a
// row costs O(n). Simbody's constrained solve stays as the reference: the minimal formulation
// compares the two every simulation.self_check_interval rows (RunStats::reaction_self_check).
#pragma once

#include <vector>

#include "Simbody.h"
#include "multibody/MinimalDynamics.h"
#include "multibody/MultibodyModel.h"

namespace rollerdyn {

class MinimalReactions {
 public:
  MinimalReactions(const MultibodyModel& model, const SimTK::State& state);
  // The reactions row of the state `s` that `dyn` has just evaluated (realized to Velocity).
  void row(const SimTK::State& s, const MinimalDynamics& dyn, std::vector<double>& out);

 private:
  // Σ m·a - applied force [N] of body b, one term of the crankshaft subtree's free body.
  SimTK::Vec3 netForce(const SimTK::State& s, const MinimalDynamics& dyn, const SimTK::MobilizedBody& b) const;
  // Cart j's columns (guide normals, friction, rod or cam force, crank pin) into `re`, and what
  // its rod and loop add to the main bearing's force `bearing` [N] (nothing for a cam).
  void cartColumns(const SimTK::State& s, const MinimalDynamics& dyn, const SimTK::Vector& normals, int j,
                   SimTK::Vec3& bearing, std::vector<double>& re) const;

  const MultibodyModel& model_;
  SimTK::Vector_<SimTK::SpatialVec> body_accelerations_;  // A_GB at the evaluated u̇
};

}  // namespace rollerdyn
