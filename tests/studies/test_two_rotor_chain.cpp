// Dyomin (two rotors): two rotors on an elastic chain. The Simbody simulation (with the project's
// ElasticCoupling element) against the closed-form response, corrected and as printed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>

#include "studies/TwoRotorChain.h"

namespace rollerdyn {
namespace {

TEST(TwoRotorChain, NaturalFrequencyAndDecrementEq9Eq10) {
  TwoRotorChainParams p;  // J1 73.6, J2 95, k 2e5, b 2000
  const TwoRotorChainDerived d = deriveChain(p);
  EXPECT_NEAR(d.p0, std::sqrt(2e5 * (73.6 + 95.0) / (73.6 * 95.0)), 1e-12);
  EXPECT_NEAR(d.delta1, 2000 * (73.6 + 95.0) / (2 * 73.6 * 95.0), 1e-12);
  EXPECT_NEAR(d.p1, std::sqrt(d.p0 * d.p0 - d.delta1 * d.delta1), 1e-12);
  // Balanced default: M_c = mean drive torque M1(π - 2α)/π, and Φ0 = that torque / k (eq. (11)).
  EXPECT_NEAR(d.Mc, 1000 * (M_PI - 0.6) / M_PI, 1e-12);
  EXPECT_NEAR(d.Phi0, d.Mc / 2e5, 1e-15);
}

// The exact response of eq. (7)-(8) from rest, written here independently of the closed form in
// physics/TwoRotorClosedForm.cpp: each forcing term (A_n·sin nωt + B_n·cos nωt)/J1 answers with
// Re[X_n·e^{inωt}], X_n = (B_n − i·A_n)/J1 / (p0² − n²ω² + 2i·δ1·nω) (complex arithmetic), plus
// Φ0 = (mean drive torque/J1 + M_c/J2)/p0², plus the underdamped homogeneous solution fitted to
// ψ(0) = ψ̇(0) = 0.
double exactTwist(const TwoRotorChainParams& p, double Mc, double t) {
  const double p0sq = p.k * (p.J1 + p.J2) / (p.J1 * p.J2), d1 = p.b * (p.J1 + p.J2) / (2 * p.J1 * p.J2);
  const double s = p.M1 / M_PI;
  const int ns[4] = {1, 2, 3, 5};
  const double A[4] = {2 * s, 0, 2 * s / 3, 2 * s / 5};
  const double B[4] = {s * std::sin(p.alpha), -s * std::sin(2 * p.alpha) / 2, s * std::sin(3 * p.alpha) / 3, 0};
  const double Phi0 = (p.M1 * (M_PI - 2 * p.alpha) / M_PI / p.J1 + Mc / p.J2) / p0sq;
  auto steady = [&](double tt, double& y, double& v) {
    y = Phi0;
    v = 0;
    for (int i = 0; i < 4; ++i) {
      const double nw = ns[i] * p.omega;
      const std::complex<double> X = std::complex<double>(B[i], -A[i]) / p.J1 / std::complex<double>(p0sq - nw * nw, 2 * d1 * nw);
      const std::complex<double> e = std::exp(std::complex<double>(0, nw * tt));
      y += (X * e).real();
      v += (std::complex<double>(0, nw) * X * e).real();
    }
  };
  double y, v, y0, v0;
  steady(t, y, v);
  steady(0.0, y0, v0);
  const double p1 = std::sqrt(p0sq - d1 * d1), h0 = -y0, h1 = -v0;
  return y + std::exp(-d1 * t) * (h0 * std::cos(p1 * t) + (h1 + d1 * h0) / p1 * std::sin(p1 * t));
}

TEST(TwoRotorChain, SimulationMatchesTheCorrectedClosedForm) {
  for (double omega : {10.47, 23.15 /* p0 ≈ 3ω: third-harmonic resonance */}) {
    TwoRotorChainParams p;
    p.omega = omega;
    const double Mc = p.M1 * (M_PI - 2 * p.alpha) / M_PI;  // the balanced default (Mc < 0 in the params)
    const Table sim = simulateTwoRotorChain(p);
    // Linear ODE, RKM at relative accuracy 1e-10 on states of O(1): the twist is a difference of
    // two angles of O(1 rad), so its error is ~1e-10 rad; the twist itself is ~1e-2 rad. 1e-8 rad
    // (1e-6 of the twist) bounds the integration error with margin and would catch any
    // modelling difference (a wrong sign or factor changes ψ by its own size).
    double worst = 0;
    for (const auto& row : sim.rows) worst = std::max(worst, std::abs(row[sim.index("psi")] - exactTwist(p, Mc, row[0])));
    EXPECT_LT(worst, 1e-8) << omega;  // transient (33)-(36) included
    // The study's own comparison says the same (its closed form is the project's one).
    const ChainComparison c = compareTwoRotorChain(p);
    EXPECT_LT(c.max_err_corrected_full, 1e-8) << omega;
    // Mean over the last period vs Φ0 (eq. (11)) written out: (M1(π − 2α)/(π·J1) + M_c/J2)/p0².
    const double p0sq = p.k * (p.J1 + p.J2) / (p.J1 * p.J2);
    EXPECT_NEAR(c.mean_sim, (p.M1 * (M_PI - 2 * p.alpha) / (M_PI * p.J1) + Mc / p.J2) / p0sq, 5e-3 * c.swing_sim) << omega;
  }
}

TEST(TwoRotorChain, PrintedAmplitudesDropTheSeriesFactors) {
  // Eq. (17), (18), (20), (21) use the numerator of the n = 1 term for n = 2, 3, 5: the printed
  // Ψ5 is 5 times, Ψ2 twice the amplitude of the forcing terms sin 5ωt/5 and sin 2α·cos 2ωt/2
  // of eq. (8)/(12) (n = 5 and n = 2 have a single term each, so the ratio is exact).
  TwoRotorChainParams p;
  const ChainHarmonics h = chainHarmonics(p);
  EXPECT_NEAR(h.printed[3] / h.corrected[3], 5.0, 1e-12);
  EXPECT_NEAR(h.printed[1] / h.corrected[1], 2.0, 1e-12);
  // Consequence measured against the simulation: the printed steady swing is far off.
  const ChainComparison c = compareTwoRotorChain(p);
  EXPECT_GT(c.swing_printed / c.swing_sim, 2.0);
  EXPECT_GT(c.max_err_printed_steady, 0.3 * c.swing_sim);
}

TEST(TwoRotorChain, ResonanceWarningNearHarmonics) {
  TwoRotorChainParams p;
  const double p0 = deriveChain(p).p0;
  p.omega = p0 / 3 * 1.02;  // p0 = 3ω/1.02: within 10 %
  p.t_end = 1.0;            // only the warning is looked at
  EXPECT_EQ(compareTwoRotorChain(p).resonance_warnings.size(), 1u);
  p.omega = p0 / 4;         // 4ω is not a harmonic of eq. (8); 3ω and 5ω are 25 % away
  EXPECT_TRUE(compareTwoRotorChain(p).resonance_warnings.empty());
}

}  // namespace
}  // namespace rollerdyn
