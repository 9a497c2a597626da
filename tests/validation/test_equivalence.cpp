// Fast subset of the validation suite, part (1)-(2): the multibody and the reduced model run on
// the shipped scene files (model/*.yaml), made physically identical where the test says so.
//
// Tolerances:
//  * Equivalent physics, both integrators at relative accuracy 1e-9: crank speed and coupling
//    torque must agree to max_rel_diff <= 1e-6 (kEquivalenceTarget, ValidationSuite.h). The full
//    suite observes 3e-8 (speed) and 2e-7 (torque) over 20 revolutions; the coupling torque
//    c·ψ + k·ψ̇ is a small difference of large speeds and keeps fewer digits. These runs are
//    shorter (1.5-2 s, 2-3 revolutions), so the error has had less time to accumulate.
//  * Kinetostatic reactions (reduced cart statics plus the carts' d'Alembert forces) against
//    the multibody constraint forces, split rods: the two describe the same Newton equations of
//    the cart, so they agree to integration accuracy too; they depend on the acceleration,
//    which both integrators hold less tightly than speeds, hence 1e-5 (observed ~1e-7).
//  * A genuine modelling difference (guide friction from dynamic vs the papers' quasi-static
//    reactions, reduced.guide_normals = quasi_static) must show far above the integration error
//    (> 1e-5) and stay small (< 1 % of the crank speed, < 5 % of the coupling torque): friction
//    itself is f·(|N1|+|N2|) ≈ 0.008·17 kN ≈ 140 N per cart against 15.9 kN roller forces, and
//    only the part due to the carts' inertial forces differs between the models.
//  * The reduced model's kinetostatic normal forces (its default) and the multibody model's
//    algebraic friction law (the minimal formulation's default) solve the same equations of the
//    cart, its rod and the crank, with or without friction: integration error, 1e-5 as above.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "compare/ModelComparison.h"
#include "reduced/ReducedModel.h"
#include "scene/SceneParser.h"

using namespace rollerdyn;

namespace {

std::string modelFile(const std::string& name) { return std::string(ROLLERDYN_SOURCE_DIR) + "/model/" + name; }

const std::vector<std::string> kEquivalent = {"rods.model=split", "loads.guide_friction.coefficient=0",
                                              "reduced.kinematics=exact", "reduced.integrator=cvode",
                                              "simulation.accuracy=1e-9"};

std::vector<std::string> with(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

double maxRelOf(const ModelComparison& c, const std::vector<QuantityComparison>& qs) {
  double m = 0;
  for (const auto& q : qs)
    if (q.name != "omega_crank" && q.name != "coupling_torque") m = std::max(m, q.stats.max_rel_diff);
  return m;
}

}  // namespace

TEST(Equivalence, FourCartsElasticSplitRodsNoFriction) {
  // The README's command, shortened: rollerdyn compare model/balanced-4cart.yaml --set
  // rods.model=split --set loads.guide_friction.coefficient=0 --set simulation.accuracy=1e-9
  const Scene sc = parseSceneFile(modelFile("balanced-4cart.yaml"), with(kEquivalent, {"simulation.t_end=1.5"}));
  const ModelComparison c = runComparison(sc);
  ASSERT_TRUE(c.multibody.stats.complete) << c.multibody.stats.status;
  ASSERT_TRUE(c.reduced.stats.complete) << c.reduced.stats.status;
  EXPECT_TRUE(c.motion_equivalent);
  EXPECT_LE(c.find("omega_crank")->stats.max_rel_diff, 1e-6);
  EXPECT_LE(c.find("coupling_torque")->stats.max_rel_diff, 1e-6);
  EXPECT_LE(maxRelOf(c, c.kinetostatic), 1e-5);
  // The reduced model's own reactions, kinetostatic by default, are the same Newton equations.
  EXPECT_LE(maxRelOf(c, c.quantities), 1e-5);
  // The papers' quasi-static reactions leave out the carts' inertia (~1000 kg at up to ~20 m/s²):
  // a large difference, as documented in `differences`.
  const Scene qs = parseSceneFile(modelFile("balanced-4cart.yaml"),
                                  with(kEquivalent, {"simulation.t_end=1.5", "reduced.guide_normals=quasi_static"}));
  const ModelComparison c_qs = compareRuns(qs, c.multibody, runReducedModel(qs));
  EXPECT_GT(maxRelOf(c_qs, c_qs.quantities), 0.1);
}

TEST(Equivalence, TwoCartsOppositeSidesRigidDrive) {
  // Accuracy 1e-10 here, as in the validation suite: with loads opposing the velocity (Loveikin and Pochka (2007),
  // tanh(v/v_s), v_s = 1 mm/s) the load flips within ~0.1 ms at every cart reversal and the rigid
  // drive's coupling torque M_motor - J_n1·ε carries the acceleration's error; at 1e-9 this 2 s
  // run reaches 7e-7, too close to the target to test reliably. The suite's convergence study
  // shows the difference falling tenfold per decade of accuracy (integration error).
  const Scene sc = parseSceneFile(modelFile("recuperative-2cart.yaml"),
                                  with(kEquivalent, {"simulation.t_end=2", "simulation.accuracy=1e-10"}));
  const ModelComparison c = runComparison(sc);
  ASSERT_TRUE(c.multibody.stats.complete && c.reduced.stats.complete);
  EXPECT_LE(c.find("omega_crank")->stats.max_rel_diff, 1e-6);
  EXPECT_LE(c.find("coupling_torque")->stats.max_rel_diff, 1e-6);
  EXPECT_LE(maxRelOf(c, c.kinetostatic), 1e-5);
}

TEST(Equivalence, DistributedRodsChangeReactionsNotMotion) {
  // Distributed rods: the reduced model's m(x_S'² + y_S'²) + I_S·β'² is the rods' exact kinetic
  // energy (Loveikin and Pochka (2007) eq. (9)), so the motion must agree as for split rods; the reactions differ
  // even kinetostatically by the rods' own inertial forces (m_rod·r·ω²/2 ≈ 730 N against
  // reactions of ~15 kN: a few per cent).
  const Scene sc = parseSceneFile(modelFile("balanced-4cart.yaml"),
                                  {"loads.guide_friction.coefficient=0", "simulation.accuracy=1e-9", "simulation.t_end=1.5"});
  const ModelComparison c = runComparison(sc);
  ASSERT_TRUE(c.multibody.stats.complete && c.reduced.stats.complete);
  EXPECT_LE(c.find("omega_crank")->stats.max_rel_diff, 1e-6);
  EXPECT_LE(c.find("coupling_torque")->stats.max_rel_diff, 1e-6);
  EXPECT_GT(maxRelOf(c, c.kinetostatic), 1e-3);
  // The reduced model's own kinetostatic reactions include the rods' inertial load at the hinge
  // (the rod's moment balance about the crank pin): they agree.
  EXPECT_LE(maxRelOf(c, c.quantities), 1e-5);
}

TEST(Differences, GuideFrictionFromDynamicReactionsIsMeasurable) {
  const Scene sc = parseSceneFile(modelFile("balanced-4cart.yaml"),
                                  {"rods.model=split", "simulation.accuracy=1e-9", "simulation.t_end=1.5",
                                   "reduced.guide_normals=quasi_static"});
  const ModelComparison c = runComparison(sc);
  ASSERT_TRUE(c.multibody.stats.complete && c.reduced.stats.complete);
  EXPECT_FALSE(c.motion_equivalent);
  const double w = c.find("omega_crank")->stats.max_rel_diff;
  const double m = c.find("coupling_torque")->stats.max_rel_diff;
  EXPECT_GT(w, 1e-5);
  EXPECT_LT(w, 1e-2);
  EXPECT_GT(m, 1e-5);
  EXPECT_LT(m, 5e-2);
}

// Per-cart inputs (docs/per-cart.md): the models must stay equivalent when the carts differ.
// Same physics settings and tolerances as FourCartsElasticSplitRodsNoFriction; the non-uniform
// carts only change which terms of the same equations are summed.
const std::vector<std::string> kEmptyCart2 = {"loads.roller_force_front[1]=0", "loads.roller_force_rear[1]=0",
                                              "loads.roller_normal_front[1]=0", "loads.roller_normal_rear[1]=0"};

TEST(Equivalence, OneEmptyCartBothFormulations) {
  for (const char* formulation : {"minimal", "constrained"}) {
    const Scene sc = parseSceneFile(
        modelFile("balanced-4cart.yaml"),
        with(with(kEquivalent, kEmptyCart2), {"simulation.t_end=1.5", std::string("simulation.formulation=") + formulation}));
    const ModelComparison c = runComparison(sc);
    ASSERT_TRUE(c.multibody.stats.complete && c.reduced.stats.complete) << formulation;
    EXPECT_TRUE(c.motion_equivalent);
    EXPECT_LE(c.find("omega_crank")->stats.max_rel_diff, 1e-6) << formulation;
    EXPECT_LE(c.find("coupling_torque")->stats.max_rel_diff, 1e-6) << formulation;
    EXPECT_LE(maxRelOf(c, c.kinetostatic), 1e-5) << formulation;
  }
}

TEST(Equivalence, OneCrankTwoDegreesOffAndALighterCart) {
  const Scene sc = parseSceneFile(modelFile("balanced-4cart.yaml"),
                                  with(kEquivalent, {"crank.angle_error_deg[2]=2", "carts.mass[3]=700",
                                                     "simulation.t_end=1.5"}));
  const ModelComparison c = runComparison(sc);
  ASSERT_TRUE(c.multibody.stats.complete && c.reduced.stats.complete);
  EXPECT_TRUE(c.motion_equivalent);
  EXPECT_LE(c.find("omega_crank")->stats.max_rel_diff, 1e-6);
  EXPECT_LE(c.find("coupling_torque")->stats.max_rel_diff, 1e-6);
  EXPECT_LE(maxRelOf(c, c.kinetostatic), 1e-5);
}

// Each model with its default normal force: the same loop of physics/GuideFrictionLoop.h, built
// once from Simbody's inverse dynamics, once from the reduced model's closed-form cart and rod statics.
void expectKinetostaticFrictionAgrees(const Scene& sc) {
  ASSERT_EQ(sc.loads.guide_normal_force, GuideNormalForce::Algebraic);
  ASSERT_EQ(sc.reduced.guide_normals, ReducedGuideNormals::Kinetostatic);
  const ModelComparison c = runComparison(sc);
  ASSERT_TRUE(c.multibody.stats.complete && c.reduced.stats.complete);
  EXPECT_LE(c.find("omega_crank")->stats.max_rel_diff, 1e-6);
  EXPECT_LE(c.find("coupling_torque")->stats.max_rel_diff, 1e-6);
  EXPECT_LE(maxRelOf(c, c.quantities), 1e-5);
  // The friction forces themselves (not in `quantities`).
  const auto t = c.multibody.reactions.column("t");
  for (int j = 1; j <= sc.carts.count; ++j) {
    const std::string k = "friction_" + std::to_string(j);
    const auto a = c.multibody.reactions.column(k);
    const auto b = resampleLinear(c.reduced.reactions.column("t"), c.reduced.reactions.column(k), t);
    double d = 0, m = 0;
    for (size_t i = 0; i < t.size(); ++i)
      if (std::isfinite(b[i])) d = std::max(d, std::abs(a[i] - b[i])), m = std::max(m, std::abs(a[i]));
    EXPECT_LE(d, 1e-5 * m) << k;
  }
  EXPECT_NEAR(c.multibody.energy.friction_dissipation, c.reduced.energy.friction_dissipation,
              1e-6 * c.multibody.energy.friction_dissipation);
}

TEST(Equivalence, KinetostaticNormalsAndTheAlgebraicFrictionLawAgree) {
  // Guide friction on (f = 0.008, distributed rods: the shipped scene).
  expectKinetostaticFrictionAgrees(
      parseSceneFile(modelFile("balanced-4cart.yaml"), {"simulation.accuracy=1e-9", "simulation.t_end=1.5"}));
}

TEST(Equivalence, KinetostaticFrictionWithCartsOfTheirOwn) {
  // The friction loop with an empty cart, a lighter one and a crank 2 degrees off: each cart's
  // statics read its own mass and loads in both models.
  expectKinetostaticFrictionAgrees(parseSceneFile(
      modelFile("balanced-4cart.yaml"),
      with(kEmptyCart2, {"carts.mass[3]=700", "crank.angle_error_deg[2]=2", "simulation.accuracy=1e-9",
                         "simulation.t_end=1.5"})));
}
