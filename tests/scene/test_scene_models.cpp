// The shipped model files parse to the papers' numbers, and values derived by the parser
// (radians, critical slip, defaults) are right.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "SceneTestSupport.h"
#include "scene/SceneParser.h"

namespace rollerdyn {
namespace {

using test::kMinimalScene;
using test::replaced;

std::string modelPath(const std::string& name) {
  return std::string(ROLLERDYN_SOURCE_DIR) + "/model/" + name;
}

TEST(SceneModels, Balanced4CartMatchesLoveikin2018) {
  const Scene s = parseSceneFile(modelPath("balanced-4cart.yaml"));
  EXPECT_EQ(s.name, "balanced-4cart");
  EXPECT_NE(s.source.find("Romasevych Yu.O. (2018)"), std::string::npos);
  EXPECT_EQ(s.carts.count, 4);
  EXPECT_EQ(s.carts.side, (std::vector<int>{1, 1, 1, 1}));
  EXPECT_DOUBLE_EQ(s.crank.offset, M_PI / 2);
  EXPECT_DOUBLE_EQ(s.crank.radius, 0.2);
  EXPECT_DOUBLE_EQ(s.rods.length, 0.8);
  EXPECT_EQ(s.rods.model, RodModel::Distributed);
  EXPECT_NEAR(s.rods.inertia_com, 64.0 * 0.64 / 12.0, 1e-12);
  EXPECT_EQ(s.coupling.type, CouplingType::Elastic);
  EXPECT_DOUBLE_EQ(s.coupling.stiffness, 200000.0);
  EXPECT_DOUBLE_EQ(s.coupling.damping, 8000.0);
  // Paper: s_n = 0.025, s_kr = 0.1145 (from omega_n = 102.1, lambda = 2.4).
  EXPECT_NEAR(s.motor.critical_slip, 0.1145, 2e-4);
  EXPECT_EQ(s.loads.roller_force_direction, RollerForceDirection::AsPrinted);
  EXPECT_DOUBLE_EQ(s.loads.roller_force_front, 7962.0);
  EXPECT_DOUBLE_EQ(s.loads.roller_normal_rear, 9740.0);
  EXPECT_DOUBLE_EQ(s.loads.guide_friction, 0.008);
  EXPECT_DOUBLE_EQ(s.carts.geometry.b, 0.37);
  EXPECT_DOUBLE_EQ(s.carts.geometry.d, 0.046);
  EXPECT_DOUBLE_EQ(s.simulation.t_end, 10.0);
  EXPECT_DOUBLE_EQ(s.simulation.output_step, 0.005);
  EXPECT_NEAR(s.motorSideInertia(), (0.4 + 0.32 + 0.046) * 9.8 * 9.8, 1e-9);
  EXPECT_DOUBLE_EQ(s.initial.crank_speed, 0.0);
}

TEST(SceneModels, Recuperative2CartMatchesLoveikinPochka2007) {
  const Scene s = parseSceneFile(modelPath("recuperative-2cart.yaml"));
  EXPECT_EQ(s.name, "recuperative-2cart");
  EXPECT_EQ(s.carts.count, 2);
  EXPECT_EQ(s.carts.side, (std::vector<int>{1, -1}));
  EXPECT_DOUBLE_EQ(s.crank.offset, M_PI / 2);
  EXPECT_EQ(s.coupling.type, CouplingType::Rigid);
  EXPECT_NEAR(s.motor.critical_slip, 1.0 - 94.95 / 104.72, 1e-12);
  EXPECT_NEAR(s.rods.inertia_com, 80.0 * 0.8 * 0.8 * 0.8 / 12.0, 1e-8);  // I_s = q·l³/12
  EXPECT_EQ(s.loads.roller_force_direction, RollerForceDirection::OpposesVelocity);
  // F0 = 3562 N per cart, split over the two roller keys.
  EXPECT_DOUBLE_EQ(s.loads.roller_force_front + s.loads.roller_force_rear, 3562.0);
  EXPECT_DOUBLE_EQ(s.loads.guide_friction, 0.0);
  EXPECT_NEAR(s.motorSideInertia(), (0.138 + 0.32 + 0.036) * 9.8 * 9.8, 1e-9);
  EXPECT_DOUBLE_EQ(s.reducer.efficiency, 0.9);
  EXPECT_DOUBLE_EQ(s.simulation.t_end, 15.0);
}

TEST(SceneModels, EnergyBalanced3CartMatchesEnergyBalancedDrivePaper) {
  const Scene s = parseSceneFile(modelPath("energy-balanced-3cart.yaml"));
  EXPECT_EQ(s.carts.count, 3);
  EXPECT_EQ(s.carts.side, (std::vector<int>{1, 1, 1}));
  EXPECT_NEAR(s.crank.offset, 2.0 * M_PI / 3.0, 1e-12);
  EXPECT_DOUBLE_EQ(s.motor.breakdown_torque, 293.8);
  EXPECT_DOUBLE_EQ(s.reducer.efficiency, 0.95);
  // The paper's I_o = 0.539 kg·m² reduced with u = 9.8.
  EXPECT_NEAR(s.motorSideInertia(), 0.539 * 9.8 * 9.8, 1e-9);
  EXPECT_EQ(s.flywheel.location, FlywheelLocation::Crankshaft);
  EXPECT_DOUBLE_EQ(s.flywheel.inertia, 0.0);
  EXPECT_EQ(s.coupling.type, CouplingType::Rigid);
}

TEST(SceneModels, FlywheelOverrideReachesCrankSideInertia) {
  const Scene s = parseSceneFile(modelPath("energy-balanced-3cart.yaml"), {"flywheel.inertia=250"});
  EXPECT_DOUBLE_EQ(s.crankSideInertia(), 250.0);
  EXPECT_TRUE(s.hasFlywheel());
}

TEST(SceneDerived, DegreesBecomeRadians) {
  std::string y = replaced("  offset_deg: 90", "  offset_deg: 120");
  y += "initial:\n  crank_angle_deg: 30\nreduced:\n  baranov_step_deg: 0.5\n";
  const Scene s = parseSceneText(y, "test.yaml");
  EXPECT_NEAR(s.crank.offset, 2.0 * M_PI / 3.0, 1e-15);
  EXPECT_NEAR(s.initial.crank_angle, M_PI / 6.0, 1e-15);
  EXPECT_NEAR(s.reduced.baranov_step, 0.5 * M_PI / 180.0, 1e-15);
  EXPECT_NEAR(s.crankPhase(2), 4.0 * M_PI / 3.0, 1e-15);
}

TEST(SceneDerived, CriticalSlipGivenDirectly) {
  EXPECT_DOUBLE_EQ(parseSceneText(kMinimalScene, "t.yaml").motor.critical_slip, 0.1);
}

TEST(SceneDerived, CriticalSlipFromCriticalSpeed) {
  const std::string y = replaced("  critical_slip: 0.1", "  omega_critical: 94.95");
  EXPECT_NEAR(parseSceneText(y, "t.yaml").motor.critical_slip, 1.0 - 94.95 / 104.72, 1e-15);
}

TEST(SceneDerived, CriticalSlipFromNominalSpeedAndOverloadRatio) {
  const std::string y =
      replaced("  critical_slip: 0.1", "  omega_nominal: 102.1\n  overload_ratio: 2.4");
  const double s_n = 1.0 - 102.1 / 104.72;
  const double expected = s_n * (2.4 + std::sqrt(2.4 * 2.4 - 1.0));
  EXPECT_NEAR(parseSceneText(y, "t.yaml").motor.critical_slip, expected, 1e-15);
  EXPECT_NEAR(expected, 0.1146, 1e-4);  // Loveikin, Pochka, Romasevych (2018) prints 0.1145
}

TEST(SceneDerived, DocumentedDefaults) {
  const Scene s = parseSceneText(kMinimalScene, "dir/minimal.yaml");
  EXPECT_EQ(s.name, "minimal");
  EXPECT_EQ(s.source_path, "dir/minimal.yaml");
  EXPECT_EQ(s.source, "unit-test scene");
  EXPECT_DOUBLE_EQ(s.simulation.accuracy, 1e-6);
  EXPECT_EQ(s.simulation.integrator, "RungeKuttaMerson");
  EXPECT_DOUBLE_EQ(s.simulation.output_step, 0.005);
  EXPECT_DOUBLE_EQ(s.simulation.constraint_tolerance, 1e-6);
  EXPECT_DOUBLE_EQ(s.simulation.steady_window_revolutions, 5.0);
  EXPECT_DOUBLE_EQ(s.initial.crank_angle, 0.0);
  EXPECT_DOUBLE_EQ(s.initial.twist, 0.0);
  EXPECT_DOUBLE_EQ(s.crank.inertia_per_crank, 0.0);
  EXPECT_DOUBLE_EQ(s.crank.shaft_inertia, 0.0);
  EXPECT_NEAR(s.rods.inertia_com, 64.0 * 0.8 * 0.8 / 12.0, 1e-12);
  EXPECT_EQ(s.carts.side, (std::vector<int>{1, 1}));
  EXPECT_DOUBLE_EQ(s.carts.geometry.b, 0.0);
  EXPECT_TRUE(s.motor.enabled);
  EXPECT_DOUBLE_EQ(s.reducer.inertia, 0.0);
  EXPECT_DOUBLE_EQ(s.reducer.delta, 1.0);
  EXPECT_DOUBLE_EQ(s.coupling.damping, 0.0);
  EXPECT_DOUBLE_EQ(s.coupling.inertia, 0.0);
  EXPECT_DOUBLE_EQ(s.flywheel.inertia, 0.0);
  EXPECT_EQ(s.flywheel.location, FlywheelLocation::Crankshaft);
  EXPECT_DOUBLE_EQ(s.loads.roller_force_front, 0.0);
  EXPECT_EQ(s.loads.roller_force_direction, RollerForceDirection::OpposesVelocity);
  EXPECT_DOUBLE_EQ(s.loads.guide_friction, 0.0);
  EXPECT_DOUBLE_EQ(s.loads.gravity, 9.81);
  EXPECT_DOUBLE_EQ(s.loads.velocity_smoothing, 1e-3);
  EXPECT_EQ(s.reduced.kinematics, KinematicsForm::Exact);
  EXPECT_EQ(s.reduced.integrator, ReducedIntegrator::Cvode);
  EXPECT_NEAR(s.reduced.baranov_step, M_PI / 180.0, 1e-15);
}

TEST(SceneDerived, ConstraintToleranceFollowsAccuracy) {
  const std::string y = replaced("  t_end: 1.0", "  t_end: 1.0\n  accuracy: 1.0e-8");
  EXPECT_DOUBLE_EQ(parseSceneText(y, "t.yaml").simulation.constraint_tolerance, 1e-8);
  const std::string z = replaced("  t_end: 1.0", "  t_end: 1.0\n  constraint_tolerance: 1.0e-4");
  EXPECT_DOUBLE_EQ(parseSceneText(z, "t.yaml").simulation.constraint_tolerance, 1e-4);
}

TEST(SceneDerived, SidesShorthands) {
  const std::string three = replaced("  count: 2", "  count: 3");
  EXPECT_EQ(parseSceneText(replaced("  mass: 1000", "  mass: 1000\n  sides: alternate", three),
                           "t.yaml").carts.side,
            (std::vector<int>{1, -1, 1}));
  EXPECT_EQ(parseSceneText(replaced("  mass: 1000", "  mass: 1000\n  sides: opposite", three),
                           "t.yaml").carts.side,
            (std::vector<int>{-1, -1, -1}));
  EXPECT_EQ(parseSceneText(replaced("  mass: 1000", "  mass: 1000\n  sides: [opposite, same, same]",
                                    three), "t.yaml").carts.side,
            (std::vector<int>{-1, 1, 1}));
}

TEST(SceneDerived, MasslessRodsNeedNoMass) {
  std::string y = replaced("  model: distributed", "  model: massless");
  y = test::without("  mass: 64", y);
  const Scene s = parseSceneText(y, "t.yaml");
  EXPECT_EQ(s.rods.model, RodModel::Massless);
  EXPECT_DOUBLE_EQ(s.rods.mass, 0.0);
  EXPECT_DOUBLE_EQ(s.rods.inertia_com, 0.0);
}

TEST(SceneDerived, EmptySectionTakesDefaults) {
  const Scene s = parseSceneText(kMinimalScene + "flywheel:\n", "t.yaml");
  EXPECT_DOUBLE_EQ(s.flywheel.inertia, 0.0);
}

}  // namespace
}  // namespace rollerdyn
