// Excitation orders from the layout and from the reduced model's Fourier series; the order
// spectrum of a signal against the crank angle.
#include <cmath>

#include <gtest/gtest.h>

#include "modes/ExcitationOrders.h"
#include "modes/OrderSpectrum.h"
#include "scene/SceneParser.h"
#include "reduced/ReducedModel.h"

using namespace rollerdyn;
using namespace rollerdyn::modes;

namespace {
Scene shipped(const std::string& name, const std::vector<std::string>& overrides = {}) {
  return parseSceneFile(std::string(ROLLERDYN_SOURCE_DIR) + "/model/" + name + ".yaml", overrides);
}
bool has(const std::vector<int>& v, int k) { return std::find(v.begin(), v.end(), k) != v.end(); }
}  // namespace

// Four equal carts at 90° on one side (Loveikin, Pochka, Romasevych (2018)): only the orders 4k
// survive, in the layout's phase sums and in the measured inertia and load torque.
TEST(ExcitationOrders, FourEqualCartsKeepMultiplesOfFour) {
  const ExcitationOrders e = excitationOrders(ReducedModel(shipped("balanced-4cart")), 10.7);
  EXPECT_EQ(e.layout, (std::vector<int>{4, 8, 12, 16, 20, 24}));
  ASSERT_FALSE(e.inertia.empty());
  for (int k : e.all) EXPECT_EQ(k % 4, 0) << k;
  EXPECT_TRUE(has(e.inertia, 4));
  EXPECT_TRUE(has(e.load, 4));
}

// Two carts on opposite sides at 90° (Loveikin and Pochka (2007)): the opposite cart acts as a
// same-side one half a turn later, effective phases 0 and 270°: orders 2, 6, 10, ... cancel,
// every other order (odd ones from the rod's obliquity r/l) survives.
TEST(ExcitationOrders, OppositeSidesCancelTwoModFour) {
  const ExcitationOrders e = excitationOrders(ReducedModel(shipped("recuperative-2cart")), 10.4);
  for (int k = 1; k <= 24; ++k) EXPECT_EQ(has(e.layout, k), k % 4 != 2) << k;
  for (int k : e.inertia) EXPECT_NE(k % 4, 2) << k;
  EXPECT_TRUE(has(e.inertia, 1));
  EXPECT_TRUE(has(e.inertia, 4));
}

// The sides matter: two cranks in line (Δφ = 0) on opposite sides cancel every odd order, on the
// same side they keep all.
TEST(ExcitationOrders, SidesDecideWithCranksInLine) {
  const ExcitationOrders opposite = excitationOrders(ReducedModel(shipped("recuperative-2cart", {"crank.offset_deg=0"})), 10.4);
  for (int k = 1; k <= 24; ++k) EXPECT_EQ(has(opposite.layout, k), k % 2 == 0) << k;
  for (int k : opposite.inertia) EXPECT_EQ(k % 2, 0) << k;
  // The rods' own weight does not follow the mirror rule: it brings order 1 into the load torque
  // (cranks in line: the two rods' weights add); without gravity every odd order cancels there too.
  EXPECT_TRUE(has(opposite.load, 1));
  const ExcitationOrders no_gravity =
      excitationOrders(ReducedModel(shipped("recuperative-2cart", {"crank.offset_deg=0", "loads.gravity=0"})), 10.4);
  for (int k : no_gravity.all) EXPECT_EQ(k % 2, 0) << k;
  const ExcitationOrders same =
      excitationOrders(ReducedModel(shipped("recuperative-2cart", {"crank.offset_deg=0", "carts.sides=same"})), 10.4);
  EXPECT_TRUE(has(same.inertia, 1));
  EXPECT_TRUE(has(same.inertia, 3));
}

// Offsets of 73°: no order up to 12 has a vanishing phase sum (73·k is never 90, 180 or 270 mod 360).
TEST(ExcitationOrders, UnequalOffsetsKeepEveryOrder) {
  const ExcitationOrders e = excitationOrders(ReducedModel(shipped("balanced-4cart", {"crank.offset_deg=73"})), 10.7);
  for (int k = 1; k <= 12; ++k) EXPECT_TRUE(has(e.layout, k)) << k;
}

// A signal of known orders (mean 3, order 4 of amplitude 2, order 2.5 of 0.5) against a crank
// angle with a 2 % speed ripple, sampled in time: the spectrum in crank angle finds them exactly
// (to the linear interpolation of 2000 rows per revolution).
TEST(OrderSpectrum, FindsKnownOrdersAgainstCrankAngle) {
  Table ts;
  ts.columns = {"t", "phi_crank", "omega_crank", "signal"};
  const double w = 10.0;
  const int rows_per_rev = 2000, revs = 12;
  for (int i = 0; i <= rows_per_rev * revs; ++i) {
    const double t = i * (2 * M_PI / w) / rows_per_rev;
    const double phi = w * t + 0.02 * std::sin(w * t);  // ripple, same each revolution
    ts.rows.push_back({t, phi, w, 3 + 2 * std::cos(4 * phi) + 0.5 * std::cos(2.5 * phi + 0.3)});
  }
  const OrderSpectrum s = orderSpectrum(ts, ts, {"signal"}, 4, 64, 10);
  ASSERT_TRUE(s.ok) << s.note;
  EXPECT_EQ(s.revolutions, 4);
  auto at = [&](double order) {
    for (size_t b = 0; b < s.orders.size(); ++b)
      if (std::abs(s.orders[b] - order) < 1e-9) return s.amplitude[0][b];
    return -1.0;
  };
  EXPECT_NEAR(at(0), 3.0, 1e-3);
  EXPECT_NEAR(at(4), 2.0, 1e-3);
  EXPECT_NEAR(at(2.5), 0.5, 1e-3);
  EXPECT_LT(at(1), 1e-3);
  EXPECT_NEAR(s.peaks[0][0].order, 4.0, 1e-12);
  EXPECT_NEAR(s.peaks[0][1].order, 2.5, 1e-12);
  EXPECT_NEAR(s.whole_order_share[0], 4.0 / 4.25, 1e-3);  // amplitude² of order 4 over 4 and 2.5
}
