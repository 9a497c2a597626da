// Resonance check of the elastic coupling (Dyomin (two rotors) eq. (10)) for installation scenes.
#include <gtest/gtest.h>

#include <cmath>

#include "reduced/ReducedModel.h"
#include "studies/ResonanceCheck.h"
#include "support/Seed000Scene.h"

namespace rollerdyn {
namespace {

TEST(ResonanceCheck, NaturalFrequencyOfSeed000Drive) {
  const Scene s = test_scenes::seed000Scene();
  const ReducedModel m(s);
  // Mean J_n2 over a revolution against an independent fine trapezoidal average.
  double J2 = 0;
  const int n = 100000;
  for (int i = 0; i < n; ++i) J2 += m.crankSideInertia(2 * M_PI * i / n) / n;
  EXPECT_NEAR(meanCrankSideInertia(s), J2, 1e-9 * J2);
  const ResonanceReport r = checkResonance(s, 10.5);
  ASSERT_TRUE(r.applicable);
  EXPECT_DOUBLE_EQ(r.J1, s.motorSideInertia());
  EXPECT_NEAR(r.p0, std::sqrt(2e5 * (r.J1 + J2) / (r.J1 * J2)), 1e-9 * r.p0);  // eq. (10)
}

TEST(ResonanceCheck, WarnsWithinTenPercentOfOneTwoThreeFiveOmega) {
  const double p0 = 60.0;
  // n·ω = p0/ratio: ratio 1.05 and 0.95 are inside, 1.11 and 0.89 outside the 10 % band.
  for (int n : {1, 2, 3, 5}) {
    EXPECT_EQ(resonanceHits(p0, p0 / (1.05 * n)).size(), 1u) << n;
    EXPECT_EQ(resonanceHits(p0, p0 / (0.95 * n)).size(), 1u) << n;
    const auto outside = resonanceHits(p0, p0 / (1.11 * n));
    for (const ResonanceHit& h : outside) EXPECT_NE(h.harmonic, n);
  }
  EXPECT_TRUE(resonanceHits(p0, p0 / 4).empty());   // 4ω: not among the harmonics checked
  EXPECT_TRUE(resonanceHits(p0, 0.0).empty());      // no speed, no check
}

TEST(ResonanceCheck, SummaryGetsWarningsForAnElasticSceneOnly) {
  Scene s = test_scenes::seed000Scene();
  const double J1 = s.motorSideInertia(), J2 = meanCrankSideInertia(s);
  const double omega = 10.4;
  // Stiffness that puts p0 at 3ω·1.03: c = p0²·J1·J2/(J1 + J2).
  const double p0 = 3 * omega * 1.03;
  s.coupling.stiffness = p0 * p0 * J1 * J2 / (J1 + J2);
  nlohmann::json summary = {{"omega_crank", {{"mean", omega}}}, {"warnings", {"kept"}}};
  const auto added = addResonanceWarnings(s, summary);
  ASSERT_EQ(added.size(), 1u);
  EXPECT_EQ(summary["warnings"].size(), 2u);  // earlier warnings are kept
  EXPECT_EQ(summary["resonance"]["hits"][0]["harmonic"], 3);
  EXPECT_NEAR(summary["resonance"]["p0"].get<double>(), p0, 1e-9 * p0);

  s.coupling.type = CouplingType::Rigid;
  nlohmann::json rigid = {{"omega_crank", {{"mean", omega}}}};
  EXPECT_TRUE(addResonanceWarnings(s, rigid).empty());
  EXPECT_TRUE(rigid["warnings"].empty());
  EXPECT_FALSE(rigid["resonance"]["applicable"].get<bool>());
}

}  // namespace
}  // namespace rollerdyn
