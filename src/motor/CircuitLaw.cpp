#include "motor/CircuitLaw.h"

#include <stdexcept>

namespace rollerdyn {

CircuitLaw::CircuitLaw(const InductionMachineParameters& machine) : machine_(machine) { machine_.validate(); }

std::string CircuitLaw::description() const {
  return machine_.cages == 2 ? "equivalent circuit (steady state), double cage"
                             : "equivalent circuit (steady state), single cage";
}

CircuitSolution CircuitLaw::solve(const SupplyState& supply, double omega_rotor) const {
  if (!(supply.frequency > 0.0)) throw std::invalid_argument("circuit law: supply frequency ratio f/f_n must be > 0");
  return solveCircuit(machine_, machine_.phase_voltage * supply.voltage,
                      machine_.supplyAngularFrequency() * supply.frequency, omega_rotor);
}

void CircuitLaw::evaluate(const SupplyState& supply, double omega_rotor, const double*, MotorEvaluation& out,
                          double*) const {
  out = MotorEvaluation{};
  if (!supply.connected) {
    out.torque = 0.0;
    out.stator_current = 0.0;
    out.electrical_power = 0.0;
    out.copper_loss = 0.0;
    out.magnetic_energy = 0.0;
    return;
  }
  const CircuitSolution c = solve(supply, omega_rotor);
  out.torque = c.torque;
  out.stator_current = c.current;
  out.electrical_power = c.electrical_power;
  out.copper_loss = c.copper_loss;
  out.magnetic_energy = c.magnetic_energy;
}

double CircuitLaw::steadyTorque(const SupplyState& supply, double omega_rotor) const {
  return supply.connected ? solve(supply, omega_rotor).torque : 0.0;
}

double CircuitLaw::steadyCurrent(const SupplyState& supply, double omega_rotor) const {
  return supply.connected ? solve(supply, omega_rotor).current : 0.0;
}

}  // namespace rollerdyn
