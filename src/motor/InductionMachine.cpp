#include "motor/InductionMachine.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "scene/Scene.h"

namespace rollerdyn {

double InductionMachineParameters::supplyAngularFrequency() const { return 2.0 * M_PI * frequency; }
double InductionMachineParameters::synchronousSpeed() const { return supplyAngularFrequency() / pole_pairs; }

void InductionMachineParameters::validate() const {
  auto need = [](bool ok, const char* what) {
    if (!ok) throw std::invalid_argument(std::string("induction machine: ") + what);
  };
  need(R_s >= 0 && std::isfinite(R_s), "R_s must be >= 0");
  need(L_sigma_s > 0 && std::isfinite(L_sigma_s), "L_sigma_s must be > 0");
  need(L_m > 0 && std::isfinite(L_m), "L_m must be > 0");
  need(cages == 1 || cages == 2, "1 or 2 rotor cages");
  for (int k = 0; k < cages; ++k) {
    need(R_r[k] > 0 && std::isfinite(R_r[k]), "rotor resistances must be > 0");
    need(L_sigma_r[k] > 0 && std::isfinite(L_sigma_r[k]), "rotor leakage inductances must be > 0");
  }
  need(pole_pairs >= 1, "pole pairs must be >= 1");
  need(phase_voltage > 0 && std::isfinite(phase_voltage), "rated phase voltage must be > 0");
  need(frequency > 0 && std::isfinite(frequency), "rated frequency must be > 0");
}

std::string InductionMachineParameters::summary() const {
  char buf[400];
  int n = std::snprintf(buf, sizeof buf, "R_s = %.5g Ω, L_σs = %.5g H, L_m = %.5g H, R_r = %.5g Ω, L_σr = %.5g H",
                        R_s, L_sigma_s, L_m, R_r[0], L_sigma_r[0]);
  if (cages == 2 && n > 0 && n < int(sizeof buf))
    std::snprintf(buf + n, sizeof buf - n, ", R_r2 = %.5g Ω, L_σr2 = %.5g H", R_r[1], L_sigma_r[1]);
  return buf;
}

InductionMachineParameters InductionMachineParameters::fromScene(const InductionMotor& motor) {
  if (!motor.circuit.given()) throw std::invalid_argument("induction machine: the scene gives no motor.circuit");
  InductionMachineParameters m;
  m.R_s = motor.circuit.R_s;
  m.L_sigma_s = motor.circuit.L_sigma_s;
  m.L_m = motor.circuit.L_m;
  m.cages = motor.circuit.doubleCage() ? 2 : 1;
  m.R_r[0] = motor.circuit.R_r;
  m.L_sigma_r[0] = motor.circuit.L_sigma_r;
  m.R_r[1] = motor.circuit.R_r2;
  m.L_sigma_r[1] = motor.circuit.L_sigma_r2;
  m.pole_pairs = motor.pole_pairs;
  m.phase_voltage = motor.phaseVoltage();
  m.frequency = motor.frequency;
  m.validate();
  return m;
}

namespace {
using C = std::complex<double>;
const C kJ(0.0, 1.0);

// The magnetizing branch and the rotor branches in parallel at slip s: their admittance [S], and
// each rotor branch's Y_k = 1/(R_k/s + jX_k) = s/(R_k + j·s·X_k) into Y_r.
C airGapAdmittance(const InductionMachineParameters& m, double s, double w1, C* Y_r) {
  C Y = 1.0 / (kJ * w1 * m.L_m);
  for (int k = 0; k < m.cages; ++k) {
    Y_r[k] = s / (m.R_r[k] + kJ * s * w1 * m.L_sigma_r[k]);
    Y += Y_r[k];
  }
  return Y;
}

// Sums over the rotor branches at air-gap voltage E: Σ I_rk [A], Σ R_k·|I_rk|² [W],
// Σ L_σrk·|I_rk|² [J] and the air-gap power per phase [W].
struct RotorSums {
  C I_r = 0.0;
  double loss = 0.0, leakage_energy = 0.0, airgap = 0.0;
};

// Each rotor branch's current into r.I_r, and their sums.
RotorSums rotorCurrents(const InductionMachineParameters& m, C E, const C* Y_r, CircuitSolution& r) {
  RotorSums sum;
  for (int k = 0; k < m.cages; ++k) {
    r.I_r[k] = -E * Y_r[k];  // rotor current flows against the stator's (ψ = L_m(I_s + ΣI_r))
    sum.I_r += r.I_r[k];
    const double i2 = std::norm(r.I_r[k]);
    sum.loss += m.R_r[k] * i2;
    sum.leakage_energy += m.L_sigma_r[k] * i2;
    // P_ag per phase through branch k: |E|²·Re(Y_k) = |E|²·s·R_k/(R_k² + s²X_k²): finite at s = 0.
    sum.airgap += std::norm(E) * Y_r[k].real();
  }
  return sum;
}

}  // namespace

CircuitSolution solveCircuit(const InductionMachineParameters& m, double u, double w1, double omega_rotor) {
  CircuitSolution r;
  const double p = m.pole_pairs;
  const double s = (w1 - p * omega_rotor) / w1;
  r.slip = s;
  C Y_r[2];
  const C Y = airGapAdmittance(m, s, w1, Y_r);
  const C Z_s = m.R_s + kJ * w1 * m.L_sigma_s;
  const C Z = Z_s + 1.0 / Y;
  const C U(u, 0.0);
  r.I_s = U / Z;
  const C E = U - r.I_s * Z_s;  // air-gap voltage
  const RotorSums rotor = rotorCurrents(m, E, Y_r, r);
  const double is2 = std::norm(r.I_s);
  r.current = std::sqrt(is2);
  r.electrical_power = 3.0 * (U * std::conj(r.I_s)).real();
  r.airgap_power = 3.0 * rotor.airgap;
  r.torque = r.airgap_power / (w1 / p);
  r.copper_loss = 3.0 * (m.R_s * is2 + rotor.loss);
  r.magnetic_energy = 1.5 * (m.L_sigma_s * is2 + rotor.leakage_energy + m.L_m * std::norm(r.I_s + rotor.I_r));
  r.power_factor = r.current > 0 ? r.electrical_power / (3.0 * u * r.current) : 0.0;
  return r;
}

}  // namespace rollerdyn
