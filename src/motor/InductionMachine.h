// The induction machine's equivalent circuit: parameters per phase of the EQUIVALENT STAR and its
// steady-state solution. One description for the quasi-static circuit law (CircuitLaw.h), the
// space-phasor machine (ParkLaw.h) and the catalogue fit (CatalogueFit.h).
//
// Circuit (per phase, T-form; Pedra (2008) fig. 1 for the double cage; Krause, "Analysis of
// Electric Machinery and Drive Systems", ch. 6 for the single cage):
//
//   U_ph ──R_s──jX_σs──┬──────────┬──────────────┬─ ...
//                      │          │              │
//                     jX_m     R_r1/s          R_r2/s        (second cage: double cage only)
//                      │       jX_σr1          jX_σr2
//   ───────────────────┴──────────┴──────────────┴─
//
// with X = ω1·L, ω1 = 2π·f the supply's angular frequency and s = (ω1 − p·ω_r)/ω1 the slip. The
// cages couple only through the magnetizing inductance (no common rotor leakage).
// Quantities per phase of the equivalent star: U_ph = U_line/√3 and the line current; a delta
// winding's own values are R_Δ = 3·R, L_Δ = 3·L and its winding current is I_line/√3.
#pragma once

#include <complex>
#include <string>

namespace rollerdyn {

struct InductionMotor;

struct InductionMachineParameters {
  double R_s = 0;           // stator resistance [Ω]
  double L_sigma_s = 0;     // stator leakage inductance [H]
  double L_m = 0;           // magnetizing inductance [H]
  int cages = 1;            // rotor cages: 1 or 2 [-]
  double R_r[2] = {0, 0};        // rotor cage resistances referred to the stator [Ω]
  double L_sigma_r[2] = {0, 0};  // rotor cage leakage inductances [H]
  int pole_pairs = 1;       // p [-]
  double phase_voltage = 0; // rated RMS phase voltage of the equivalent star U_ph [V]
  double frequency = 50;    // rated supply frequency f_n [Hz]

  double supplyAngularFrequency() const;  // ω1 = 2π·f_n [rad/s]
  double synchronousSpeed() const;        // ω0 = ω1/p [rad/s]
  // Throws std::invalid_argument naming the first value out of range.
  void validate() const;
  // "R_s = 0.03 Ω, L_σs = ..." for messages and the console.
  std::string summary() const;
  // From the scene's motor.circuit.* and rated supply (Scene.h: InductionMotor).
  static InductionMachineParameters fromScene(const InductionMotor& motor);
};

// Steady state of the circuit at one supply and rotor speed. Phasors are RMS, phase-voltage
// phasor real and positive.
struct CircuitSolution {
  double slip = 0;             // s [-]
  double torque = 0;           // electromagnetic torque M = P_ag/ω0 [N·m]
  double current = 0;          // RMS stator (line) current |I_s| [A]
  double power_factor = 0;     // cos φ = P_in/(3·U·I) [-]
  double electrical_power = 0; // P_in = 3·Re(U·I_s*) [W]
  double airgap_power = 0;     // P_ag = P_in − 3·R_s·|I_s|² [W]
  double copper_loss = 0;      // 3·(R_s·|I_s|² + Σ R_rk·|I_rk|²) [W]
  double magnetic_energy = 0;  // energy in the inductances, constant in a balanced steady state
                               // (3/2)·(L_σs|I_s|² + Σ L_σrk|I_rk|² + L_m|I_s + Σ I_rk|²) [J]
  std::complex<double> I_s;          // stator current phasor [A]
  std::complex<double> I_r[2];       // rotor cage current phasors [A]
};

// Solves the circuit at phase voltage u_phase [V RMS], supply angular frequency omega1 [rad/s]
// (electrical) and rotor speed omega_rotor [rad/s]. The rotor branches enter as admittances
// s/(R + j·s·X), so s = 0 (synchronous speed) and s < 0 (generating) need no special case.
CircuitSolution solveCircuit(const InductionMachineParameters& m, double u_phase, double omega1,
                             double omega_rotor);

}  // namespace rollerdyn
