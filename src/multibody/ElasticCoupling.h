// Elastic, damped coupling between the motor-side body and the crankshaft, reduced to the crank
// axis, with the reducer's backlash: the law of physics/CouplingLaw.h (without backlash
// Loveikin, Pochka, Romasevych (2018) eq. (34), (58): τ = c·(φ1 - φ2) + k·(φ̇1 - φ̇2)), acting + on
// the crankshaft and - on the motor side. Only built for coupling.type = elastic; a rigid
// coupling is one body, never a stiff spring.
// The motor side is mobilized RELATIVE to the crankshaft, so its coordinate is the twist itself:
// as the difference of two absolute angles (each held by the integrator to ~accuracy rad) the
// twist of a 1e9 N·m/rad coupling carried torque errors of c·accuracy, 1 kN·m at 1e-6.
#pragma once

#include "Simbody.h"
#include "physics/CouplingLaw.h"

namespace rollerdyn {

class ElasticCoupling : public SimTK::Force::Custom::Implementation {
 public:
  // motor_body: mobilized by a Pin on the crankshaft (its q = φ1 - φ2, its u = φ̇1 - φ̇2).
  ElasticCoupling(const SimTK::MobilizedBody& motor_body, const CouplingLaw& law)
      : motor_(motor_body), law_(law) {}
  // Without backlash: stiffness c [N·m/rad], damping k [N·m·s/rad].
  ElasticCoupling(const SimTK::MobilizedBody& motor_body, double stiffness, double damping)
      : ElasticCoupling(motor_body, CouplingLaw{stiffness, damping, 0.0}) {}

  double twist(const SimTK::State& s) const { return motor_.getOneQ(s, 0); }
  double twistRate(const SimTK::State& s) const { return motor_.getOneU(s, 0); }
  const CouplingLaw& law() const { return law_; }
  // Torque the coupling transmits to the crankshaft [N·m].
  double torque(const SimTK::State& s) const { return couplingTorque(law_, twist(s), twistRate(s)).torque; }
  // Power lost in the damper [W] (≥ 0).
  double dampingPower(const SimTK::State& s) const {
    return couplingTorque(law_, twist(s), twistRate(s)).damping_power;
  }

  void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>&,
                 SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector& mobility_forces) const override {
    // A generalized force on the relative joint acts -τ on the motor side and +τ on the crank.
    motor_.applyOneMobilityForce(s, 0, -torque(s), mobility_forces);
  }
  SimTK::Real calcPotentialEnergy(const SimTK::State& s) const override {
    return couplingPotential(law_, twist(s));
  }

 private:
  SimTK::MobilizedBody motor_;  // handle copy of the motor-side body in the matter subsystem
  CouplingLaw law_;
};

}  // namespace rollerdyn
