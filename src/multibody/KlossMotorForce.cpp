#include "multibody/KlossMotorForce.h"

#include "physics/KlossMotor.h"

namespace rollerdyn {

double KlossMotorForce::torque(const SimTK::State& s) const {
  return klossCrankTorque(motor_, ratio_, efficiency_, motor_body_.getOneU(s, 0));
}

void KlossMotorForce::calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>&,
                                SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector& mobility_forces) const {
  motor_body_.applyOneMobilityForce(s, 0, torque(s), mobility_forces);
}

}  // namespace rollerdyn
