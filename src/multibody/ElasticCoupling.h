// Elastic, damped coupling between the motor-side body and the crankshaft, reduced to the crank
// axis (Loveikin, Pochka, Romasevych (2018) eq. (34), (58)): torque_coupling = c·(φ1 - φ2) + k·(φ̇1 - φ̇2), acting + on the
// crankshaft and - on the motor side. Only built for coupling.type = elastic; a rigid coupling is
// one body, never a stiff spring.
// The motor side is mobilized RELATIVE to the crankshaft, so its coordinate is the twist itself:
// as the difference of two absolute angles (each held by the integrator to ~accuracy rad) the
// twist of a 1e9 N·m/rad coupling carried torque errors of c·accuracy, 1 kN·m at 1e-6.
#pragma once

#include "Simbody.h"

namespace rollerdyn {

class ElasticCoupling : public SimTK::Force::Custom::Implementation {
 public:
  // motor_body: mobilized by a Pin on the crankshaft (its q = φ1 - φ2, its u = φ̇1 - φ̇2).
  ElasticCoupling(const SimTK::MobilizedBody& motor_body, double stiffness, double damping)
      : motor_(motor_body), stiffness_(stiffness), damping_(damping) {}

  double twist(const SimTK::State& s) const { return motor_.getOneQ(s, 0); }
  double twistRate(const SimTK::State& s) const { return motor_.getOneU(s, 0); }
  // Torque the coupling transmits to the crankshaft [N·m].
  double torque(const SimTK::State& s) const {
    return stiffness_ * twist(s) + damping_ * twistRate(s);
  }
  // Power lost in the damper [W] (≥ 0).
  double dampingPower(const SimTK::State& s) const {
    const double w = twistRate(s);
    return damping_ * w * w;
  }

  void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>&,
                 SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector& mobility_forces) const override {
    // A generalized force on the relative joint acts -τ on the motor side and +τ on the crank.
    motor_.applyOneMobilityForce(s, 0, -torque(s), mobility_forces);
  }
  SimTK::Real calcPotentialEnergy(const SimTK::State& s) const override {
    const double q = twist(s);
    return 0.5 * stiffness_ * q * q;
  }

 private:
  SimTK::MobilizedBody motor_;  // handle copy of the motor-side body in the matter subsystem
  double stiffness_, damping_;
};

}  // namespace rollerdyn
