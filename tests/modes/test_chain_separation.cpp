// The separation margins of the crankshaft's own torsional modes (a torsional chain,
// modes/SeparationMargins.h addChainSeparation): each crankshaft mode is kept 10 % away from the
// orders that drive a throw, whose torque no phase sum cancels (modes/ExcitationOrders.h
// throwOrderShares).
#include <gtest/gtest.h>

#include <cmath>

#include "modes/ExcitationOrders.h"
#include "modes/SeparationMargins.h"
#include "support/Loveikin2018Scene.h"
#include "reduced/ReducedModel.h"

using namespace rollerdyn;
using namespace rollerdyn::modes;

namespace {

SteadyMotion steadyAt(double omega) {
  SteadyMotion s;
  s.found = true;
  s.omega_mean = omega;
  return s;
}

// A chain whose first elastic mode is the coupling mode and whose second is a shaft mode with
// the band [lo, hi] over a revolution.
CrankshaftChainModes chainWithShaftMode(double lo, double hi) {
  CrankshaftChainModes c;
  c.applies = true;
  c.modes = {{40.0, 45.0, 0, 0, "the coupling"}, {lo, hi, 0, 0, "the shaft between carts 1 and 2"}};
  return c;
}

const SeparationMargin* find(const SeparationMargins& s, int order, const std::string& mode_prefix) {
  for (const SeparationMargin& m : s.rows)
    if (m.order == order && m.mode.rfind(mode_prefix, 0) == 0) return &m;
  return nullptr;
}

}  // namespace

// ω = 10 rad/s, a shaft mode between 230 and 240 rad/s, every order driving a throw (5 %):
// by hand, order 23 (230 rad/s) and 24 (240) lie in the band, SM = 0; order 22 (220):
// (230 − 220)/220 = 4.5 %; order 25 (250): (250 − 240)/250 = 4 %; order 21 (210): 9.5 %, all FAIL;
// order 20 (200): 15 % and order 27 (270): 11 %, outside 10 %: no row. The coupling mode (the
// chain's first) is the rigid crankshaft's, judged apart: no row of the chain for it.
TEST(ChainSeparation, AShaftModeNearADrivingOrderFails) {
  SeparationMargins s;
  s.applicable = true;
  s.omega = 10.0;
  const std::vector<double> shares(40, 0.05);
  addChainSeparation(s, chainWithShaftMode(230.0, 240.0), true, steadyAt(10.0), shares);
  for (const SeparationMargin& m : s.rows) EXPECT_EQ(m.mode.rfind("crankshaft mode 2", 0), 0u) << m.mode;
  ASSERT_NE(find(s, 23, "crankshaft mode 2"), nullptr);
  EXPECT_EQ(find(s, 23, "crankshaft mode 2")->verdict, "FAIL");
  EXPECT_DOUBLE_EQ(find(s, 23, "crankshaft mode 2")->margin, 0.0);
  EXPECT_NEAR(find(s, 22, "crankshaft mode 2")->margin, 10.0 / 220.0, 1e-12);
  EXPECT_NEAR(find(s, 25, "crankshaft mode 2")->margin, 10.0 / 250.0, 1e-12);
  EXPECT_NEAR(find(s, 21, "crankshaft mode 2")->margin, 20.0 / 210.0, 1e-12);
  EXPECT_EQ(find(s, 21, "crankshaft mode 2")->verdict, "FAIL");
  EXPECT_EQ(find(s, 20, "crankshaft mode 2"), nullptr);
  EXPECT_EQ(find(s, 27, "crankshaft mode 2"), nullptr);
  // The checks of the sign-off: one per row, named for the mode and the order.
  bool named = false;
  for (const SizingCheck& c : separationChecks(s))
    named = named || c.name == "separation_margin_crankshaft_mode_2_order_23";
  EXPECT_TRUE(named);
}

// The same mode where only orders 1 to 3 drive a throw (a slider-crank's torque without shocks):
// the nearest driving order is 3 (30 rad/s), 200/30 = 667 % away: one row, pass; the weak orders
// within 10 % of the band are counted in its reason, not listed.
TEST(ChainSeparation, AShaftModeFarFromEveryDrivingOrderPasses) {
  SeparationMargins s;
  s.applicable = true;
  s.omega = 10.0;
  std::vector<double> shares(40, 0.001);
  shares[0] = 1.0;
  shares[1] = 0.3;
  shares[2] = 0.05;
  addChainSeparation(s, chainWithShaftMode(230.0, 240.0), true, steadyAt(10.0), shares);
  const SeparationMargin* m = find(s, 3, "crankshaft mode 2");
  ASSERT_NE(m, nullptr);
  EXPECT_EQ(m->verdict, "pass");
  EXPECT_NEAR(m->margin, 200.0 / 30.0, 1e-12);
  EXPECT_EQ(s.rows.size(), 1u);
  // Orders 21 to 26 (210 … 260 rad/s) lie within 10 % of [230, 240] but drive nothing: counted.
  EXPECT_NE(m->reason.find("6 weaker orders"), std::string::npos) << m->reason;
}

// A rigid coupling: the drive's only torsional modes are the chain's, so the margins apply to
// them although the coupling mode's do not; the chain's first mode is judged.
TEST(ChainSeparation, WithARigidCouplingTheChainsModesAreJudged) {
  SeparationMargins s;
  s.applicable = false;
  s.not_applicable = "rigid coupling";
  const std::vector<double> shares(40, 0.05);
  addChainSeparation(s, chainWithShaftMode(230.0, 240.0), false, steadyAt(10.0), shares);
  EXPECT_TRUE(s.applicable);
  EXPECT_DOUBLE_EQ(s.omega, 10.0);
  ASSERT_NE(find(s, 4, "crankshaft mode 1"), nullptr);  // 40 rad/s inside [40, 45]
  EXPECT_EQ(find(s, 4, "crankshaft mode 1")->verdict, "FAIL");
}

// One cart: the throw's torque is the machine's, so each order's share is the machine's exciting
// torque over its largest (ExcitationOrders.h), computed there from the whole crank side.
// Four carts at 90°: the machine cancels every order but 4, 8, ...; a throw's torque keeps
// orders 1, 2, 3.
TEST(ChainSeparation, AThrowKeepsTheOrdersTheLayoutCancels) {
  Scene one = test_scenes::loveikin2018Scene();
  one.carts.count = 1;
  one.carts.side = {1};
  one.loads.gravity = 0.0;  // no rod weight torque, which the throw's shares leave out
  const double omega = 10.0;
  const ExcitationOrders e = excitationOrders(ReducedModel(one), omega, 12);
  const std::vector<double> shares = throwOrderShares(ReducedModel(one), omega, 12);
  for (int k = 1; k <= 12; ++k)
    EXPECT_NEAR(shares[k - 1], e.table[k - 1].exciting_torque / e.exciting_largest, 1e-9) << "order " << k;

  const Scene four = test_scenes::loveikin2018Scene();
  const ExcitationOrders e4 = excitationOrders(ReducedModel(four), omega, 12);
  const std::vector<double> s4 = throwOrderShares(ReducedModel(four), omega, 12);
  EXPECT_LT(e4.table[0].exciting_torque, 1e-6 * e4.exciting_largest);  // order 1 cancelled at the coupling
  EXPECT_GT(s4[0], 0.1);                                                // but not in a throw
  EXPECT_GT(s4[1], 0.01);
}
