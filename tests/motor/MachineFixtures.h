// Machines of the motor tests, each from a published source, and the steady-state closed form of
// the equivalent circuit written out here (independently of src/motor) in complex arithmetic.
#pragma once

#include <cmath>
#include <complex>

#include "compare/ReferenceMachines.h"  // header-only data
#include "motor/InductionMachine.h"

namespace rollerdyn::test {

inline InductionMachineParameters mslMachine() { return reference::mslSquirrelCage(); }
inline InductionMachineParameters krause3hp() { return reference::krause3hp(); }

// A double cage of the size of the papers' 22 kW motor (illustrative values; starting cage of
// high resistance and low leakage).
inline InductionMachineParameters doubleCage() {
  InductionMachineParameters m;
  const double w = 2 * M_PI * 50;
  m.R_s = 0.2;
  m.L_sigma_s = 0.35 / w;
  m.L_m = 15.0 / w;
  m.cages = 2;
  m.R_r[0] = 0.12;
  m.L_sigma_r[0] = 0.5 / w;
  m.R_r[1] = 0.6;
  m.L_sigma_r[1] = 0.1 / w;
  m.pole_pairs = 3;
  m.phase_voltage = 380 / std::sqrt(3.0);
  m.frequency = 50;
  return m;
}

struct ClosedForm {
  double torque;   // N·m
  double current;  // A RMS
};

// Textbook T-circuit at slip s ≠ 0: Z = R_s + jX_σs + (jX_m ∥ (R_r1/s + jX_σr1) ∥ (R_r2/s + jX_σr2)),
// I_s = U/Z, E = U − I_s(R_s + jX_σs), I_rk = E/(R_rk/s + jX_σrk), M = (3p/ω1)·Σ|I_rk|²·R_rk/s.
inline ClosedForm closedForm(const InductionMachineParameters& m, double s, double u_ratio = 1.0,
                             double f_ratio = 1.0) {
  using C = std::complex<double>;
  const C j(0, 1);
  const double w1 = 2 * M_PI * m.frequency * f_ratio, U = m.phase_voltage * u_ratio;
  C Zr[2];
  C Y = 1.0 / (j * w1 * m.L_m);
  for (int k = 0; k < m.cages; ++k) {
    Zr[k] = m.R_r[k] / s + j * w1 * m.L_sigma_r[k];
    Y += 1.0 / Zr[k];
  }
  const C Zs = m.R_s + j * w1 * m.L_sigma_s;
  const C I = U / (Zs + 1.0 / Y);
  const C E = U - I * Zs;
  double M = 0;
  for (int k = 0; k < m.cages; ++k) M += std::norm(E / Zr[k]) * m.R_r[k] / s;
  return {3.0 * m.pole_pairs / w1 * M, std::abs(I)};
}

}  // namespace rollerdyn::test
