// Kloss induction motor as a Simbody force element: applies the motor torque reduced to the
// crank axis (physics/KlossMotor.h, Loveikin, Pochka, Romasevych (2018) eq. (37)) to the motor-side body as a torque about
// the shaft axis z, its reaction going to the (grounded) stator. The body's absolute angular
// velocity is used, because with an elastic coupling the motor side is mobilized relative to
// the crankshaft (MultibodyModel.h).
#pragma once

#include "Simbody.h"
#include "scene/Scene.h"

namespace rollerdyn {

class KlossMotorForce : public SimTK::Force::Custom::Implementation {
 public:
  KlossMotorForce(const SimTK::MobilizedBody& motor_body, const KlossMotor& motor, double ratio,
                  double efficiency)
      : motor_body_(motor_body), motor_(motor), ratio_(ratio), efficiency_(efficiency) {}

  // Torque on the motor-side body at its current speed, reduced to the crank axis [N·m].
  double torque(const SimTK::State& s) const;
  // Power delivered by the motor into the mechanism [W].
  double power(const SimTK::State& s) const { return torque(s) * speed(s); }
  // Absolute angular speed of the motor-side body about z, reduced to the crank axis [rad/s].
  double speed(const SimTK::State& s) const { return motor_body_.getBodyAngularVelocity(s)[2]; }

  void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& body_forces,
                 SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector&) const override;
  SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }

 private:
  SimTK::MobilizedBody motor_body_;  // handle copy: refers to the body in the matter subsystem
  KlossMotor motor_;
  double ratio_, efficiency_;
};

}  // namespace rollerdyn
