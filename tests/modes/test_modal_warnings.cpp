// The resonance warnings of the modal analysis (what simulate's verdict rests on).
#include <gtest/gtest.h>

#include "ModesTestSupport.h"

using namespace rollerdyn;
using namespace rollerdyn::modes;

namespace {
ModesReport light(const std::vector<std::string>& overrides) { return rollerdyn::modes::test::lightModes(overrides); }
bool mentions(const std::vector<std::string>& w, const std::string& text) {
  for (const std::string& s : w)
    if (s.find(text) != std::string::npos) return true;
  return false;
}
}  // namespace

// Undamped coupling of 130 kN·m/rad: the motor's static slope (7450 N·m·s/rad at the crank) holds
// the motor side, and the coupling mode oscillates at |λ| ≈ 42 rad/s ≈ 4ω (two-mass check with the
// slope: 42.2 rad/s, ζ = 0.21), the four-cart layout's first exciting order (its load torque's
// largest harmonic). (At 73 kN·m/rad, where the undamped p0 is 4ω, the slope pulls the mode down to
// 30 rad/s = 2.8ω: the warning there came from a Floquet frequency on the wrong branch.)
TEST(ModalWarnings, ForcedResonanceAtTheLayoutsFirstOrder) {
  const ModesReport r = light({"coupling.stiffness=130000", "coupling.damping=0"});
  ASSERT_TRUE(r.steady.found) << r.steady.failure;
  EXPECT_TRUE(mentions(r.warnings, "within 5 % of order 4 of the crank speed")) << (r.warnings.empty() ? "" : r.warnings[0]);
}

// The papers' coupling: the mode lies between orders 4 and 8 and is stable: no warning. At p ≈ 3ω
// (41 kN·m/rad) the two-mass check would warn (3ω), but order 3 does not excite four equal carts.
TEST(ModalWarnings, NoneBetweenTheOrders) {
  EXPECT_TRUE(light({}).warnings.empty());
  EXPECT_TRUE(light({"coupling.stiffness=41000", "coupling.damping=0"}).warnings.empty());
}

// Finding of the 6-cart trial: the console listed the crossings of load-shape harmonics (orders
// 14-20, about a thousandth of the layout's order 6) first and the order-6 crossing, 1.5 % from
// the running speed, last. The layout's orders come first, nearest the running speed first.
TEST(ModesConsole, CampbellCrossingsOfTheLayoutsOrdersNearestTheRunningSpeedComeFirst) {
  ModesReport r;
  r.scene = "synthetic";
  r.elastic = r.motor = true;
  r.steady.found = true;
  r.steady.omega_mean = 10.68;
  r.steady.period = 2 * M_PI / 10.68;
  r.orders.layout = {6, 12};
  r.campbell.applicable = true;
  auto crossing = [](int k, bool parametric, double w) {
    CampbellCrossing c;
    c.order = k;
    c.parametric = parametric;
    c.omega = w;
    return c;
  };
  r.campbell.crossings = {crossing(20, true, 3.25), crossing(14, true, 9.29), crossing(12, false, 5.42),
                          crossing(6, false, 10.84)};
  const std::string text = modesText(r);
  const auto at = [&](const char* s) { return text.find(s); };
  ASSERT_NE(at("p=6 at 10.84"), std::string::npos) << text;
  EXPECT_LT(at("p=6 at 10.84"), at("p=12 at 5.42"));
  EXPECT_LT(at("p=12 at 5.42"), at("2p=14 at 9.29"));
  EXPECT_LT(at("2p=14 at 9.29"), at("2p=20 at 3.25"));
}
