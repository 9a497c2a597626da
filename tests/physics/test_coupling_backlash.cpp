// The coupling's law with backlash (physics/CouplingLaw.h) against values worked by hand from its
// definition (Modelica Standard Library, Rotational.Components.ElastoBacklash), c = 2e5 N·m/rad,
// k = 8000 N·m·s/rad, total backlash 2b = 0.002 rad.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/CouplingLaw.h"

namespace rollerdyn {
namespace {

constexpr double c = 2e5, k = 8000, b = 0.001;
const CouplingLaw kLaw{c, k, b};

TEST(CouplingBacklash, NoTorqueInsideTheGap) {
  for (double q : {-0.001, -0.0005, 0.0, 0.0007, 0.001})
    for (double w : {-3.0, 0.0, 2.0}) {
      const CouplingTorque t = couplingTorque(kLaw, q, w);
      EXPECT_EQ(t.torque, 0.0) << q << " " << w;
      EXPECT_EQ(t.damping_power, 0.0);
      EXPECT_EQ(couplingPotential(kLaw, q), 0.0);
      EXPECT_EQ(toothContact(kLaw, q), ToothContact::Gap);
    }
}

TEST(CouplingBacklash, SpringActsBeyondTheGapWithoutTwistRate) {
  // Δφ = 0.003: 2e5·(0.003 − 0.001) = 400 N·m; Δφ = −0.0025: 2e5·(−0.0015) = −300 N·m.
  EXPECT_NEAR(couplingTorque(kLaw, 0.003, 0.0).torque, 400.0, 1e-9);
  EXPECT_NEAR(couplingTorque(kLaw, -0.0025, 0.0).torque, -300.0, 1e-9);
  EXPECT_EQ(toothContact(kLaw, 0.003), ToothContact::Drive);
  EXPECT_EQ(toothContact(kLaw, -0.0025), ToothContact::Reverse);
  // V = ½·2e5·0.002² = 0.4 J and ½·2e5·0.0015² = 0.225 J.
  EXPECT_NEAR(couplingPotential(kLaw, 0.003), 0.4, 1e-12);
  EXPECT_NEAR(couplingPotential(kLaw, -0.0025), 0.225, 1e-12);
}

TEST(CouplingBacklash, DampingAddsWhileClosingAndIsLimitedToTheSpringTorque) {
  // Δφ = 0.003 (τ_c = 400), Δω = 0.01: τ_d = 80 < 400, τ = 480, P_d = 80·0.01 = 0.8 W.
  CouplingTorque t = couplingTorque(kLaw, 0.003, 0.01);
  EXPECT_NEAR(t.torque, 480.0, 1e-9);
  EXPECT_NEAR(t.damping_power, 0.8, 1e-12);
  // Δω = 0.5: τ_d = 4000 > τ_c = 400, limited: τ = 800, P_d = 400·0.5 = 200 W (not k·Δω² = 2000).
  t = couplingTorque(kLaw, 0.003, 0.5);
  EXPECT_NEAR(t.torque, 800.0, 1e-9);
  EXPECT_NEAR(t.damping_power, 200.0, 1e-9);
  // Just past contact the torque starts from 0 whatever the speed of approach: Δφ = b + 1e-9.
  EXPECT_NEAR(couplingTorque(kLaw, b + 1e-9, 5.0).torque, 2 * c * 1e-9, 1e-9);
}

TEST(CouplingBacklash, DampingNeverPullsTheTeethTogether) {
  // Opening fast: Δφ = 0.003 (τ_c = 400), Δω = −0.1: τ_c + τ_d = 400 − 800 < 0, so τ = 0; the
  // spring's store runs down into the damper: P_d = −τ_c·Δω = 40 W.
  CouplingTorque t = couplingTorque(kLaw, 0.003, -0.1);
  EXPECT_EQ(t.torque, 0.0);
  EXPECT_NEAR(t.damping_power, 40.0, 1e-12);
  // Opening slowly: Δω = −0.02, τ_d = −160: τ = 240 (pushing), P_d = k·Δω² = 3.2 W.
  t = couplingTorque(kLaw, 0.003, -0.02);
  EXPECT_NEAR(t.torque, 240.0, 1e-9);
  EXPECT_NEAR(t.damping_power, 3.2, 1e-12);
  // Reverse flank, mirror image: Δφ = −0.003, Δω = +0.1: τ = 0; Δω = −0.5: τ = −800.
  EXPECT_EQ(couplingTorque(kLaw, -0.003, 0.1).torque, 0.0);
  EXPECT_NEAR(couplingTorque(kLaw, -0.003, -0.5).torque, -800.0, 1e-9);
  // Over a grid: τ never has the opposite sign of the spring torque, P_d ≥ 0.
  for (double q = -0.01; q <= 0.01; q += 1.7e-4)
    for (double w = -2.0; w <= 2.0; w += 0.013) {
      const CouplingTorque r = couplingTorque(kLaw, q, w);
      EXPECT_GE(r.torque * r.spring_torque, 0.0) << q << " " << w;
      EXPECT_GE(r.damping_power, 0.0) << q << " " << w;
    }
}

TEST(CouplingBacklash, WithoutBacklashItIsThePapersSpringDamper) {
  const CouplingLaw law{c, k, 0.0};
  // τ = c·Δφ + k·Δω, pulling too (Loveikin, Pochka, Romasevych (2018) eq. (58)).
  EXPECT_NEAR(couplingTorque(law, 0.003, -0.1).torque, 600.0 - 800.0, 1e-9);
  EXPECT_NEAR(couplingTorque(law, 0.003, -0.1).damping_power, 80.0, 1e-12);
  EXPECT_NEAR(couplingPotential(law, 0.003), 0.9, 1e-12);
}

TEST(CouplingBacklash, PowerBalanceOfTheElementHolds) {
  // τ·Δω = dV/dt + P_d with dV/dt = τ_c·Δω: the coupling's own energy audit closes.
  for (double q : {-0.004, -0.0012, 0.0011, 0.002, 0.009})
    for (double w : {-1.0, -0.05, 0.0, 0.03, 0.7}) {
      const CouplingTorque r = couplingTorque(kLaw, q, w);
      const double h = 1e-9;
      const double dV = (couplingPotential(kLaw, q + h * w) - couplingPotential(kLaw, q - h * w)) / (2 * h);
      EXPECT_NEAR(r.torque * w, dV + r.damping_power, 1e-6 * (1 + std::abs(r.torque * w))) << q << " " << w;
    }
}

}  // namespace
}  // namespace rollerdyn
