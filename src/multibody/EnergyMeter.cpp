#include "multibody/EnergyMeter.h"

#include "multibody/ElasticCoupling.h"
#include "multibody/GuideFriction.h"
#include "multibody/MotorForce.h"
#include "multibody/RollerLoadForce.h"

namespace rollerdyn {

void EnergyMeter::realizeTopology(SimTK::State& s) const {
  z_start_ = forces_.allocateZ(s, SimTK::Vector(4, 0.0));
}

void EnergyMeter::realizeAcceleration(const SimTK::State& s) const { calcRates(s, forces_.updZDot(s)); }

void EnergyMeter::calcRates(const SimTK::State& s, SimTK::Vector& zdot) const {
  zdot[z_start_ + 0] = sources_.motor ? sources_.motor->power(s) : 0.0;
  zdot[z_start_ + 1] = sources_.coupling ? sources_.coupling->dampingPower(s) : 0.0;
  zdot[z_start_ + 2] = sources_.friction ? sources_.friction->dissipatedPower(s) : 0.0;
  zdot[z_start_ + 3] = sources_.loads ? sources_.loads->loadPower(s) : 0.0;
}

}  // namespace rollerdyn
