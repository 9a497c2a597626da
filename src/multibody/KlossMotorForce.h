// Kloss induction motor as a Simbody force element: applies the motor torque reduced to the
// crank axis (physics/KlossMotor.h, seed 000 eq. (37)) to the mobility of the motor-side body.
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
  double power(const SimTK::State& s) const { return torque(s) * motor_body_.getOneU(s, 0); }

  void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>&,
                 SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector& mobility_forces) const override;
  SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }

 private:
  SimTK::MobilizedBody motor_body_;  // handle copy: refers to the body in the matter subsystem
  KlossMotor motor_;
  double ratio_, efficiency_;
};

}  // namespace rollerdyn
