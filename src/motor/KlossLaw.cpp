#include "motor/KlossLaw.h"

#include <stdexcept>
#include <string>

#include "physics/KlossMotor.h"

namespace rollerdyn {

KlossMotor klossAtSupply(const KlossMotor& rated, const SupplyState& supply) {
  if (!(supply.frequency > 0.0))
    throw std::invalid_argument("Kloss law: supply frequency ratio f/f_n must be > 0, got " +
                                std::to_string(supply.frequency));
  const double v = supply.voltage, phi = supply.frequency;
  KlossMotor m = rated;
  m.omega_sync = rated.omega_sync * phi;
  m.critical_slip = rated.critical_slip / phi;
  m.breakdown_torque = rated.breakdown_torque * (v * v) / (phi * phi);
  return m;  // at v = φ = 1 every field is the rated one exactly (×1, ÷1)
}

KlossLaw::KlossLaw(const KlossMotor& motor) : motor_(motor) {
  if (!(motor.omega_sync > 0 && motor.breakdown_torque > 0 && motor.critical_slip > 0))
    throw std::invalid_argument("Kloss law: omega_sync, breakdown_torque and critical_slip must be > 0");
}

double KlossLaw::steadyTorque(const SupplyState& supply, double omega_rotor) const {
  if (!supply.connected) return 0.0;
  return klossRotorTorque(klossAtSupply(motor_, supply), omega_rotor);
}

void KlossLaw::evaluate(const SupplyState& supply, double omega_rotor, const double*, MotorEvaluation& out,
                        double*) const {
  out = MotorEvaluation{};
  out.torque = steadyTorque(supply, omega_rotor);
}

}  // namespace rollerdyn
