// The crankshaft's torsional chain (crankshaft.torsional_stiffness): its natural frequencies by
// the eigen-solution against Holzer's method and against closed forms, and the limit of a stiff
// shaft (the coupling mode of the rigid crankshaft).
#include <gtest/gtest.h>

#include <cmath>

#include "modes/ChainModes.h"
#include "reduced/ReducedModel.h"
#include "support/Loveikin2018Scene.h"

using namespace rollerdyn;
using namespace rollerdyn::modes;

namespace {

// The four-cart drive of Loveikin, Pochka, Romasevych (2018) with its throws 0.3 m apart along
// the shaft, in the firing order 1-3-4-2 from the coupling (z = 0, 0.9, 0.3, 0.6 m).
Scene chainScene(double GIp) {
  Scene sc = test_scenes::loveikin2018Scene();
  sc.crankshaft.throw_positions = {0.0, 0.9, 0.3, 0.6};
  sc.crankshaft.torsional_stiffness = GIp;
  sc.simulation.formulation = Formulation::Constrained;  // the chain is built by the constrained formulation
  sc.loads.guide_normal_force = GuideNormalForce::Lagged;  // with its law of the guide friction
  return sc;
}

}  // namespace

// Two rotors on one spring: p = √(c·(J1 + J2)/(J1·J2)) (Dyomin (two rotors) eq. (10)).
TEST(ChainModes, TwoRotorsHaveTheTwoMassFrequency) {
  const std::vector<double> J = {50.0, 2.0}, c = {2e5};
  const double p = std::sqrt(2e5 * 52.0 / (50.0 * 2.0));  // 322.49 rad/s
  const std::vector<double> eig = chainNaturalFrequencies(J, c);
  ASSERT_EQ(eig.size(), 2u);
  EXPECT_NEAR(eig[0], 0.0, 1e-6);  // the chain turns as a whole
  EXPECT_NEAR(eig[1], p, 1e-9 * p);
  const std::vector<double> holzer = holzerFrequencies(J, c, 2000.0);
  ASSERT_EQ(holzer.size(), 1u);
  EXPECT_NEAR(holzer[0], p, 1e-9 * p);
}

// Five rotors of unequal inertia on unequal springs: Holzer's residual torque vanishes at each
// frequency of the eigen-solution, found on its own by a sign search (no frequency handed over).
TEST(ChainModes, HolzerFindsTheEigenSolutionsFrequencies) {
  const std::vector<double> J = {30.0, 2.0, 3.0, 1.5, 2.5}, c = {2e5, 1e6, 8e5, 1.2e6};
  const std::vector<double> eig = chainNaturalFrequencies(J, c);
  const std::vector<double> holzer = holzerFrequencies(J, c, 1.2 * eig.back());
  ASSERT_EQ(holzer.size(), eig.size() - 1);
  for (size_t m = 0; m < holzer.size(); ++m) EXPECT_NEAR(holzer[m], eig[m + 1], 1e-9 * eig[m + 1]) << "mode " << m + 1;
  // Between two natural frequencies the residual is far from zero (the roots are real ones).
  const double between = 0.5 * (eig[1] + eig[2]);
  EXPECT_GT(std::abs(holzerResidual(J, c, between)), 1e3);
}

// The four-cart chain has one elastic mode per spring (coupling and three shaft segments); at
// every frozen angle Holzer's frequencies of that angle's chain lie in the reported bands.
TEST(ChainModes, TheFourCartChainHasOneModePerSpringWithinItsBands) {
  const Scene sc = chainScene(2e6);
  const CrankshaftChainModes m = crankshaftChainModes(sc, 36);
  ASSERT_TRUE(m.applies) << m.not_applicable;
  ASSERT_EQ(m.modes.size(), 4u);
  ASSERT_EQ(m.segments.size(), 3u);
  // Throws in z order: carts 1, 3, 4, 2; each segment 0.3 m, c = G·I_p/0.3.
  EXPECT_EQ(m.segments[0].cart_a, 1);
  EXPECT_EQ(m.segments[0].cart_b, 3);
  EXPECT_EQ(m.segments[2].cart_b, 2);
  EXPECT_NEAR(m.segments[1].stiffness, 2e6 / 0.3, 1e-6);
  for (double phi : {0.0, 0.7, 2.0}) {
    std::vector<double> J, c;
    chainAtAngle(sc, phi, J, c);
    const std::vector<double> holzer = holzerFrequencies(J, c, 1.5 * m.modes.back().p_max, 40000);
    ASSERT_EQ(holzer.size(), 4u) << "phi " << phi;
    for (size_t k = 0; k < 4; ++k) {
      // The bands are taken over 36 angles; these angles lie between, so allow the band's spread
      // between neighbouring samples (a tenth of the band width each side).
      const double slack = 0.1 * (m.modes[k].p_max - m.modes[k].p_min) + 1e-9 * m.modes[k].p_max;
      EXPECT_GE(holzer[k], m.modes[k].p_min - slack) << "mode " << k + 1 << " phi " << phi;
      EXPECT_LE(holzer[k], m.modes[k].p_max + slack) << "mode " << k + 1 << " phi " << phi;
    }
  }
  EXPECT_NE(m.modes[0].shape.find("coupling"), std::string::npos) << m.modes[0].shape;
}

// A shaft a million times stiffer than the coupling leaves the rigid crankshaft's coupling mode:
// the two-mass frequency with the reduced model's J_n2(φ) of Loveikin, Pochka, Romasevych (2018)
// eq. (9) at the same angle (the shaft's compliance shifts it by ~c/c_shaft = 1e-6 relative).
TEST(ChainModes, AStiffShaftLeavesTheRigidCrankshaftsCouplingMode) {
  const Scene sc = chainScene(1e11 * 0.3);
  const ReducedModel reduced(sc);
  for (double phi : {0.0, 0.4, 1.3}) {
    std::vector<double> J, c;
    chainAtAngle(sc, phi, J, c);
    const double J1 = sc.motorSideInertia(), J2 = reduced.crankSideInertia(phi);
    const double p_rigid = std::sqrt(sc.coupling.stiffness * (J1 + J2) / (J1 * J2));
    const std::vector<double> p = chainNaturalFrequencies(J, c);
    EXPECT_NEAR(p[1], p_rigid, 1e-5 * p_rigid) << "phi " << phi;
  }
}
