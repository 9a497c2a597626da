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
  // Stiffness that puts p0 at 4ω·1.03 (four carts at 90° excite 4ω): c = p0²·J1·J2/(J1 + J2).
  const double p0 = 4 * omega * 1.03;
  s.coupling.stiffness = p0 * p0 * J1 * J2 / (J1 + J2);
  nlohmann::json summary = {{"omega_crank", {{"mean", omega}}}, {"warnings", {"kept"}}};
  const auto added = addResonanceWarnings(s, summary);
  ASSERT_EQ(added.size(), 1u);
  EXPECT_EQ(summary["warnings"].size(), 2u);  // earlier warnings are kept
  EXPECT_EQ(summary["resonance"]["hits"][0]["harmonic"], 4);
  EXPECT_NEAR(summary["resonance"]["p0"].get<double>(), p0, 1e-9 * p0);

  s.coupling.type = CouplingType::Rigid;
  nlohmann::json rigid = {{"omega_crank", {{"mean", omega}}}};
  EXPECT_TRUE(addResonanceWarnings(s, rigid).empty());
  EXPECT_TRUE(rigid["warnings"].empty());
  EXPECT_FALSE(rigid["resonance"]["applicable"].get<bool>());
}

// The 6-cart trial: six equal carts at 60° on one side excite only 6ω, 12ω, ...; p0 = 6.09ω must
// be flagged at order 6, and p0 = 3ω or 5ω, which this layout does not excite, must not be.
TEST(ResonanceCheck, OrdersComeFromTheCartLayout) {
  Scene s = test_scenes::seed000Scene();
  s.carts.count = 6;
  s.carts.side.assign(6, 1);
  s.crank.offset = M_PI / 3;
  EXPECT_EQ(excitationOrders(s), (std::vector<int>{6, 12}));
  const double p0 = checkResonance(s, 10.0).p0;
  const ResonanceReport near6 = checkResonance(s, p0 / 6.09);
  ASSERT_EQ(near6.hits.size(), 1u);
  EXPECT_EQ(near6.hits[0].harmonic, 6);
  EXPECT_TRUE(checkResonance(s, p0 / 3.0).hits.empty());
  EXPECT_TRUE(checkResonance(s, p0 / 5.0).hits.empty());

  s.carts.count = 4;  // the papers' four carts at 90°: 4ω, 8ω, 12ω
  s.carts.side.assign(4, 1);
  s.crank.offset = M_PI / 2;
  EXPECT_EQ(excitationOrders(s), (std::vector<int>{4, 8, 12}));
  s.crank.offset = M_PI / 3;  // four carts at 0, 60, 120, 180°: only 3ω and 9ω cancel
  EXPECT_EQ(excitationOrders(s), (std::vector<int>{1, 2, 4, 5, 6, 7, 8, 10, 11, 12}));
  s.crank.offset = M_PI / 2;  // both sides (mirrored slider-cranks): every order
  s.carts.side = {1, -1, 1, -1};
  EXPECT_EQ(excitationOrders(s).size(), 12u);
}

// Carts of their own (per-cart inputs): the four carts at 90° cancel all but 4ω, 8ω, 12ω only
// while they are equal and at their places; an empty cart or a crank 2° off excites every order.
TEST(ResonanceCheck, CartsOfTheirOwnExciteEveryOrder) {
  Scene s = test_scenes::seed000Scene();
  s.carts.count = 4;
  s.carts.side.assign(4, 1);
  s.crank.offset = M_PI / 2;
  ASSERT_EQ(excitationOrders(s), (std::vector<int>{4, 8, 12}));
  Scene lists = s;  // lists equal to the uniform value change nothing
  lists.cart_loads.assign(4, CartLoads{s.loads.roller_force_front, s.loads.roller_force_rear,
                                       s.loads.roller_normal_front, s.loads.roller_normal_rear, s.loads.rolling_resistance});
  lists.crank.angle_errors.assign(4, 0.0);
  EXPECT_EQ(excitationOrders(lists), (std::vector<int>{4, 8, 12}));
  Scene empty = lists;
  empty.cart_loads[1] = CartLoads{};
  EXPECT_EQ(excitationOrders(empty).size(), 12u);
  Scene off = s;
  off.crank.angle_errors = {0, 0, 2 * M_PI / 180, 0};
  EXPECT_EQ(excitationOrders(off).size(), 12u);
}

}  // namespace
}  // namespace rollerdyn
