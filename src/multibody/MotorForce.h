// The induction motor as a Simbody force element: the scene's motor law (motor.model,
// src/motor/MotorLaw.h) fed by the starting method's supply (src/motor/Supply.h) applies its
// torque, reduced to the crank axis through the reducer's law (reducer.losses,
// physics/ReducerLosses.h; the papers' ×u·η, Loveikin, Pochka, Romasevych (2018) eq. (37)), to the
// motor-side body about the shaft axis z, its reaction going to the (grounded) stator; a
// mechanical brake on the motor shaft (motor.stop.brake_torque) acts on the same body. The
// body's absolute angular velocity is used, because with an elastic coupling the motor side is
// mobilized relative to the crankshaft (MultibodyModel.h).
//
// Self-contained in Simbody's way: what the element needs beyond q and u lives in the State.
//   z (continuous, only when the scene asks for them): the law's own states (none for the static
//     laws; the dynamic Kloss torque; the Park machine's fluxes), then the brake's dissipated
//     energy [J] when a brake is set;
//   a discrete variable (only when the supply switches): the SupplyPhase, changed by the run
//     loops at the switching events (applyDueEvents), never inside a step.
// The z rates are set in realizeAcceleration (constrained formulation) or by calcRates (minimal
// formulation, MultibodyModel::auxiliaryRates).
#pragma once

#include <memory>

#include "Simbody.h"
#include "motor/MotorLaw.h"
#include "motor/Supply.h"
#include "physics/ReducerLosses.h"

namespace rollerdyn {

class MotorForce : public SimTK::Force::Custom::Implementation {
 public:
  MotorForce(const SimTK::GeneralForceSubsystem& forces, const SimTK::MobilizedBody& motor_body,
             std::shared_ptr<const MotorLaw> law, Supply supply, ReducerLaw reducer);

  const MotorLaw& law() const { return *law_; }
  const Supply& supply() const { return supply_; }
  // z entries this element owns: the law's states, then the brake work (0 for a static law
  // without brake).
  int stateCount() const { return law_->stateCount() + (supply_.hasBrake() ? 1 : 0); }
  int lawStateCount() const { return law_->stateCount(); }

  // Electromagnetic torque on the motor-side body, reduced to the crank axis [N·m].
  double torque(const SimTK::State& s) const;
  // Brake torque on the motor-side body, reduced to the crank axis [N·m] (≤ 0 while turning forwards).
  double brakeTorque(const SimTK::State& s) const;
  // Power delivered by the motor through the reducer into the mechanism [W].
  double power(const SimTK::State& s) const { return torque(s) * speed(s); }
  // The reducer's loss torque on the motor's torque, at the crank axis [N·m] (ReducerLosses.h),
  // and its loss power [W] (≥ 0 under power_flow). The brake's share is not in it: a brake's
  // torque passes the reducer's law on its own and all it takes counts as brake dissipation.
  double reducerLossTorque(const SimTK::State& s) const;
  double reducerLossPower(const SimTK::State& s) const { return reducerLossTorque(s) * speed(s); }
  const ReducerLaw& reducer() const { return reducer_; }
  // Power dissipated in the brake [W] (≥ 0).
  double brakePower(const SimTK::State& s) const { return -brakeTorque(s) * speed(s); }
  // Brake energy dissipated since t = 0 [J] (0 without brake).
  double brakeWork(const SimTK::State& s) const;
  // Absolute angular speed of the motor-side body about z, reduced to the crank axis [rad/s].
  double speed(const SimTK::State& s) const { return motor_body_.getBodyAngularVelocity(s)[2]; }
  // Rotor speed ω_r = u·speed [rad/s].
  double rotorSpeed(const SimTK::State& s) const { return ratio_ * speed(s); }

  // The supply phase of state s (the initial one when the supply never switches), the supply
  // state, and the law's full evaluation (torque at the rotor, stator current, ...) in s.
  SupplyPhase phase(const SimTK::State& s) const;
  SupplyState supplyState(const SimTK::State& s) const;
  MotorEvaluation evaluate(const SimTK::State& s) const;

  // The law's states at t = 0 in z (steady: the motor ran before, MotorLaw::initialState); brake
  // work 0. State realized to Velocity.
  void initialize(SimTK::State& s, bool steady) const;
  // Applies the supply's events due at the state's time (speed_reached: the speed-triggered one
  // was found by root finding), mapping the law's states; true when the phase changed. State
  // realized to Velocity.
  bool applyDueEvents(SimTK::State& s, bool speed_reached) const;
  // Sets the supply phase of s (e.g. of a copy of the state the run keeps).
  void setPhase(SimTK::State& s, const SupplyPhase& p) const;

  // z rates (law states, brake work), written into zdot (indexed like the force subsystem's z);
  // state realized to Velocity.
  void calcRates(const SimTK::State& s, SimTK::Vector& zdot) const;
  // The integrators' error weights of this element's z: one unit = the law's state scale
  // (MotorLaw::stateScales); brake work is left at Simbody's default. State at Model stage.
  void setErrorWeights(SimTK::State& s) const;

  void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& body_forces,
                 SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector&) const override;
  SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }
  void realizeTopology(SimTK::State& s) const override;
  void realizeAcceleration(const SimTK::State& s) const override;

 private:
  const double* lawStates(const SimTK::State& s) const;
  // The law's evaluation at s; rates into xdot (lawStateCount() values) when given.
  MotorEvaluation evaluateLaw(const SimTK::State& s, double* xdot) const;

  const SimTK::GeneralForceSubsystem& forces_;
  SimTK::MobilizedBody motor_body_;  // handle copy: refers to the body in the matter subsystem
  std::shared_ptr<const MotorLaw> law_;
  Supply supply_;
  SupplyPhase initial_phase_;
  ReducerLaw reducer_;
  double ratio_;
  mutable SimTK::ZIndex z_start_;
  mutable SimTK::DiscreteVariableIndex phase_index_;
};

}  // namespace rollerdyn
