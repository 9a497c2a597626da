// The steady-state equivalent circuit as a quasi-static motor law (motor.model: circuit): at
// every instant the torque and current the machine would have in steady state at this supply
// and rotor speed (InductionMachine.h). With a double cage it honours the catalogue's starting
// torque, which Kloss's formula cannot (docs/motor.md).
// What it neglects: every electrical transient (flux build-up, the supply-frequency torque
// oscillation after switching on, the decay of the rotor flux after switching off), saturation,
// iron and friction losses (the catalogue fit puts them into R_s).
// Supply: phase voltage U_ph·(U/U_n), angular frequency ω1·(f/f_n); the phase is irrelevant here.
#pragma once

#include "motor/InductionMachine.h"
#include "motor/MotorLaw.h"

namespace rollerdyn {

class CircuitLaw : public MotorLaw {
 public:
  explicit CircuitLaw(const InductionMachineParameters& machine);
  std::string description() const override;
  double synchronousSpeed() const override { return machine_.synchronousSpeed(); }
  void evaluate(const SupplyState& supply, double omega_rotor, const double* x, MotorEvaluation& out,
                double* xdot) const override;
  double steadyTorque(const SupplyState& supply, double omega_rotor) const override;
  double steadyCurrent(const SupplyState& supply, double omega_rotor) const override;
  const InductionMachineParameters& machine() const { return machine_; }
  // The circuit's steady state under `supply` (connected) at rotor speed ω_r.
  CircuitSolution solve(const SupplyState& supply, double omega_rotor) const;

 private:
  InductionMachineParameters machine_;
};

}  // namespace rollerdyn
