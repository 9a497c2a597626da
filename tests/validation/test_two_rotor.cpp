// Dyomin's two rotors on an elastic, damped link against the multibody ElasticCoupling element
// (src/multibody/ElasticCoupling.h), through the Simbody system of src/compare/TwoRotorCheck.h.
// The expected values are computed HERE from the paper's formulas (eq. (7)-(10), (14) and the
// steady response of a damped oscillator in complex form), not by the code under test.
//
// Parameters (Dyomin (two rotors) prints none; the Loveikin, Pochka, Romasevych (2018) drive of the validation report, loveikin2018Drive()):
// J1 = 0.766·9.8² kg·m², J2 = 100 kg·m², k = 2e5 N·m/rad, b = 2000 N·m·s/rad, M1 = 1000 N·m,
// α = 30°, M_c = M1(π - 2α)/π, ω = 10.68 rad/s.
//
// Tolerances:
//  * Free oscillation frequency: the crossings are located by cubic Hermite interpolation with
//    64 samples per period (error ~ (2π/64)^4/384 ≈ 2.5e-7 rad of phase per crossing, i.e.
//    ~4e-9 s, over 40 periods ≈ 3.7 s: ~1e-9 relative) and the integrator runs at accuracy
//    1e-10 (phase error per period ~1e-10, ~1e-8 over 40 periods). 1e-6 relative leaves two
//    orders of margin (observed 7e-9).
//  * Damping rate from the ratio of maxima 20 periods apart: the maxima come from Hermite
//    interpolation of ψ̇ with ψ̈; 1e-5 relative (observed 3e-7).
//  * Forced response: the harmonics are projected from 256 samples per period over whole
//    periods (exact for a trigonometric polynomial of degree < 128), after 2 s of settling
//    (transients e^{-δ1·2} = e^{-47}); what remains is integration error, ~1e-9 of the signal at
//    accuracy 1e-10. 1e-6 of the first harmonic's amplitude (observed ~1e-9).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "compare/TwoRotorCheck.h"

using namespace rollerdyn::validation;

namespace {

// Steady response of ψ̈ + 2δ1ψ̇ + p0²ψ = F(t), written independently of TwoRotorCheck.cpp in
// complex form: the forcing (A·sin nωt + B·cos nωt)/J1 = Re[(B - i·A)/J1 · e^{inωt}] gives
// ψ_n = Re[X·e^{inωt}] = a·sin nωt + b·cos nωt with X = (B - i·A)/J1 / (p0² - n²ω² + 2i·δ1·nω),
// b = Re X, a = -Im X.
void expectedHarmonic(const TwoRotorParameters& p, int n, double& a, double& b) {
  const double p0sq = p.k * (p.J1 + p.J2) / (p.J1 * p.J2);  // eq. (10)
  const double d1 = p.b * (p.J1 + p.J2) / (2.0 * p.J1 * p.J2);  // eq. (9)
  // Fourier coefficients of M(t), eq. (8) times J1
  double A = 0, B = 0;
  const double s = p.M1 / M_PI;
  if (n == 1) { A = 2 * s; B = s * std::sin(p.alpha); }
  if (n == 2) { A = 0; B = -s * std::sin(2 * p.alpha) / 2; }
  if (n == 3) { A = 2 * s / 3; B = s * std::sin(3 * p.alpha) / 3; }
  if (n == 5) { A = 2 * s / 5; B = 0; }
  const std::complex<double> X = std::complex<double>(B, -A) / p.J1 /
                                 std::complex<double>(p0sq - n * n * p.omega * p.omega, 2 * d1 * n * p.omega);
  b = X.real();
  a = -X.imag();
}

}  // namespace

TEST(TwoRotor, FreeOscillationAtNaturalFrequencyEq10) {
  TwoRotorParameters p = loveikin2018Drive();
  p.b = 0.0;
  const double p0 = std::sqrt(p.k * (p.J1 + p.J2) / (p.J1 * p.J2));  // Dyomin (two rotors), eq. (10)
  const FreeOscillationMeasurement m = measureFreeOscillation(p, 0.01, 40, 64, 1e-10);
  EXPECT_EQ(m.periods, 40);
  EXPECT_NEAR(m.frequency / p0, 1.0, 1e-6);
  EXPECT_NEAR(m.decay_rate, 0.0, 1e-6 * p0);  // no damping, no decay
}

TEST(TwoRotor, DampedFrequencyAndDecayEq9Eq14) {
  TwoRotorParameters p = loveikin2018Drive();
  p.b = 200.0;
  const double p0sq = p.k * (p.J1 + p.J2) / (p.J1 * p.J2);
  const double d1 = p.b * (p.J1 + p.J2) / (2.0 * p.J1 * p.J2);  // eq. (9)
  const double p1 = std::sqrt(p0sq - d1 * d1);                  // eq. (14)
  const FreeOscillationMeasurement m = measureFreeOscillation(p, 0.01, 20, 64, 1e-10);
  EXPECT_NEAR(m.frequency / p1, 1.0, 1e-6);
  EXPECT_NEAR(m.decay_rate / d1, 1.0, 1e-5);
  EXPECT_NEAR(m.natural_frequency / std::sqrt(p0sq), 1.0, 1e-6);
}

TEST(TwoRotor, SteadyHarmonicResponseEq7Eq8) {
  for (double omega : {10.68, 0.0}) {
    TwoRotorParameters p = loveikin2018Drive();
    // second case: ω = p0/3, the third harmonic at resonance (the paper's warning after (21))
    if (omega == 0.0) p.omega = std::sqrt(p.k * (p.J1 + p.J2) / (p.J1 * p.J2)) / 3.0;
    const ForcedResponseMeasurement m = measureForcedResponse(p, 2.0, 4, 256, 1e-10);
    double a1, b1;
    expectedHarmonic(p, 1, a1, b1);
    const double scale = std::hypot(a1, b1);
    ASSERT_EQ(m.harmonics.size(), 4u);
    for (const auto& h : m.harmonics) {
      double a, b;
      expectedHarmonic(p, h.n, a, b);
      EXPECT_NEAR(h.a_sin, a, 1e-6 * scale) << "n = " << h.n << ", omega = " << p.omega;
      EXPECT_NEAR(h.b_cos, b, 1e-6 * scale) << "n = " << h.n << ", omega = " << p.omega;
    }
    // mean twist, eq. (11)/(42)-(43): M1(π - 2α)/(π·J1·p0²) + M_c/(J2·p0²) = M_c/k here
    EXPECT_NEAR(m.mean_twist, p.Mc / p.k, 1e-6 * scale);
  }
}

TEST(TwoRotor, ClosedFormAgreesWithComplexArithmeticAndRecordsThePrintedFormulas) {
  const TwoRotorParameters p = loveikin2018Drive();
  const double p0 = std::sqrt(p.k * (p.J1 + p.J2) / (p.J1 * p.J2));
  const double d1 = p.b * (p.J1 + p.J2) / (2.0 * p.J1 * p.J2);
  for (const HarmonicResponse& h : closedFormResponse(p)) {
    double a, b;
    expectedHarmonic(p, h.n, a, b);
    EXPECT_NEAR(h.a_sin, a, 1e-12 * std::hypot(a, b)) << h.n;
    EXPECT_NEAR(h.b_cos, b, 1e-12 * std::hypot(a, b)) << h.n;
    if (h.n == 5) {
      // eq. (18) as printed, 2M1/(πJ1·D5), is 5 times the response to the sin 5ωt/5 term of (8).
      const double D5 = std::sqrt(std::pow(p0 * p0 - 25 * p.omega * p.omega, 2) + 100 * d1 * d1 * p.omega * p.omega);
      EXPECT_NEAR(h.amplitude_printed, 2 * p.M1 / (M_PI * p.J1 * D5), 1e-15);
      EXPECT_NEAR(h.amplitude_printed / h.amplitude, 5.0, 1e-12);
    }
  }
}
