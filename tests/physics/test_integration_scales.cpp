// The natural scales both models' error control reads (src/physics/IntegrationScales.h), each
// against its definition by hand: the reference speed ω_ref, the torque M_ref, the coupling's
// twist scale, and the cam drive's step cap, which both models once computed for themselves.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "physics/IntegrationScales.h"
#include "scene/SceneParser.h"

using namespace rollerdyn;

namespace {
constexpr double kNoPrescribedSpeed = std::numeric_limits<double>::quiet_NaN();
constexpr double kPi = 3.14159265358979323846;

Scene shipped(const std::string& name, const std::vector<std::string>& sets = {}) {
  return parseSceneFile(std::string(ROLLERDYN_SOURCE_DIR) + "/model/" + name + ".yaml", sets);
}
}  // namespace

TEST(IntegrationScales, ReferenceSpeedIsTheSynchronousCrankSpeedOrThePrescribedOne) {
  const Scene sc = shipped("balanced-4cart");
  const IntegrationScales k = integrationScales(sc, kNoPrescribedSpeed, 1000.0);
  EXPECT_DOUBLE_EQ(k.speed, sc.motor.omega_sync / sc.reducer.ratio);
  EXPECT_DOUBLE_EQ(k.cvode_rtol, kAccuracyToCvodeTolerance * sc.simulation.accuracy);
  EXPECT_DOUBLE_EQ(integrationScales(sc, -7.5, 1000.0).speed, 7.5);
  EXPECT_DOUBLE_EQ(integrationScales(sc, 0.2, 1000.0).speed, 1.0);  // at least 1 rad/s
  const Scene off = shipped("balanced-4cart", {"motor.enabled=false", "initial.crank_speed=4"});
  EXPECT_DOUBLE_EQ(integrationScales(off, kNoPrescribedSpeed, 1000.0).speed, 4.0);
}

TEST(IntegrationScales, TwistScaleIsTheTorqueScaleOverTheCouplingStiffness) {
  const Scene sc = shipped("balanced-4cart");
  const double M_kr = 1000.0;  // [N·m at the rotor]
  const IntegrationScales k = integrationScales(sc, kNoPrescribedSpeed, M_kr);
  const double M_ref = std::max({M_kr * sc.reducer.ratio * sc.reducer.efficiency, sc.rollerForceSum() * sc.crank.radius, 1.0});
  EXPECT_DOUBLE_EQ(k.torque, M_ref);
  EXPECT_DOUBLE_EQ(k.twist, M_ref / sc.coupling.stiffness);
  EXPECT_DOUBLE_EQ(k.twist_rate, k.twist * std::sqrt(sc.coupling.stiffness / sc.motorSideInertia()));
  const IntegrationScales rigid = integrationScales(shipped("balanced-4cart", {"coupling.type=rigid"}), kNoPrescribedSpeed, M_kr);
  EXPECT_EQ(rigid.twist, 0.0);
  EXPECT_EQ(rigid.twist_rate, 0.0);
}

TEST(IntegrationScales, OnlyACamDriveCapsTheStepAtAnEighthOfItsShortestSegment) {
  const Scene cam = shipped("cam-drive");
  ASSERT_TRUE(cam.hasCamDrive());
  const IntegrationScales k = integrationScales(cam, kNoPrescribedSpeed, 1000.0);
  EXPECT_DOUBLE_EQ(k.max_step, (kPi / 6.0) / k.speed / 8.0);  // a crank angle of π/6 at ω_ref, over 8
  EXPECT_GT(k.max_step, 0.0);
  EXPECT_EQ(integrationScales(shipped("balanced-4cart"), kNoPrescribedSpeed, 1000.0).max_step, 0.0);  // unbounded
}
