// Elastic, damped coupling between the motor-side body and the crankshaft, reduced to the crank
// axis (seed 000 eq. (34), (58)): torque_coupling = c·(φ1 - φ2) + k·(φ̇1 - φ̇2), acting + on the
// crankshaft and - on the motor side. Only built for coupling.type = elastic; a rigid coupling is
// one body, never a stiff spring.
#pragma once

#include "Simbody.h"

namespace rollerdyn {

class ElasticCoupling : public SimTK::Force::Custom::Implementation {
 public:
  ElasticCoupling(const SimTK::MobilizedBody& motor_body, const SimTK::MobilizedBody& crank_body,
                  double stiffness, double damping)
      : motor_(motor_body), crank_(crank_body), stiffness_(stiffness), damping_(damping) {}

  double twist(const SimTK::State& s) const { return motor_.getOneQ(s, 0) - crank_.getOneQ(s, 0); }
  double twistRate(const SimTK::State& s) const {
    return motor_.getOneU(s, 0) - crank_.getOneU(s, 0);
  }
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
    const double tau = torque(s);
    crank_.applyOneMobilityForce(s, 0, tau, mobility_forces);
    motor_.applyOneMobilityForce(s, 0, -tau, mobility_forces);
  }
  SimTK::Real calcPotentialEnergy(const SimTK::State& s) const override {
    const double q = twist(s);
    return 0.5 * stiffness_ * q * q;
  }

 private:
  SimTK::MobilizedBody motor_, crank_;  // handle copies of the bodies in the matter subsystem
  double stiffness_, damping_;
};

}  // namespace rollerdyn
