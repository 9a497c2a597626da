// Frozen-angle modes and the steady motion's Floquet analysis of the shipped drives, against
// closed forms (Dyomin's p0) and between the two models.
#include <chrono>
#include <cmath>

#include <gtest/gtest.h>

#include "modes/DriveModels.h"
#include "modes/DriveOrbit.h"
#include "modes/FrozenModes.h"
#include "physics/TwoRotorClosedForm.h"
#include "reduced/ReducedModel.h"
#include "scene/SceneParser.h"

using namespace rollerdyn;
using namespace rollerdyn::modes;

namespace {

Scene shipped(const std::string& name, const std::vector<std::string>& overrides = {}) {
  return parseSceneFile(std::string(ROLLERDYN_SOURCE_DIR) + "/model/" + name + ".yaml", overrides);
}

// The balanced four-cart machine with a constant crank-side inertia: a flywheel, carts of 1 mg
// and massless rods (J_n2 varies by 1e-6·r² kg·m² over a turn: 1e-10 of the flywheel's 400),
// no loads, friction or gravity. The drive is then Dyomin's two rotors.
Scene constantInertiaScene() {
  return shipped("balanced-4cart", {"carts.mass=1e-6", "rods.model=massless", "flywheel.inertia=400",
                                    "loads.roller_force_front=0", "loads.roller_force_rear=0",
                                    "loads.roller_normal_front=0", "loads.roller_normal_rear=0",
                                    "loads.guide_friction.coefficient=0", "loads.gravity=0"});
}

}  // namespace

TEST(FrozenModes, ConstantInertiaGivesDyominP0InBothModels) {
  const Scene s = constantInertiaScene();
  const ReducedModel rm(s);
  for (auto make : {makeReducedDrive, makeMultibodyDrive}) {
    auto drive = make(s);
    for (double phi : {0.0, 0.7, 2.0}) {
      DrivePoint p;
      p.phi = phi;
      p.omega = 10.6;
      const FrozenAngle f = frozenModes(*drive, s, p);
      TwoRotorParameters tp;
      tp.J1 = s.motorSideInertia();
      tp.J2 = rm.crankSideInertia(phi);
      tp.k = s.coupling.stiffness;
      const double p0 = naturalFrequency(tp);  // Dyomin (two rotors) eq. (10)
      EXPECT_NEAR(f.torsional_frequency(), p0, 1e-8 * p0) << drive->name() << " at " << phi;
    }
  }
}

// Where both models describe the same physics (split rods, no guide friction: the validation
// suite's equivalence conditions), their frozen frequencies agree.
TEST(FrozenModes, MultibodyAndReducedAgree) {
  const Scene s = shipped("balanced-4cart", {"rods.model=split", "loads.guide_friction.coefficient=0"});
  auto red = makeReducedDrive(s);
  auto mb = makeMultibodyDrive(s);
  for (double phi : {0.0, 0.3, 1.1, 2.5, 4.0}) {
    DrivePoint p;
    p.phi = phi;
    p.omega = 10.5;
    p.twist = 0.004;
    p.twist_rate = 0.01;
    const FrozenAngle a = frozenModes(*red, s, p), b = frozenModes(*mb, s, p);
    EXPECT_NEAR((a.M - b.M).norm(), 0.0, 1e-10 * a.M.norm()) << phi;
    ASSERT_EQ(a.modes.size(), 2u);
    ASSERT_EQ(b.modes.size(), 2u);
    EXPECT_NEAR(a.torsional_frequency(), b.torsional_frequency(), 1e-6 * a.torsional_frequency()) << phi;
    EXPECT_NEAR(a.modes[0].lambda, b.modes[0].lambda, 1e-6 * std::abs(a.modes[1].lambda)) << phi;
  }
}

TEST(SteadyMotion, BalancedFourCartRunsStably) {
  const Scene s = shipped("balanced-4cart");
  auto red = makeReducedDrive(s);
  const auto t0 = std::chrono::steady_clock::now();
  const SteadyMotion m = steadyMotion(*red, s);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_TRUE(m.found) << m.failure;
  std::printf("steady motion: omega_mean %.6f, T %.6f, Newton %d, %.3f s\n", m.omega_mean, m.period,
              m.newton_iterations, secs);
  for (const auto& c : m.multipliers)
    std::printf("  mu = %.6g%+.6gi |mu| %.6g kind %s f %.4g zeta %.4g\n", c.m.mu.real(), c.m.mu.imag(),
                c.m.modulus, toString(c.kind), c.m.frequency, c.m.damping_ratio);
  EXPECT_TRUE(m.verdict.stable);
}
