// The laws both models share, each against its formula written out here: Kloss's motor torque
// from the catalogue data of a scene file (Loveikin, Pochka, Romasevych (2018), eq. (37)), the
// compacting-roller force under both readings and the guide friction's direction
// (physics/RollerLoads.h).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "physics/KlossMotor.h"
#include "physics/RollerLoads.h"
#include "scene/SceneParser.h"

namespace rollerdyn {
namespace {

// s_n = 1 − ω_n/ω0, s_kr = s_n·(λ + √(λ² − 1)), M = 2·M_kr/(s/s_kr + s_kr/s) at the rotor and
// M·u·η at the crank, from the scene file's motor.omega_sync, omega_nominal, overload_ratio and
// breakdown_torque and its reducer (4A200M6U3: s_kr ≈ 0.1145 as the paper prints).
TEST(KlossMotor, TorqueFollowsEq37FromTheCatalogueData) {
  const Scene sc = parseSceneFile(std::string(ROLLERDYN_SOURCE_DIR) + "/model/balanced-4cart.yaml");
  const double w0 = 104.72, wn = 102.1, lam = 2.4, Mkr = 517.14, u = 9.8, eta = 0.9;  // the file's values
  ASSERT_EQ(sc.motor.omega_sync, w0);
  ASSERT_EQ(sc.motor.breakdown_torque, Mkr);
  const double s_n = 1 - wn / w0, s_kr = s_n * (lam + std::sqrt(lam * lam - 1));
  EXPECT_NEAR(s_kr, 0.1145, 2e-4);  // as printed, from s_n rounded to 0.025
  for (double s : {-0.05, -0.003, 0.002, 0.025, s_kr, 0.3, 1.0}) {
    const double M = 2 * Mkr / (s / s_kr + s_kr / s);
    const double w_rotor = w0 * (1 - s);
    EXPECT_NEAR(klossRotorTorque(sc.motor, w_rotor), M, 1e-12 * Mkr) << "s " << s;
    EXPECT_NEAR(klossCrankTorque(sc.motor, u, eta, w_rotor / u), M * u * eta, 1e-12 * Mkr * u) << "s " << s;
  }
  EXPECT_NEAR(klossRotorTorque(sc.motor, w0 * (1 - s_kr)), Mkr, 1e-12 * Mkr);  // breakdown at s_kr
  EXPECT_EQ(klossRotorTorque(sc.motor, w0), 0.0);                                 // none at synchronous speed
}

// Along the cart's local axis x' (pointing away from the shaft): as printed, +(F_front + F_rear)
// whatever the velocity (Loveikin, Pochka, Romasevych (2018), fig. 3); opposing the velocity,
// −(F_front + F_rear)·tanh(v'/v_s); guide friction's direction factor −tanh(v'/v_s) (friction
// opposes the velocity under either reading). Front and rear forces differ so that their sum
// is checked, and v' = v_s checks the smoothing width.
TEST(RollerLoads, AsPrintedPushesAwayOpposingResistsAndFrictionOpposesTheVelocity) {
  Loads L{};
  L.roller_force_front = 5000.0;
  L.roller_force_rear = 3000.0;
  L.velocity_smoothing = 1e-3;
  L.roller_force_direction = RollerForceDirection::AsPrinted;
  for (double v : {-2.0, -1e-3, 0.0, 1e-3, 2.0}) EXPECT_EQ(rollerHorizontalForce(L, v), 8000.0) << v;
  L.roller_force_direction = RollerForceDirection::OpposesVelocity;
  EXPECT_NEAR(rollerHorizontalForce(L, 2.0), -8000.0, 1e-9);
  EXPECT_NEAR(rollerHorizontalForce(L, -2.0), 8000.0, 1e-9);
  EXPECT_NEAR(rollerHorizontalForce(L, 1e-3), -8000.0 * std::tanh(1.0), 1e-9);
  EXPECT_NEAR(rollerHorizontalForce(L, -0.5e-3), 8000.0 * std::tanh(0.5), 1e-9);
  EXPECT_EQ(rollerHorizontalForce(L, 0.0), 0.0);
  for (RollerForceDirection d : {RollerForceDirection::AsPrinted, RollerForceDirection::OpposesVelocity}) {
    L.roller_force_direction = d;
    EXPECT_NEAR(frictionDirection(L, 2.0), -1.0, 1e-12);
    EXPECT_NEAR(frictionDirection(L, -2.0), 1.0, 1e-12);
    EXPECT_NEAR(frictionDirection(L, 1e-3), -std::tanh(1.0), 1e-12);
  }
}

}  // namespace
}  // namespace rollerdyn
