// Closed-form torsional response of two rotors on an elastic, damped link, Dyomin (two rotors),
// eq. (1)-(43): the one copy used by the validation suite's analytic check and by the `chain`
// study.
//
//   J1·φ̈1 + b(φ̇1 - φ̇2) + k(φ1 - φ2) = M(t)          (1)
//   J2·φ̈2 - b(φ̇1 - φ̇2) - k(φ1 - φ2) = -M_c          (2)
//   ψ = φ1 - φ2:  ψ̈ + 2δ1·ψ̇ + p0²·ψ = M(t)/J1 + M_c/J2  (7)
//   δ1 = b(J1 + J2)/(2·J1·J2)   (9),   p0 = √(k(J1 + J2)/(J1·J2))   (10),   p1 = √(p0² - δ1²)  (14)
//
// The drive torque is the paper's truncated series, eq. (8) multiplied by J1:
//   M(t) = M1(π - 2α)/π + (2M1/π)·[sin ωt + sin 3ωt/3 + sin 5ωt/5]
//          + (M1/π)·[sin α·cos ωt - sin 2α·cos 2ωt/2 + sin 3α·cos 3ωt/3]
// so the exact steady response is a constant plus harmonics n = 1, 2, 3, 5: each forcing term
// F·sin(nωt) or F·cos(nωt) answers with (F/D_n)·sin/cos(nωt - ξ_n),
//   D_n = √((p0² - n²ω²)² + 4δ1²n²ω²),  ξ_n = atan2(2δ1·nω, p0² - n²ω²)  (22)-(25),
//   Φ0 = M1(π - 2α)/(π·J1·p0²) + M_c/(J2·p0²)  (11), (42)-(43).
// The paper as printed differs: eq. (17), (18), (20), (21) drop the 1/n of the series (8) (and
// the 1/2 of the cos 2ωt term), eq. (15) writes the cosine responses as cos(nωt + ξ_n) where a
// damped oscillator lags, cos(nωt - ξ_n), which (27)-(28) then combine, and its arctg (atan)
// loses the quadrant above a resonance. Both are provided; the exact one is what simulations are
// held to.
//
// Naming: Dyomin's k is the STIFFNESS and b the damping; in the scenes (Loveikin, Pochka,
// Romasevych (2018)) the same quantities are coupling.stiffness c and coupling.damping k.
#pragma once

#include <vector>

namespace rollerdyn {

struct TwoRotorParameters {
  double J1 = 0;     // driving rotor inertia [kg·m²]
  double J2 = 0;     // driven rotor inertia [kg·m²]
  double k = 0;      // link stiffness [N·m/rad]
  double b = 0;      // link damping [N·m·s/rad]
  double M1 = 0;     // drive torque level of eq. (8) [N·m]
  double alpha = 0;  // angle parameter α of eq. (8) [rad]
  double Mc = 0;     // resisting torque on the driven rotor [N·m]
  double omega = 0;  // fundamental angular frequency ω of M(t) [rad/s]
};

double naturalFrequency(const TwoRotorParameters& p);   // p0, eq. (10) [rad/s]
double dampingRate(const TwoRotorParameters& p);        // δ1, eq. (9) [1/s]
double dampedFrequency(const TwoRotorParameters& p);    // p1, eq. (14) [rad/s]; NaN when δ1 >= p0
double meanTwist(const TwoRotorParameters& p);          // Φ0, eq. (11), (42)-(43) [rad]
double balancedResistingTorque(const TwoRotorParameters& p);  // the mean drive torque M1(π - 2α)/π [N·m]
double driveTorque(const TwoRotorParameters& p, double t);    // M(t), eq. (8)·J1 [N·m]

// One harmonic of the steady twist response, ψ_n(t) = a_sin·sin nωt + b_cos·cos nωt [rad].
struct HarmonicResponse {
  int n = 0;
  double a_sin = 0, b_cos = 0;   // exact [rad]
  double amplitude = 0;          // √(a² + b²) [rad]
  // The paper as printed: per-harmonic amplitude from eq. (16)-(21) combined by (27)-(28)
  // (n = 1: Ψ1 of (27); n = 2: Ψ2 of (20); n = 3: Ψ3 of (28); n = 5: Ψ5 of (18)) [rad].
  double amplitude_printed = 0;
  double phase_lag = 0;          // ξ_n [rad]
};

// Exact steady response of eq. (7) to the drive of eq. (8), harmonics n = 1, 2, 3, 5, with the
// paper's printed amplitudes beside them.
std::vector<HarmonicResponse> closedFormResponse(const TwoRotorParameters& p);

// Twist ψ(t) [rad] from rest (ψ(0) = ψ̇(0) = 0, eq. (33)); with_transient = false gives Φ0 plus
// the steady harmonics.
//   exact:   the steady harmonics above plus the homogeneous solution fitted to the start
//            (under-, critically or over-damped);
//   printed: eq. (26) and (36) as printed (NaN with the transient when δ1 >= p0: (13)-(14)
//            assume an oscillating transient).
double twistExact(const TwoRotorParameters& p, double t, bool with_transient);
double twistPrinted(const TwoRotorParameters& p, double t, bool with_transient);

}  // namespace rollerdyn
