#include "multibody/MotorForce.h"

#include <array>
#include <stdexcept>

namespace rollerdyn {

namespace {
constexpr int kMaxLawStates = 8;
}

MotorForce::MotorForce(const SimTK::GeneralForceSubsystem& forces, const SimTK::MobilizedBody& motor_body,
                       std::shared_ptr<const MotorLaw> law, Supply supply, ReducerLaw reducer)
    : forces_(forces), motor_body_(motor_body), law_(std::move(law)), supply_(std::move(supply)),
      initial_phase_(supply_.initialPhase()), reducer_(reducer), ratio_(reducer.ratio) {
  if (!law_) throw std::invalid_argument("MotorForce: no motor law");
  if (law_->stateCount() > kMaxLawStates)
    throw std::invalid_argument("MotorForce: the motor law has more states than the element carries");
}

void MotorForce::realizeTopology(SimTK::State& s) const {
  if (stateCount() > 0) z_start_ = forces_.allocateZ(s, SimTK::Vector(stateCount(), 0.0));
  if (!supply_.constant())
    phase_index_ = forces_.allocateDiscreteVariable(s, SimTK::Stage::Dynamics, new SimTK::Value<SupplyPhase>(initial_phase_));
}

SupplyPhase MotorForce::phase(const SimTK::State& s) const {
  if (supply_.constant()) return initial_phase_;
  return SimTK::Value<SupplyPhase>::downcast(forces_.getDiscreteVariable(s, phase_index_)).get();
}

void MotorForce::setPhase(SimTK::State& s, const SupplyPhase& p) const {
  if (supply_.constant()) return;
  SimTK::Value<SupplyPhase>::updDowncast(forces_.updDiscreteVariable(s, phase_index_)).upd() = p;
}

SupplyState MotorForce::supplyState(const SimTK::State& s) const {
  return supply_.state(phase(s), s.getTime(), rotorSpeed(s));
}

const double* MotorForce::lawStates(const SimTK::State& s) const {
  return law_->stateCount() > 0 ? &forces_.getZ(s)[z_start_] : nullptr;
}

MotorEvaluation MotorForce::evaluateLaw(const SimTK::State& s, double* xdot) const {
  MotorEvaluation out;
  std::array<double, kMaxLawStates> scratch{};
  double* rates = xdot ? xdot : (law_->stateCount() > 0 ? scratch.data() : nullptr);
  law_->evaluate(supplyState(s), rotorSpeed(s), lawStates(s), out, rates);
  return out;
}

MotorEvaluation MotorForce::evaluate(const SimTK::State& s) const { return evaluateLaw(s, nullptr); }

double MotorForce::torque(const SimTK::State& s) const {
  return reducerCrankTorque(reducer_, evaluateLaw(s, nullptr).torque, speed(s));
}

double MotorForce::reducerLossTorque(const SimTK::State& s) const {
  return rollerdyn::reducerLossTorque(reducer_, evaluateLaw(s, nullptr).torque, speed(s));
}

double MotorForce::brakeTorque(const SimTK::State& s) const {
  if (!supply_.hasBrake()) return 0.0;
  return reducerCrankTorque(reducer_, supply_.brakeTorque(phase(s), rotorSpeed(s)), speed(s));
}

double MotorForce::brakeWork(const SimTK::State& s) const {
  return supply_.hasBrake() ? forces_.getZ(s)[z_start_ + law_->stateCount()] : 0.0;
}

void MotorForce::calcRates(const SimTK::State& s, SimTK::Vector& zdot) const {
  if (stateCount() == 0) return;
  if (law_->stateCount() > 0) {
    std::array<double, kMaxLawStates> rates{};
    evaluateLaw(s, rates.data());
    for (int i = 0; i < law_->stateCount(); ++i) zdot[z_start_ + i] = rates[i];
  }
  if (supply_.hasBrake()) zdot[z_start_ + law_->stateCount()] = brakePower(s);
}

void MotorForce::realizeAcceleration(const SimTK::State& s) const {
  if (stateCount() > 0) calcRates(s, forces_.updZDot(s));
}

void MotorForce::setErrorWeights(SimTK::State& s) const {
  if (law_->stateCount() == 0) return;
  const std::vector<double> scales = law_->stateScales();
  SimTK::Vector& w = s.updZWeights(forces_.getMySubsystemIndex());
  for (int i = 0; i < law_->stateCount(); ++i) w[z_start_ + i] = 1.0 / scales.at(i);
}

void MotorForce::initialize(SimTK::State& s, bool steady) const {
  if (stateCount() == 0) return;
  SimTK::Vector& z = forces_.updZ(s);
  if (law_->stateCount() > 0) {
    const double w_r = rotorSpeed(s);
    law_->initialState(supply_.state(phase(s), s.getTime(), w_r), w_r, steady, &z[z_start_]);
  }
  if (supply_.hasBrake()) z[z_start_ + law_->stateCount()] = 0.0;
}

bool MotorForce::applyDueEvents(SimTK::State& s, bool speed_reached) const {
  if (supply_.constant()) return false;
  SupplyPhase p = phase(s);
  const double w_r = rotorSpeed(s);  // read before z is written (which invalidates Velocity stage)
  std::array<double, kMaxLawStates> x{};
  for (int i = 0; i < law_->stateCount(); ++i) x[i] = forces_.getZ(s)[z_start_ + i];
  if (!supply_.applyDueEvents(p, s.getTime(), w_r, speed_reached, law_.get(), x.data())) return false;
  setPhase(s, p);
  if (law_->stateCount() > 0) {
    SimTK::Vector& z = forces_.updZ(s);
    for (int i = 0; i < law_->stateCount(); ++i) z[z_start_ + i] = x[i];
  }
  return true;
}

void MotorForce::calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& body_forces,
                           SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector&) const {
  const double M = supply_.hasBrake() ? torque(s) + brakeTorque(s) : torque(s);
  motor_body_.applyBodyTorque(s, SimTK::Vec3(0, 0, M), body_forces);
}

}  // namespace rollerdyn
