// Two rotors on an elastic, damped chain (Dyomin (two rotors), Dyomin: drive of a pipe-coating machine):
//   J1·φ̈1 + b(φ̇1 - φ̇2) + k(φ1 - φ2) = M(t),   J2·φ̈2 - b(φ̇1 - φ̇2) - k(φ1 - φ2) = -M_c   (1)-(2)
// The twist ψ = φ1 - φ2 obeys ψ̈ + 2δ1·ψ̇ + p0²·ψ = M(t)/J1 + M_c/J2 (7) with
// δ1 = b(J1 + J2)/(2J1J2) (9) and p0 = sqrt(k(J1 + J2)/(J1J2)) (10). The drive torque is the
// three-term series the paper integrates, eq. (8):
//   M(t) = M1(π - 2α)/π + (2M1/π)[sin ωt + sin 3ωt/3 + sin 5ωt/5]
//          + (M1/π)[sin α·cos ωt - sin 2α·cos 2ωt/2 + sin 3α·cos 3ωt/3]
// and the closed-form response is eq. (11), (13)-(36): mean twist Φ0 (11), (43), steady
// harmonics (15)-(30), transient from ψ(0) = ψ̇(0) = 0 (33)-(36).
//
// Both closed forms are those of physics/TwoRotorClosedForm.h (the one copy, shared with the
// validation suite's analytic check):
//   printed   - eq. (16)-(30), (34)-(36) exactly as printed (arctg as printed, i.e. atan);
//   corrected - the exact steady and transient solution of eq. (12) for the same forcing: each
//               forcing term F·sin(nωt) or F·cos(nωt) answers with (F/D_n)·sin/cos(nωt - ξ_n),
//               D_n = sqrt((p0² - n²ω²)² + 4δ1²n²ω²), ξ_n = atan2(2δ1·nω, p0² - n²ω²).
// The two differ: (17), (18), (20), (21) drop the 1/n (and the 1/2 of the cos 2ωt term) of the
// series (8); (15) writes the cosine terms as cos(nωt + ξ) where the response lags, cos(nωt - ξ),
// which is what (27)-(28) then combine; and atan loses the quadrant above a resonance. The
// simulation (Simbody: two Pin rotors, the project's ElasticCoupling force element, the torque
// M(t) and M_c as a custom force) decides between them.
#pragma once

#include <string>
#include <vector>

#include "io/Table.h"
#include "physics/TwoRotorClosedForm.h"

namespace rollerdyn {

struct TwoRotorChainParams {
  double J1 = 73.6;       // driving rotor (sprocket) [kg·m²]
  double J2 = 95.0;       // driven rotor [kg·m²]
  double k = 2.0e5;       // chain torsional stiffness [N·m/rad]
  double b = 2000.0;      // chain damping [N·m·s/rad]
  double M1 = 1000.0;     // drive torque amplitude [N·m]
  double alpha = 0.3;     // angle α of the series (8) [rad]
  double Mc = -1.0;       // resisting torque [N·m]; < 0: the mean drive torque M1(π - 2α)/π
  double omega = 10.47;   // frequency ω of the drive torque [rad/s]
  double t_end = 0.0;     // simulated time [s]; 0: until e^{-δ1·t} < 1e-9, at least 10 periods
  double accuracy = 1e-10;  // integrator relative accuracy
  double output_step = 0.0; // [s]; 0: 1/100 of the shortest of 2π/(5ω) and 2π/p0
};

struct TwoRotorChainDerived {
  double delta1, p0, p1;  // eq. (9), (10), (14) (p1 = NaN when δ1 >= p0: no oscillating transient)
  double Mc;              // resisting torque used [N·m]
  double Phi0;            // mean twist, eq. (11)/(43) [rad]
  double t_end, output_step;
};
TwoRotorChainDerived deriveChain(const TwoRotorChainParams& p);

// The study's parameters as the closed form's, with the resisting torque resolved.
TwoRotorParameters closedFormParameters(const TwoRotorChainParams& p);

// M(t) of eq. (8) [N·m].
double chainDriveTorque(const TwoRotorChainParams& p, double t);

// Twist ψ(t) [rad] from the closed forms; with_transient = false gives Φ0 + steady harmonics.
double chainTwistCorrected(const TwoRotorChainParams& p, double t, bool with_transient);
double chainTwistPrinted(const TwoRotorChainParams& p, double t, bool with_transient);

// Amplitudes of the steady harmonics n = 1, 2, 3, 5 [rad]: printed Ψ1, Ψ2, Ψ3, Ψ5 (eq. (16)-(21),
// (27)-(28)) and the corrected ones (amplitude of the whole n-th harmonic of ψ*).
struct ChainHarmonics {
  double printed[4], corrected[4];
};
ChainHarmonics chainHarmonics(const TwoRotorChainParams& p);

// Simbody simulation from rest (eq. (33), (53)); columns t, psi, psi_rate, phi1, phi2, omega1,
// omega2, chain_torque (k·ψ + b·ψ̇, from ElasticCoupling::torque), drive_torque.
Table simulateTwoRotorChain(const TwoRotorChainParams& p);

struct ChainComparison {
  TwoRotorChainDerived derived;
  ChainHarmonics harmonics;
  Table table;  // t, psi_sim, psi_corrected, psi_printed (with transient)
  // Over the last period 2π/ω of the run (steady state):
  double swing_sim = 0, swing_corrected = 0, swing_printed = 0;  // max - min of ψ [rad]
  double mean_sim = 0, mean_closed = 0;                          // mean ψ vs Φ0 [rad]
  double max_err_corrected_steady = 0, max_err_printed_steady = 0;   // max |ψ_sim - ψ_closed| [rad]
  // Over the whole run, the full solution (36) with its transient:
  double max_err_corrected_full = 0, max_err_printed_full = 0;
  std::vector<std::string> resonance_warnings;  // p0 within 10 % of ω, 2ω, 3ω, 5ω
};
ChainComparison compareTwoRotorChain(const TwoRotorChainParams& p);

}  // namespace rollerdyn
