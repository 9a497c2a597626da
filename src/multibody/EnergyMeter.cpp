#include "multibody/EnergyMeter.h"

#include "multibody/CrankshaftTorsion.h"
#include "multibody/ElasticCoupling.h"
#include "multibody/GuideFriction.h"
#include "multibody/MotorForce.h"
#include "multibody/RollerLoadForce.h"

namespace rollerdyn {

EnergyMeter::EnergyMeter(const SimTK::GeneralForceSubsystem& forces, Sources sources)
    : forces_(forces), sources_(sources),
      reducer_state_(sources.motor && sources.motor->reducer().model == ReducerLossModel::PowerFlow) {}

void EnergyMeter::realizeTopology(SimTK::State& s) const {
  z_start_ = forces_.allocateZ(s, SimTK::Vector(stateCount(), 0.0));
}

double EnergyMeter::reducerLosses(const SimTK::State& s) const {
  if (reducer_state_) return z(s, 4);
  if (!sources_.motor) return 0.0;
  const double eta = sources_.motor->reducer().eta_forward;  // papers: L·ω = (1 − η)·M·u·ω
  return (1.0 / eta - 1.0) * motorWork(s);
}

void EnergyMeter::realizeAcceleration(const SimTK::State& s) const { calcRates(s, forces_.updZDot(s)); }

void EnergyMeter::calcRates(const SimTK::State& s, SimTK::Vector& zdot) const {
  zdot[z_start_ + 0] = sources_.motor ? sources_.motor->power(s) : 0.0;
  zdot[z_start_ + 1] = sources_.coupling ? sources_.coupling->dampingPower(s) : 0.0;
  if (sources_.torsion) zdot[z_start_ + 1] += sources_.torsion->dampingPower(s);
  zdot[z_start_ + 2] = sources_.friction ? sources_.friction->dissipatedPower(s) : 0.0;
  zdot[z_start_ + 3] = sources_.loads ? sources_.loads->loadPower(s) : 0.0;
  if (reducer_state_) zdot[z_start_ + 4] = sources_.motor->reducerLossPower(s);
}

}  // namespace rollerdyn
