// Per-cart scene keys (docs/per-cart.md): carts.mass, loads.roller_force_front/_rear,
// loads.roller_normal_front/_rear, loads.rolling_resistance as a list of carts.count numbers;
// crank.angles_deg instead of crank.offset_deg; crank.angle_error_deg. The scalar form stays the
// uniform value; a list equal to it gives the same Scene values; every error names file, line,
// key and what was expected.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/SceneTestSupport.h"

using namespace rollerdyn;
using namespace rollerdyn::test;

namespace {
constexpr double kDeg = M_PI / 180.0;
}

TEST(ScenePerCart, ListsEqualToTheScalarGiveTheSameValues) {
  const Scene uniform = parseSceneText(kMinimalScene, "test.yaml",
                                       {"loads.roller_force_front=7000", "loads.roller_normal_rear=3000",
                                        "loads.rolling_resistance=0.05"});
  const Scene lists = parseSceneText(replaced("  mass: 1000", "  mass: [1000, 1000]"), "test.yaml",
                                     {"loads.roller_force_front=[7000, 7000]", "loads.roller_normal_rear=[3000, 3000]",
                                      "loads.rolling_resistance=[0.05, 0.05]", "crank.angle_error_deg=[0, 0]"});
  EXPECT_TRUE(uniform.cart_loads.empty());
  ASSERT_EQ(lists.cart_loads.size(), 2u);
  EXPECT_TRUE(lists.cartsIdentical());
  for (int j = 0; j < 2; ++j) {
    EXPECT_EQ(lists.cartMass(j), uniform.cartMass(j));
    EXPECT_EQ(lists.cartMassWithRodShare(j), uniform.cartMassWithRodShare(j));
    EXPECT_EQ(lists.crankPhase(j), uniform.crankPhase(j));
    const Loads a = lists.cartLoads(j), b = uniform.cartLoads(j);
    EXPECT_EQ(a.roller_force_front, b.roller_force_front);
    EXPECT_EQ(a.roller_force_rear, b.roller_force_rear);
    EXPECT_EQ(a.roller_normal_front, b.roller_normal_front);
    EXPECT_EQ(a.roller_normal_rear, b.roller_normal_rear);
    EXPECT_EQ(a.rolling_resistance, b.rolling_resistance);
  }
  EXPECT_EQ(lists.rollerForceSum(), uniform.rollerForceSum());
}

TEST(ScenePerCart, EachCartGetsItsOwnValues) {
  const Scene s = parseSceneText(replaced("  mass: 1000", "  mass: [1000, 400]"), "test.yaml",
                                 {"loads.roller_force_front=[7000, 0]", "loads.roller_force_rear=2000",
                                  "crank.angle_error_deg=[0, 2]"});
  EXPECT_TRUE(std::isnan(s.carts.mass));  // a list: the scalar is not a value any law may read
  EXPECT_EQ(s.cartMass(0), 1000.0);
  EXPECT_EQ(s.cartMass(1), 400.0);
  EXPECT_DOUBLE_EQ(s.cartMassWithRodShare(1), 400.0);  // distributed rods: no rod share at the cart
  EXPECT_DOUBLE_EQ(s.lightestCartMassWithRodShare(), 400.0);
  EXPECT_EQ(s.cartLoads(0).roller_force_front, 7000.0);
  EXPECT_EQ(s.cartLoads(1).roller_force_front, 0.0);
  EXPECT_EQ(s.cartLoads(1).roller_force_rear, 2000.0);  // the scalar repeats for every cart
  EXPECT_DOUBLE_EQ(s.rollerForceSum(), 7000.0 + 2000.0 + 2000.0);
  EXPECT_DOUBLE_EQ(s.crankPhase(0), 0.0);
  EXPECT_DOUBLE_EQ(s.crankPhase(1), 92 * kDeg);
  EXPECT_FALSE(s.cartsIdentical());
  EXPECT_THROW(s.cartMassWithRodShare(), std::logic_error);  // no silent "cart 1's mass for all"
}

TEST(ScenePerCart, CrankAnglesReplaceTheOffset) {
  const Scene s = parseSceneText(replaced("  offset_deg: 90", "  angles_deg: [0, 135]"), "test.yaml",
                                 {"crank.angle_error_deg=[0, -1.5]"});
  EXPECT_TRUE(std::isnan(s.crank.offset));
  EXPECT_DOUBLE_EQ(s.crankPhase(1), (135 - 1.5) * kDeg);
  // A later --set of the other key wins over the file's.
  const Scene o = parseSceneText(kMinimalScene, "test.yaml", {"crank.angles_deg=[0, 200]"});
  EXPECT_DOUBLE_EQ(o.crankPhase(1), 200 * kDeg);
  // One error for every crank turns the whole shaft.
  const Scene e = parseSceneText(kMinimalScene, "test.yaml", {"crank.angle_error_deg=3"});
  EXPECT_DOUBLE_EQ(e.crankPhase(0), 3 * kDeg);
  EXPECT_DOUBLE_EQ(e.crankPhase(1), 93 * kDeg);
}

TEST(ScenePerCart, OneElementBySet) {
  const Scene s = parseSceneText(kMinimalScene, "test.yaml", {"carts.mass[1]=250", "crank.angle_error_deg[1]=2"});
  EXPECT_EQ(s.cartMass(0), 1000.0);
  EXPECT_EQ(s.cartMass(1), 250.0);
  EXPECT_DOUBLE_EQ(s.crankPhase(1), 92 * kDeg);
  expectSceneError(kMinimalScene, {"carts.mass[2]", "an index from 0 to 1", "got 2"}, {"carts.mass[2]=250"});
  // Only per-cart keys take an index.
  expectSceneError(kMinimalScene, {"crank.radius[0]"}, {"crank.radius[0]=0.3"});
}

TEST(ScenePerCart, WrongListsAreLocatedErrors) {
  expectSceneError(replaced("  mass: 1000", "  mass: [1000]"),
                   {"test.yaml:13: carts.mass: expected a list of 2 numbers > 0 [kg], one per cart (carts.count = 2), "
                    "got a list of 1"});
  expectSceneError(replaced("  mass: 1000", "  mass: [1000, -5]"),
                   {"test.yaml:13: carts.mass[1]: expected a number > 0 [kg] for cart 2, got -5"});
  expectSceneError(replaced("  mass: 1000", "  mass: [1000, heavy]"), {"carts.mass[1]", "for cart 2", "heavy"});
  expectSceneError(replaced("  offset_deg: 90", "  angles_deg: [10, 100]"),
                   {"test.yaml:6: crank.angles_deg[0]: expected 0 for cart 1"});
  expectSceneError(replaced("  offset_deg: 90", "  angles_deg: 90"), {"test.yaml:6: crank.angles_deg: expected a list of 2"});
  expectSceneError(replaced("  offset_deg: 90", "  offset_deg: 90\n  angles_deg: [0, 90]"),
                   {"crank.angles_deg: expected at most one of crank.offset_deg and crank.angles_deg"});
  expectSceneError(without("  offset_deg: 90"), {"crank.offset_deg", "required unless crank.angles_deg"});
  expectSceneError(kMinimalScene, {"loads.roller_force_front: expected a list of 2 numbers", "got a list of 3"},
                   {"loads.roller_force_front=[1, 2, 3]"});
  // A --set of carts.count that no longer fits a list of the file is the override's fault.
  expectSceneError(replaced("  mass: 1000", "  mass: [1000, 900]"),
                   {"carts.count", "an integer equal to the length of carts.mass (2)"}, {"carts.count=3"});
}
