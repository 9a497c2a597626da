// The multibody model's initial state: the closed-form configuration of given crank angle, speed
// and coupling twist, the motor's own states at t = 0, and the loops assembled by projection
// with the guide-friction normal forces they produce.
#include "multibody/MultibodyModel.h"

#include <algorithm>
#include <stdexcept>

#include "motor/Supply.h"
#include "multibody/CrankshaftTorsion.h"
#include "multibody/GuideFriction.h"
#include "multibody/MinimalCoordinates.h"
#include "multibody/MinimalDynamics.h"
#include "multibody/MotorForce.h"
#include "physics/GuideFrictionLoop.h"

namespace rollerdyn {

SimTK::State MultibodyModel::closedFormState(double phi, double omega, double twist) const {
  SimTK::State s = closedFormKinematics(phi, omega, twist);
  startMotor(s);
  return s;
}

void MultibodyModel::startMotor(SimTK::State& s) const {
  if (!motor_force_) return;
  const bool steady = motorSteadyAtStart(scene_, motor_force_->supply());
  motor_force_->initialize(s, steady);
  system_.realize(s, SimTK::Stage::Velocity);
  motor_force_->applyDueEvents(s, false);
  system_.realize(s, SimTK::Stage::Velocity);
}

SimTK::State MultibodyModel::closedFormKinematics(double phi, double omega, double twist) const {
  SimTK::State s = system_.getDefaultState();
  system_.realizeModel(s);
  // Carts of different masses: the lightest is the one a friction error moves most.
  if (friction_force_) friction_force_->setErrorWeights(s, scene_.lightestCartMassWithRodShare());
  if (motor_force_) motor_force_->setErrorWeights(s);
  weightTwists(s);
  system_.realize(s, SimTK::Stage::Instance);
  IndependentState x;
  x.crank_angle = phi;
  x.crank_speed = omega;
  x.twist = twist;
  x.twist_rate = 0.0;  // the motor side starts at the crank's speed
  // A prescribed crank speed is the options' (MinimalCoordinates::apply writes it).
  MinimalCoordinates(*this, s).apply(0.0, x, s);
  system_.realize(s, SimTK::Stage::Velocity);
  return s;
}

void MultibodyModel::weightTwists(SimTK::State& s) const {
  if (elastic()) {
    // Simbody counts 1 rad (1 rad/s) as a unit change of every coordinate (speed), but the
    // coupling twist is ~torque/c: 1e-6 rad at c = 1e9, so it was held to ~100 % of itself and
    // the coupling torque carried errors of c·accuracy. One unit of twist is the twist that
    // carries the motor's breakdown torque at the crank, M_kr·u·η, so the coupling torque is
    // held to accuracy·M_kr·u·η whatever the stiffness.
    const double torque_scale =
        breakdown_torque_ * scene_.reducer.ratio * scene_.reducer.efficiency;
    s.updUWeights(matter_.getMySubsystemIndex())[motor_.getFirstUIndex(s)] =
        std::max(1.0, scene_.coupling.stiffness / torque_scale);
  }
  if (torsion_force_) {
    // The same for each segment of a torsional chain: one unit of its twist carries M_kr·u·η.
    const double torque_scale = std::max(breakdown_torque_ * scene_.reducer.ratio * scene_.reducer.efficiency, 1e-300);
    for (int k = 0; k < torsion_force_->segmentCount(); ++k)
      s.updUWeights(matter_.getMySubsystemIndex())[torsion_force_->segmentBody(k).getFirstUIndex(s)] =
          std::max(1.0, torsion_force_->stiffness(k) / torque_scale);
  }
}

SimTK::State MultibodyModel::assembledState(double phi, double omega, double twist) const {
  SimTK::State s = closedFormKinematics(phi, omega, twist);
  // The closed-form configuration already satisfies the loops; projection only removes
  // round-off and can therefore never jump to the other assembly branch.
  system_.realize(s, SimTK::Stage::Position);
  system_.projectQ(s, 1e-13);
  system_.realize(s, SimTK::Stage::Velocity);
  system_.projectU(s, 1e-13);
  startMotor(s);
  startFrictionNormals(s);
  system_.realize(s, SimTK::Stage::Acceleration);
  return s;
}

void MultibodyModel::startFrictionNormals(SimTK::State& s) const {
  if (friction_force_ && friction_force_->lagged()) {
    // Start the friction normal forces at the reactions they produce themselves (fixed point;
    // it contracts by a factor of order f per pass).
    for (int pass = 0; pass < 8; ++pass) {
      system_.realize(s, SimTK::Stage::Acceleration);
      const SimTK::Vector n = friction_force_->currentNormals(s);
      friction_force_->setNormalsInUse(s, n);
    }
  } else if (friction_force_) {
    // Algebraic law: the friction loop solved by the minimal formulation's inverse-dynamics pass.
    MinimalCoordinates coords(*this, s);
    coords.apply(0.0, coords.extract(s), s);
    MinimalDynamics dyn(*this, s);
    if (!dyn.evaluate(s, coords))
      throw std::invalid_argument("multibody model: at the initial state the " +
                                  describeLoopFailure(dyn.loopResult()));
  }
}

SimTK::State MultibodyModel::initialState() const {
  return assembledState(scene_.initial.crank_angle, scene_.initial.crank_speed, scene_.initial.twist);
}

}  // namespace rollerdyn
