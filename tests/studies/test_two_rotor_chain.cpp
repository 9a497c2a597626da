// Dyomin (two rotors): two rotors on an elastic chain. The Simbody simulation (with the project's
// ElasticCoupling element) against the closed-form response, corrected and as printed.
#include <gtest/gtest.h>

#include <cmath>

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

TEST(TwoRotorChain, SimulationMatchesTheCorrectedClosedForm) {
  for (double omega : {10.47, 23.15 /* p0 ≈ 3ω: third-harmonic resonance */}) {
    TwoRotorChainParams p;
    p.omega = omega;
    const ChainComparison c = compareTwoRotorChain(p);
    // Linear ODE, RKM at relative accuracy 1e-10 on states of O(1): the twist is a difference of
    // two angles of O(1 rad), so its error is ~1e-10 rad; the twist itself is ~1e-2 rad. 1e-8 rad
    // (1e-6 of the twist) bounds the integration error with margin and would catch any
    // modelling difference (a wrong sign or factor changes ψ by its own size).
    EXPECT_LT(c.max_err_corrected_full, 1e-8) << omega;   // transient (33)-(36) included
    EXPECT_LT(c.max_err_corrected_steady, 1e-8) << omega;
    EXPECT_NEAR(c.swing_sim, c.swing_corrected, 1e-8) << omega;
    // Mean over the last period vs Φ0 (eq. (11)): the sample mean over a grid that does not
    // close the period exactly errs by ≤ (output step / period)·swing ~ 3e-3·swing.
    EXPECT_NEAR(c.mean_sim, c.mean_closed, 5e-3 * c.swing_sim) << omega;
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
