// Separation margins of the coupling mode from the orders that drive it (API 617 / API 684
// practice, >= 10 %), on the cases whose mode the resonance warnings' tests know.
#include <gtest/gtest.h>

#include "ModesTestSupport.h"

using namespace rollerdyn;
using namespace rollerdyn::modes;

namespace {
ModesReport light(const std::vector<std::string>& overrides) { return rollerdyn::modes::test::lightModes(overrides); }
const SeparationMargin* order(const SeparationMargins& s, int k) {
  for (const SeparationMargin& m : s.rows)
    if (m.order == k) return &m;
  return nullptr;
}
}  // namespace

// Undamped coupling of 130 kN·m/rad: the two-mass drive with the motor's static slope (7450
// N·m·s/rad at the crank) puts the mode at 42.2 rad/s, ζ = 0.21 (the hand check of
// ModalWarnings.ForcedResonanceAtTheLayoutsFirstOrder), against 4ω = 4 × 10.68 = 42.7 rad/s:
// SM ≈ 1.2 %, far below 10 %.
TEST(SeparationMargins, AModeOnTheLayoutsFirstOrderFails) {
  const ModesReport r = light({"coupling.stiffness=130000", "coupling.damping=0"});
  ASSERT_TRUE(r.separation.applicable) << r.separation.not_applicable;
  const SeparationMargin* m = order(r.separation, 4);
  ASSERT_NE(m, nullptr);
  EXPECT_EQ(m->verdict, "FAIL");
  EXPECT_NEAR(m->margin, std::abs(42.2 - 4 * r.separation.omega) / (4 * r.separation.omega), 0.02);
  EXPECT_NEAR(m->damping_ratio, 0.21, 0.05);
  EXPECT_NEAR(m->amplification, 0.5 / m->damping_ratio, 1e-12);
  // The advice is whole, to its last figure (it was cut at 240 characters).
  EXPECT_NE(m->reason.find("amplification factor 1/(2*zeta) = "), std::string::npos) << m->reason;
}

// Three times stiffer, the mode moves up to 85.4 rad/s (Floquet), exactly onto order 8 = 85.4
// rad/s; order 4 is then 50 % below it and passes. Order 8 does not drive the coupling (four equal
// carts at 90°: its harmonic is below 1 % of the largest), so it is shown with its margin and no
// verdict, never as a FAIL.
TEST(SeparationMargins, AWeakOrderOnTheModeIsShownWithoutAVerdict) {
  const ModesReport r = light({"coupling.stiffness=390000", "coupling.damping=0"});
  ASSERT_TRUE(r.separation.applicable) << r.separation.not_applicable;
  const SeparationMargin* m4 = order(r.separation, 4);
  ASSERT_NE(m4, nullptr);
  EXPECT_GT(m4->margin, 0.10);
  EXPECT_EQ(m4->verdict, "pass");
  const SeparationMargin* m8 = order(r.separation, 8);
  ASSERT_NE(m8, nullptr);
  EXPECT_LT(m8->margin, 0.01);
  EXPECT_EQ(m8->verdict, "n/a");
  EXPECT_EQ(separationJson(r.separation)["verdict"], "pass");
}

TEST(SeparationMargins, NotApplicableWithARigidCouplingAndSaysWhy) {
  const ModesReport r = light({"coupling.type=rigid"});
  EXPECT_FALSE(r.separation.applicable);
  EXPECT_NE(r.separation.not_applicable.find("rigid coupling"), std::string::npos);
  const nlohmann::json j = separationJson(r.separation);
  EXPECT_EQ(j["verdict"], "not applicable");
}

// The shipped scene's heavy damper (k = 8000 N·m·s/rad, ζ ≈ 0.88) moves the damped pair's natural
// frequency (≈ 30.5 rad/s) far below the undamped √λ ≈ 70.6 rad/s: the margin is taken from the
// damped pair, the one a forced response peaks at, and both are reported.
TEST(SeparationMargins, AHeavyDamperIsJudgedAtItsDampedPairsNaturalFrequency) {
  const ModesReport r = light({});
  const SeparationMargin* m = order(r.separation, 4);
  ASSERT_NE(m, nullptr);
  EXPECT_EQ(m->frequency_source, "frozen-angle band");
  EXPECT_LT(m->p_high, 0.5 * m->undamped_low);
  EXPECT_NEAR(m->margin, (4 * r.separation.omega - m->p_high) / (4 * r.separation.omega), 1e-12);
}
