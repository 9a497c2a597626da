// Analytic check of the multibody ElasticCoupling element (src/multibody/ElasticCoupling.h)
// against the closed-form torsional response of two rotors on an elastic, damped link,
// Dyomin (two rotors) (second paper, Dyomin Yu.M.), eq. (1)-(36):
//
//   J1·φ̈1 + b(φ̇1 - φ̇2) + k(φ1 - φ2) = M(t)          (1)
//   J2·φ̈2 - b(φ̇1 - φ̇2) - k(φ1 - φ2) = -M_c          (2)
//   ψ = φ1 - φ2:  ψ̈ + 2δ1·ψ̇ + p0²·ψ = M(t)/J1 + M_c/J2  (7)
//   δ1 = b(J1 + J2)/(2·J1·J2)   (9),   p0 = √(k(J1 + J2)/(J1·J2))   (10),   p1 = √(p0² - δ1²)  (14)
//
// The drive torque is the paper's truncated series, eq. (8) multiplied by J1:
//   M(t) = M1(π - 2α)/π + (2M1/π)·[sin ωt + sin 3ωt/3 + sin 5ωt/5]
//          + (M1/π)·[sin α·cos ωt - sin 2α·cos 2ωt/2 + sin 3α·cos 3ωt/3]
// so the steady response is exactly a constant plus harmonics n = 1, 2, 3, 5:
//   ψ* = Φ0 + Σ_n [A_n·sin(nωt - ξ_n) + B_n·cos(nωt - ξ_n)] / (J1·D_n),
//   D_n = √((p0² - n²ω²)² + 4δ1²n²ω²),  tan ξ_n = 2δ1·nω/(p0² - n²ω²)  (22)-(25),
//   Φ0 = M1(π - 2α)/(π·J1·p0²) + M_c/(J2·p0²)  (42)-(43),
// where A_n, B_n are the sin/cos coefficients of M(t) above. For n = 1 the amplitudes are the
// paper's eq. (16) and (19). NOTE, found while building this check: eq. (17), (18), (20), (21)
// as printed drop the 1/n of the series (8) (e.g. Ψ31 = 2M1/(πJ1·D3), where (8) forcing
// sin 3ωt/3 gives 2M1/(3πJ1·D3)), and eq. (15) writes the cosine responses as cos(nωt + ξ_n)
// where the steady response of a damped oscillator lags, cos(nωt - ξ_n); eq. (27)-(28) inherit
// that sign. Both are reported (closedFormResponse keeps the paper-as-printed amplitudes
// beside the exact ones); the exact solution is what the simulation is held to.
//
// Naming: Dyomin's k is the STIFFNESS and b the damping; in the scenes (Loveikin, Pochka, Romasevych (2018)) the same
// quantities are coupling.stiffness c and coupling.damping k.
#pragma once

#include <vector>

namespace rollerdyn::validation {

struct TwoRotorParameters {
  double J1 = 0;     // driving rotor ("equivalent sprocket") inertia [kg·m²]
  double J2 = 0;     // driven rotor inertia [kg·m²]
  double k = 0;      // link stiffness [N·m/rad]
  double b = 0;      // link damping [N·m·s/rad]
  double M1 = 0;     // drive torque level of eq. (8) [N·m]
  double alpha = 0;  // angle parameter α of eq. (8) [rad]
  double Mc = 0;     // resisting torque on the driven rotor [N·m]
  double omega = 0;  // fundamental angular frequency ω of M(t) [rad/s]
};

// The rotors of the validation suite's check (and of its tests). Dyomin (two rotors) gives no numbers; they
// are the Loveikin, Pochka, Romasevych (2018) drive (ASSUMED): J1 = the motor side (J_p + J_m + J_red)·u² = 0.766·9.8²
// kg·m², J2 = 100 kg·m² (about the mean crank-side reduced inertia of four carts), k = c = 2e5
// N·m/rad, b = 2000 N·m·s/rad (Table 1's smaller damping), M1 = 1000 N·m, α = 30°, M_c = the
// mean drive torque M1(π - 2α)/π so the rotors keep a steady mean speed, ω = 10.68 rad/s (the
// Loveikin, Pochka, Romasevych (2018) crank speed).
TwoRotorParameters seed000Drive();

double naturalFrequency(const TwoRotorParameters& p);   // p0, eq. (10) [rad/s]
double dampingRate(const TwoRotorParameters& p);        // δ1, eq. (9) [1/s]
double dampedFrequency(const TwoRotorParameters& p);    // p1, eq. (14) [rad/s]
double meanTwist(const TwoRotorParameters& p);          // Φ0, eq. (42)-(43) [rad]
double driveTorque(const TwoRotorParameters& p, double t);  // M(t), eq. (8)·J1 [N·m]

// One harmonic of the steady twist response, ψ_n(t) = a_sin·sin nωt + b_cos·cos nωt [rad].
struct HarmonicResponse {
  int n = 0;
  double a_sin = 0, b_cos = 0;
  double amplitude = 0;          // √(a² + b²)
  // The paper as printed: per-harmonic amplitude from eq. (16)-(21) combined by (27)-(28)
  // (n = 1: Ψ1 of (27); n = 2: Ψ2 of (20); n = 3: Ψ3 of (28); n = 5: Ψ5 of (18)).
  double amplitude_printed = 0;
  double phase_lag = 0;          // ξ_n [rad]
};

// Exact steady response of eq. (7) to the drive of eq. (8), harmonics n = 1, 2, 3, 5.
std::vector<HarmonicResponse> closedFormResponse(const TwoRotorParameters& p);

// The Simbody system of the check: two Pin rotors on ground, the ElasticCoupling element
// between them, M(t) on rotor 1, -M_c on rotor 2.
struct ForcedResponseMeasurement {
  double mean_twist = 0;                       // [rad]
  std::vector<HarmonicResponse> harmonics;     // n = 1, 2, 3, 5 measured (amplitude_printed unused)
  double settle_time = 0;                      // time skipped before measuring [s]
  int periods = 0;                             // whole periods of ω measured
  int samples_per_period = 0;
  std::vector<double> t, twist;                // the measured samples (for plots)
};
// Integrates from rest (ψ = 0) for settle_time (transients decay as e^{-δ1·t}), then samples
// ψ at `samples_per_period` equally spaced times per period over `periods` periods and
// projects on 1, sin nωt, cos nωt (discrete orthogonality: exact for the harmonics n <
// samples_per_period/2 of a periodic signal).
ForcedResponseMeasurement measureForcedResponse(const TwoRotorParameters& p, double settle_time,
                                                int periods, int samples_per_period, double accuracy);

struct FreeOscillationMeasurement {
  double initial_twist = 0;        // ψ(0) [rad], rotors at rest, M = M_c = 0
  double frequency = 0;            // measured angular frequency of the oscillation [rad/s]
  double decay_rate = 0;           // measured δ from the ratio of extremes one period apart [1/s]
  double natural_frequency = 0;    // √(frequency² + decay_rate²): measured p0 [rad/s]
  int periods = 0;                 // whole periods between the first and last crossing used
  std::vector<double> t, twist;    // samples (for plots)
};
// Free oscillation from an initial twist: the frequency from upward zero crossings of ψ
// (located by cubic Hermite interpolation with ψ̇ between samples), the decay from successive
// maxima (zeros of ψ̇, Hermite with ψ̈) one period apart.
FreeOscillationMeasurement measureFreeOscillation(const TwoRotorParameters& p, double initial_twist,
                                                  int periods, int samples_per_period, double accuracy);

}  // namespace rollerdyn::validation
