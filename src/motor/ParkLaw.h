// The space-phasor (Park, dq) induction machine (motor.model: park): stator and rotor flux
// linkages as states, in the frame that turns with the supply voltage, so a steady run has
// constant states. Krause, Wasynczuk, Sudhoff, "Analysis of Electric Machinery and Drive
// Systems", ch. 6 (arbitrary reference frame, eq. 6.5-x with flux linkages as states); the
// double cage couples its two rotor windings through L_m only, as the Modelica Standard
// Library's Machines.BasicMachines.InductionMachines.IM_SquirrelCage does for one cage.
//
// Space phasors are amplitude-invariant, x = (2/3)(x_a + a·x_b + a²·x_c), a = e^{j2π/3}, so
// |u_s| = √2·U_ph. In the frame turning at the supply's angular frequency ω_k = ω1·(f/f_n):
//   u_s = R_s·i_s + dψ_s/dt + j·ω_k·ψ_s
//   0   = R_rk·i_rk + dψ_rk/dt + j·(ω_k − p·ω_r)·ψ_rk              (each cage k)
//   ψ_s = L_s·i_s + L_m·Σ i_rk,   ψ_rk = L_m·(i_s + Σ_j i_rj) + L_σrk·i_rk,   L_s = L_σs + L_m
//   M   = (3/2)·p·Im(ψ_s*·i_s)
// with u_s = √2·U_ph·(U/U_n)·e^{j·phase} (SupplyState). Outputs: P_el = (3/2)·Re(u_s·i_s*),
// copper loss (3/2)·(R_s|i_s|² + Σ R_rk|i_rk|²), magnetic energy W = (3/4)·Re(Σ ψ_k*·i_k), and
// P_el = copper loss + M·ω_r + dW/dt holds exactly (validated by an energy audit).
// Switched off (SupplyState::connected false) the stator current is zero: the rotor fluxes decay
// through the rotor resistances and the stator flux follows them, ψ_s = L_m·Σ i_rk; the
// breaker's instant is switchStates (rotor fluxes continuous, i_s → 0). Switching on, a changed
// voltage or a phase jump leave every flux continuous. Parameters per phase of the equivalent
// star (InductionMachine.h). Neglected: saturation, iron and friction losses, skin effect beyond
// what a second cage represents, space harmonics.
#pragma once

#include <complex>

#include <Eigen/Dense>

#include "motor/InductionMachine.h"
#include "motor/MotorLaw.h"

namespace rollerdyn {

class ParkLaw : public MotorLaw {
 public:
  explicit ParkLaw(const InductionMachineParameters& machine);
  std::string description() const override;
  double synchronousSpeed() const override { return machine_.synchronousSpeed(); }
  int stateCount() const override { return 2 * windings_; }
  std::vector<std::string> stateNames() const override;
  std::vector<double> stateScales() const override;
  double fastestTimeConstant() const override { return fastest_; }
  void initialState(const SupplyState& supply, double omega_rotor, bool steady, double* x) const override;
  void evaluate(const SupplyState& supply, double omega_rotor, const double* x, MotorEvaluation& out,
                double* xdot) const override;
  void switchStates(const SupplyState& before, const SupplyState& after, double omega_rotor,
                    double* x) const override;
  double steadyTorque(const SupplyState& supply, double omega_rotor) const override;
  double steadyCurrent(const SupplyState& supply, double omega_rotor) const override;
  const InductionMachineParameters& machine() const { return machine_; }

 private:
  // The steady state's fluxes ψ [Wb] and currents i [A] at (supply, ω_r), the breaker closed.
  void steadyFluxesAndCurrents(const SupplyState& supply, double omega_rotor, std::complex<double>* psi,
                               std::complex<double>* i) const;

  InductionMachineParameters machine_;
  int windings_;              // 1 stator + cages
  Eigen::Matrix3d L_;         // inductance matrix (windings_ × windings_ block used)
  Eigen::Matrix3d Gamma_;     // its inverse: i = Γ·ψ
  Eigen::Matrix2d Gamma_rr_;  // inverse of the rotor block: i_r = Γ_rr·ψ_r when i_s = 0
  double fastest_;            // 1/max|eigenvalue of R·Γ| [s]
};

}  // namespace rollerdyn
