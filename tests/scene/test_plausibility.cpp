// A metre value typed in millimetres (the 6-cart trial: accepted without a word) gets a warning
// naming the key, the value and what was likely meant; the papers' own values get none.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/Plausibility.h"
#include "support/Loveikin2018Scene.h"

namespace rollerdyn {
namespace {

TEST(Plausibility, LengthTypedInMillimetresIsNamedAndThePapersValuesAreNot) {
  Scene s = test_scenes::loveikin2018Scene();
  EXPECT_TRUE(plausibilityWarnings(s).empty());
  s.crank.radius = 200;  // meant 200 mm
  const auto w = plausibilityWarnings(s);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("crank.radius = 200 m"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("write 0.2"), std::string::npos) << w[0];
}

// The 6-cart trial typed crank.offset_deg: 1.0472 (60° in radians) and carts.mass: 1 (tonnes):
// both were accepted silently.
TEST(Plausibility, AnAngleTypedInRadiansAndACartMassInTonnesAreNamed) {
  Scene s = test_scenes::loveikin2018Scene();
  s.crank.offset = 1.0472 * M_PI / 180.0;  // the key is in degrees: 1.0472 deg
  auto w = plausibilityWarnings(s);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("crank.offset_deg = 1.0472 is read as 1.0472°"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("write 60"), std::string::npos) << w[0];
  for (double deg : {3.14, 2.09, 0.52, 6.28}) {  // the fourth trial's radians, near no round angle
    s.crank.offset = deg * M_PI / 180.0;
    EXPECT_EQ(plausibilityWarnings(s).size(), 1u) << deg;
  }
  for (double deg : {3.0, 5.0, 45.0, 90.0, 7.5}) {  // whole degrees, or beyond 2π
    s.crank.offset = deg * M_PI / 180.0;
    EXPECT_TRUE(plausibilityWarnings(s).empty()) << deg;
  }
  s.crank.offset = M_PI / 2;
  s.carts.mass = 1.0;
  w = plausibilityWarnings(s);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("carts.mass = 1 kg"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("write 1000"), std::string::npos) << w[0];
  s.carts.mass = 1e-6;  // a deliberately massless cart
  EXPECT_TRUE(plausibilityWarnings(s).empty());
  // Per-cart lists name the entry.
  s.carts.mass = std::nan("");
  s.carts.masses.assign(s.carts.count, 1000.0);
  s.carts.masses[1] = 0.8;
  w = plausibilityWarnings(s);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("carts.mass[1] = 0.8 kg"), std::string::npos) << w[0];
}

// The trial typed simulation.output_step: 5 (meaning 5 ms) and got "steady state reached" from 3
// rows and a motor FAIL of a drive that ran well; a breakdown torque 1000x the catalogue's, a
// gravity of 981 and a δ* of 5 were accepted silently.
TEST(Plausibility, SparseRowsACatalogueMismatchGravityAndAPercentTargetAreNamed) {
  Scene s = test_scenes::loveikin2018Scene();
  ASSERT_TRUE(plausibilityWarnings(s).empty());
  const double t_rev = 2 * M_PI * s.reducer.ratio / s.motor.omega_sync;
  s.simulation.output_step = t_rev / 40;  // 40 rows per revolution
  auto w = plausibilityWarnings(s);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("about 40 output rows per crank revolution"), std::string::npos) << w[0];
  s.simulation.output_step = t_rev / 60;
  EXPECT_TRUE(plausibilityWarnings(s).empty());
  s.induction.catalogue.power = 22000;
  s.induction.catalogue.omega_nominal = 22000.0 * 2.4 / s.motor.breakdown_torque;  // consistent: M_kr = λ·P_n/ω_n
  s.induction.catalogue.breakdown_torque_ratio = 2.4;
  EXPECT_TRUE(plausibilityWarnings(s).empty());
  s.motor.breakdown_torque *= 1000;
  w = plausibilityWarnings(s);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("disagrees with the catalogue"), std::string::npos) << w[0];
  s.motor.breakdown_torque /= 1000;
  s.loads.gravity = 981;
  s.sizing.target_delta = 5;
  w = plausibilityWarnings(s);
  ASSERT_EQ(w.size(), 2u);
  EXPECT_NE(w[0].find("loads.gravity = 981"), std::string::npos) << w[0];
  EXPECT_NE(w[1].find("write 0.05"), std::string::npos) << w[1];
  // The rotor speed typed for the crank's.
  s.loads.gravity = 9.81;
  s.sizing.target_delta = 0.05;
  s.initial.crank_speed = 102;
  w = plausibilityWarnings(s);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("initial.crank_speed = 102 rad/s is"), std::string::npos) << w[0];
  s.initial.crank_speed = 10.4;
  EXPECT_TRUE(plausibilityWarnings(s).empty());
  // A switch-off after the end of the run.
  s.motor_stop.t_off = 2 * s.simulation.t_end;
  w = plausibilityWarnings(s);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("the run holds no switch-off"), std::string::npos) << w[0];
}

}  // namespace
}  // namespace rollerdyn
