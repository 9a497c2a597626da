// The springs of the crankshaft's torsional chain (physics/TorsionalChain.h): throw k+1 is
// mobilized by a Pin on throw k, so that joint's coordinate is the segment's twist
// q_k = θ_(k+1) - θ_k and the segment acts on it with the generalized force -c_k·q_k (+ on throw
// k+1's side, - on throw k's, as a relative joint does), and its Kelvin-Voigt damper with -d_k·q̇_k
// (crankshaft.torsional_damping; d_k = 0 leaves the chain undamped).
#pragma once

#include <vector>

#include "Simbody.h"

namespace rollerdyn {

class CrankshaftTorsion : public SimTK::Force::Custom::Implementation {
 public:
  // segments[k]: throw k+1's body, mobilized on throw k; stiffness[k] = c_k [N·m/rad], damping[k] =
  // d_k [N·m·s/rad].
  CrankshaftTorsion(std::vector<SimTK::MobilizedBody> segments, std::vector<double> stiffness,
                    std::vector<double> damping)
      : segments_(std::move(segments)), stiffness_(std::move(stiffness)), damping_(std::move(damping)) {}

  int segmentCount() const { return int(segments_.size()); }
  const SimTK::MobilizedBody& segmentBody(int k) const { return segments_[k]; }  // throw k+1's body
  double stiffness(int k) const { return stiffness_[k]; }                       // c_k [N·m/rad]
  // Twist of segment k, θ_(k+1) - θ_k [rad].
  double twist(const SimTK::State& s, int k) const { return segments_[k].getOneQ(s, 0); }
  // Torque segment k carries from the drive side on to the far side, c_k·(θ_k - θ_(k+1)) [N·m]:
  // positive while the drive side leads, like the coupling's torque.
  double torque(const SimTK::State& s, int k) const {
    return -stiffness_[k] * twist(s, k) - damping_[k] * segments_[k].getOneU(s, 0);
  }
  // Power the segments' dampers dissipate, Σ d_k·q̇_k² ≥ 0 [W] (the energy audit's damping).
  double dampingPower(const SimTK::State& s) const {
    double P = 0;
    for (int k = 0; k < segmentCount(); ++k) P += damping_[k] * segments_[k].getOneU(s, 0) * segments_[k].getOneU(s, 0);
    return P;
  }

  void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>&, SimTK::Vector_<SimTK::Vec3>&,
                 SimTK::Vector& mobility_forces) const override {
    for (int k = 0; k < segmentCount(); ++k) segments_[k].applyOneMobilityForce(s, 0, torque(s, k), mobility_forces);
  }
  SimTK::Real calcPotentialEnergy(const SimTK::State& s) const override {
    double V = 0;
    for (int k = 0; k < segmentCount(); ++k) V += 0.5 * stiffness_[k] * twist(s, k) * twist(s, k);
    return V;
  }

 private:
  std::vector<SimTK::MobilizedBody> segments_;
  std::vector<double> stiffness_;
  std::vector<double> damping_;
};

}  // namespace rollerdyn
