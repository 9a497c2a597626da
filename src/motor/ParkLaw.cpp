#include "motor/ParkLaw.h"

#include <cmath>
#include <complex>

#include <Eigen/Eigenvalues>

namespace rollerdyn {

namespace {
using C = std::complex<double>;
const C kJ(0.0, 1.0);

// The evaluation's steps, file-local so that they inline into the law's hot evaluate().

// u_s = √2·U_ph·(U/U_n)·e^{j·phase}, the stator voltage's space phasor [V].
C statorVoltage(const InductionMachineParameters& m, const SupplyState& supply) {
  return std::sqrt(2.0) * m.phase_voltage * supply.voltage * std::polar(1.0, supply.phase);
}

// Breaker closed: the n windings' currents i = Γ·ψ [A].
void connectedCurrents(const Eigen::Matrix3d& Gamma, int n, const C* psi, C* i) {
  for (int a = 0; a < n; ++a) {
    i[a] = 0.0;
    for (int c = 0; c < n; ++c) i[a] += Gamma(a, c) * psi[c];
  }
}

// Breaker open: i_s = 0, and the nr rotor currents i_r = Γ_rr·ψ_r from the rotor fluxes alone [A].
void openStatorCurrents(const Eigen::Matrix2d& Gamma_rr, int nr, const C* psi, C* i) {
  i[0] = 0.0;
  for (int k = 0; k < nr; ++k) {
    i[1 + k] = 0.0;
    for (int c = 0; c < nr; ++c) i[1 + k] += Gamma_rr(k, c) * psi[1 + c];
  }
}

// The voltage equations solved for dψ/dt [Wb/s] into xdot (re, im per winding), wk the frame's and
// wr the rotor windings' angular frequency [rad/s]; open, the stator flux follows the rotor's.
void fluxDerivatives(const InductionMachineParameters& m, const Eigen::Matrix2d& Gamma_rr, int nr, bool connected,
                     C u_s, double wk, double wr, const C* psi, const C* i, double* xdot) {
  C dpsi[3];
  for (int k = 0; k < nr; ++k) dpsi[1 + k] = -m.R_r[k] * i[1 + k] - kJ * wr * psi[1 + k];
  if (connected) {
    dpsi[0] = u_s - m.R_s * i[0] - kJ * wk * psi[0];
  } else {
    // ψ_s = L_m·Σ i_rk stays on that relation: dψ_s/dt = L_m·Σ_k (Γ_rr·dψ_r/dt)_k.
    dpsi[0] = 0.0;
    for (int k = 0; k < nr; ++k)
      for (int c = 0; c < nr; ++c) dpsi[0] += m.L_m * Gamma_rr(k, c) * dpsi[1 + c];
  }
  for (int a = 0; a < 1 + nr; ++a) {
    xdot[2 * a] = dpsi[a].real();
    xdot[2 * a + 1] = dpsi[a].imag();
  }
}

// M = (3/2)·p·Im(ψ_s*·i_s) [N·m].
double airGapTorque(const InductionMachineParameters& m, const C* psi, const C* i) {
  return 1.5 * m.pole_pairs * (std::conj(psi[0]) * i[0]).imag();
}

// The stator current's rms value |i_s|/√2 [A].
double statorCurrent(const C* i) { return std::abs(i[0]) / std::sqrt(2.0); }

// Torque, stator current, electrical power, copper loss and magnetic energy from ψ and i.
void powersAndTorque(const InductionMachineParameters& m, int nr, C u_s, const C* psi, const C* i,
                     MotorEvaluation& out) {
  out = MotorEvaluation{};
  out.torque = airGapTorque(m, psi, i);
  out.stator_current = statorCurrent(i);
  out.electrical_power = 1.5 * (u_s * std::conj(i[0])).real();
  double loss = m.R_s * std::norm(i[0]), energy = (std::conj(psi[0]) * i[0]).real();
  for (int k = 0; k < nr; ++k) {
    loss += m.R_r[k] * std::norm(i[1 + k]);
    energy += (std::conj(psi[1 + k]) * i[1 + k]).real();
  }
  out.copper_loss = 1.5 * loss;
  out.magnetic_energy = 0.75 * energy;
}

}  // namespace

ParkLaw::ParkLaw(const InductionMachineParameters& machine) : machine_(machine) {
  machine_.validate();
  windings_ = 1 + machine_.cages;
  const int n = windings_;
  L_.setZero();
  Gamma_.setZero();
  Gamma_rr_.setZero();
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) L_(a, b) = machine_.L_m;
  L_(0, 0) += machine_.L_sigma_s;
  for (int k = 0; k < machine_.cages; ++k) L_(1 + k, 1 + k) += machine_.L_sigma_r[k];
  Gamma_.topLeftCorner(n, n) = L_.topLeftCorner(n, n).inverse();
  const int nr = machine_.cages;
  Gamma_rr_.topLeftCorner(nr, nr) = L_.block(1, 1, nr, nr).inverse();
  // Stiffness: the decay rates of the fluxes, eigenvalues of R·Γ (the rotation terms add only
  // oscillation).
  Eigen::MatrixXd RG = Gamma_.topLeftCorner(n, n);
  RG.row(0) *= machine_.R_s;
  for (int k = 0; k < nr; ++k) RG.row(1 + k) *= machine_.R_r[k];
  double rate = 0;
  for (const auto& ev : RG.eigenvalues()) rate = std::max(rate, std::abs(ev.real()));
  fastest_ = rate > 0 ? 1.0 / rate : std::numeric_limits<double>::infinity();
}

std::string ParkLaw::description() const {
  return machine_.cages == 2 ? "space-phasor (Park) machine, double cage"
                             : "space-phasor (Park) machine, single cage";
}

std::vector<std::string> ParkLaw::stateNames() const {
  if (machine_.cages == 1) return {"psi_sd[Wb]", "psi_sq[Wb]", "psi_rd[Wb]", "psi_rq[Wb]"};
  return {"psi_sd[Wb]", "psi_sq[Wb]", "psi_r1d[Wb]", "psi_r1q[Wb]", "psi_r2d[Wb]", "psi_r2q[Wb]"};
}

std::vector<double> ParkLaw::stateScales() const {
  // Rated stator flux amplitude √2·U_ph/ω1: every flux of the machine is of that order.
  const double psi = std::sqrt(2.0) * machine_.phase_voltage / machine_.supplyAngularFrequency();
  return std::vector<double>(2 * windings_, psi);
}

void ParkLaw::initialState(const SupplyState& supply, double omega_rotor, bool steady, double* x) const {
  const int n = windings_;
  for (int i = 0; i < 2 * n; ++i) x[i] = 0.0;
  if (!steady || !supply.connected) return;
  // Constant fluxes: (R + j·Ω·L)·i = (u_s, 0, ...), Ω = diag(ω_k, ω_k − pω_r, ...); ψ = L·i.
  const double wk = machine_.supplyAngularFrequency() * supply.frequency;
  const double wr = wk - machine_.pole_pairs * omega_rotor;
  Eigen::Matrix3cd A = Eigen::Matrix3cd::Zero();
  Eigen::Vector3cd b = Eigen::Vector3cd::Zero();
  for (int a = 0; a < n; ++a) {
    const double w = a == 0 ? wk : wr;
    for (int c = 0; c < n; ++c) A(a, c) = kJ * w * L_(a, c);
    A(a, a) += a == 0 ? machine_.R_s : machine_.R_r[a - 1];
  }
  b(0) = statorVoltage(machine_, supply);
  const Eigen::VectorXcd i = A.topLeftCorner(n, n).partialPivLu().solve(b.head(n));
  const Eigen::VectorXcd psi = L_.topLeftCorner(n, n).cast<C>() * i;
  for (int a = 0; a < n; ++a) {
    x[2 * a] = psi(a).real();
    x[2 * a + 1] = psi(a).imag();
  }
}

void ParkLaw::evaluate(const SupplyState& supply, double omega_rotor, const double* x, MotorEvaluation& out,
                       double* xdot) const {
  const int n = windings_, nr = machine_.cages;
  C psi[3], i[3];
  for (int a = 0; a < n; ++a) psi[a] = C(x[2 * a], x[2 * a + 1]);
  const double wk = machine_.supplyAngularFrequency() * supply.frequency;
  const double wr = wk - machine_.pole_pairs * omega_rotor;
  C u_s = 0.0;
  if (supply.connected) {
    connectedCurrents(Gamma_, n, psi, i);
    u_s = statorVoltage(machine_, supply);
  } else {
    openStatorCurrents(Gamma_rr_, nr, psi, i);
  }
  if (xdot) fluxDerivatives(machine_, Gamma_rr_, nr, supply.connected, u_s, wk, wr, psi, i, xdot);
  powersAndTorque(machine_, nr, u_s, psi, i, out);
}

void ParkLaw::switchStates(const SupplyState& before, const SupplyState& after, double, double* x) const {
  if (!(before.connected && !after.connected)) return;  // fluxes are continuous otherwise
  // The breaker forces i_s to zero; the rotor fluxes are continuous (their windings stay
  // closed), so the rotor currents become Γ_rr·ψ_r and the stator flux L_m·Σ i_rk.
  const int nr = machine_.cages;
  C psi_s = 0.0;
  for (int k = 0; k < nr; ++k)
    for (int c = 0; c < nr; ++c) psi_s += machine_.L_m * Gamma_rr_(k, c) * C(x[2 + 2 * c], x[3 + 2 * c]);
  x[0] = psi_s.real();
  x[1] = psi_s.imag();
}

// The steady torque and current need ψ_s and i_s only: computed as evaluate() computes them, so
// the start-up's many calls do not pay for the rest of the evaluation.
void ParkLaw::steadyFluxesAndCurrents(const SupplyState& supply, double omega_rotor, C* psi, C* i) const {
  double x[6];
  initialState(supply, omega_rotor, true, x);
  for (int a = 0; a < windings_; ++a) psi[a] = C(x[2 * a], x[2 * a + 1]);
  connectedCurrents(Gamma_, windings_, psi, i);
}

double ParkLaw::steadyTorque(const SupplyState& supply, double omega_rotor) const {
  if (!supply.connected) return 0.0;
  C psi[3], i[3];
  steadyFluxesAndCurrents(supply, omega_rotor, psi, i);
  return airGapTorque(machine_, psi, i);
}

double ParkLaw::steadyCurrent(const SupplyState& supply, double omega_rotor) const {
  if (!supply.connected) return 0.0;
  C psi[3], i[3];
  steadyFluxesAndCurrents(supply, omega_rotor, psi, i);
  return statorCurrent(i);
}

}  // namespace rollerdyn
