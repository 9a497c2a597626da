#include "motor/KlossDynamicLaw.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "motor/KlossLaw.h"
#include "physics/KlossMotor.h"

namespace rollerdyn {

KlossDynamicLaw::KlossDynamicLaw(const KlossMotor& motor, double time_constant)
    : motor_(motor), time_constant_(time_constant) {
  if (!(time_constant > 0 && std::isfinite(time_constant)))
    throw std::invalid_argument("dynamic Kloss law: time constant T_e must be > 0");
  if (!(motor.omega_sync > 0 && motor.breakdown_torque > 0 && motor.critical_slip > 0))
    throw std::invalid_argument("dynamic Kloss law: omega_sync, breakdown_torque and critical_slip must be > 0");
}

double KlossDynamicLaw::defaultTimeConstant(const KlossMotor& motor, double rated_frequency) {
  return 1.0 / (2.0 * M_PI * rated_frequency * motor.critical_slip);
}

std::string KlossDynamicLaw::description() const {
  char buf[96];
  std::snprintf(buf, sizeof buf, "dynamic Kloss characteristic (T_e = %.4g s)", time_constant_);
  return buf;
}

double KlossDynamicLaw::steadyTorque(const SupplyState& supply, double omega_rotor) const {
  if (!supply.connected) return 0.0;
  return klossRotorTorque(klossAtSupply(motor_, supply), omega_rotor);
}

void KlossDynamicLaw::initialState(const SupplyState& supply, double omega_rotor, bool steady, double* x) const {
  x[0] = steady ? steadyTorque(supply, omega_rotor) : 0.0;
}

void KlossDynamicLaw::evaluate(const SupplyState& supply, double omega_rotor, const double* x,
                               MotorEvaluation& out, double* xdot) const {
  out = MotorEvaluation{};
  out.torque = x[0];
  if (xdot) xdot[0] = (steadyTorque(supply, omega_rotor) - x[0]) / time_constant_;
}

void KlossDynamicLaw::switchStates(const SupplyState& before, const SupplyState& after, double, double* x) const {
  if (before.connected && !after.connected) x[0] = 0.0;
}

}  // namespace rollerdyn
