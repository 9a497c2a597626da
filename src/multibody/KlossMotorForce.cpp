#include "multibody/KlossMotorForce.h"

#include "physics/KlossMotor.h"

namespace rollerdyn {

double KlossMotorForce::torque(const SimTK::State& s) const {
  return klossCrankTorque(motor_, ratio_, efficiency_, speed(s));
}

void KlossMotorForce::calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& body_forces,
                                SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector&) const {
  motor_body_.applyBodyTorque(s, SimTK::Vec3(0, 0, torque(s)), body_forces);
}

}  // namespace rollerdyn
