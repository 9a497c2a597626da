// What the stop rules every run shares (analysis/RunRecorder.h) read of a multibody state: the
// crank's angle and speed, the motor's speed, every cart's speed and the supply's phase. The
// same for both formulations.
#pragma once

#include <vector>

#include "analysis/RunRecorder.h"
#include "motor/Supply.h"
#include "multibody/MotorForce.h"
#include "multibody/MultibodyModel.h"

namespace rollerdyn {

// cart_speeds and phase are the storage the motion points to: they must outlive its use.
inline RowMotion stopRuleMotion(const MultibodyModel& model, const SimTK::State& s, std::vector<double>& cart_speeds,
                                SupplyPhase& phase) {
  cart_speeds.resize(model.carts().size());
  for (std::size_t j = 0; j < cart_speeds.size(); ++j) cart_speeds[j] = model.carts()[j].v(s);
  const MotorForce* motor = model.motorForce();
  if (motor) phase = motor->phase(s);
  return {model.crankAngle(s), model.crankSpeed(s), model.motorSpeed(s), &cart_speeds, motor ? &phase : nullptr};
}

}  // namespace rollerdyn
