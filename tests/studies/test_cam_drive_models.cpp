// The cam drive (drive.type: cam, Loveikin and Pochka (cam drive paper)) in the scene, the reduced model and the multibody
// model, and the comparison with a crank drive of equal stroke and cycle time.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/Summary.h"
#include "multibody/MultibodySimulation.h"
#include "physics/CamMotionLaw.h"
#include "physics/SliderCrank.h"
#include "reduced/ReducedModel.h"
#include "scene/SceneError.h"
#include "scene/SceneParser.h"
#include "studies/CamStudy.h"

namespace rollerdyn {
namespace {

const std::string kCamScene = std::string(ROLLERDYN_SOURCE_DIR) + "/model/cam-drive.yaml";

TEST(CamScene, ParsesAndValidates) {
  const Scene s = parseSceneFile(kCamScene);
  EXPECT_EQ(s.drive, DriveType::Cam);
  EXPECT_DOUBLE_EQ(s.cam.stroke, 0.4);
  EXPECT_DOUBLE_EQ(s.cam.pusher_distance, 0.8);
  EXPECT_EQ(s.rods.model, RodModel::Massless);  // no rod under a cam
  EXPECT_DOUBLE_EQ(s.rods.mass, 0.0);
  // The default pusher distance is 2·stroke; the profile radius must stay positive.
  EXPECT_DOUBLE_EQ(parseSceneFile(kCamScene, {"cam={stroke: 0.3}"}).cam.pusher_distance, 0.6);
  EXPECT_THROW(parseSceneFile(kCamScene, {"cam.pusher_distance=0.4"}), SceneError);
  EXPECT_THROW(parseSceneFile(kCamScene, {"cam={pusher_distance: 0.8}"}), SceneError);  // no stroke
  EXPECT_THROW(parseSceneFile(kCamScene, {"drive.type=eccentric"}), SceneError);
  // Back to the crank: the same file is a crank drive of equal stroke (2r = Δx).
  const Scene c = parseSceneFile(kCamScene, {"drive.type=crank"});
  EXPECT_EQ(c.drive, DriveType::Crank);
  EXPECT_DOUBLE_EQ(2 * c.crank.radius, s.cam.stroke);
  // A crank scene without cam keys parses as before.
  const Scene b = parseSceneFile(std::string(ROLLERDYN_SOURCE_DIR) + "/model/balanced-4cart.yaml");
  EXPECT_EQ(b.drive, DriveType::Crank);
  EXPECT_EQ(b.rods.model, RodModel::Distributed);
}

TEST(CamDrive, ReducedModelUsesTheCamLaw) {
  Scene s = parseSceneFile(kCamScene, {"carts={count: 2, sides: [same, opposite], mass: 1000}",
                                       "crank.offset_deg=90", "loads.guide_friction.coefficient=0"});
  const ReducedModel m(s);
  for (double phi : {0.0, 0.4, 2.0, 4.0}) {
    for (int j = 0; j < 2; ++j) {
      const double th = phi + j * M_PI / 2, sigma = j == 0 ? 1 : -1;
      const SliderCrankPose p = m.cartPose(j, phi);
      const CamMotionSample c = camMotion(th, 0.4);
      EXPECT_DOUBLE_EQ(p.x_B, sigma * c.x);
      EXPECT_DOUBLE_EQ(p.dx_B, sigma * c.dx);
      EXPECT_DOUBLE_EQ(p.d2x_B, sigma * c.d2x);
      EXPECT_EQ(p.beta, 0.0);
    }
    // J_n2 = J_cams + Σ m·x'² (Loveikin, Pochka, Romasevych (2018) eq. (9) with the cam's transfer function).
    const double J = 2 * 15.0 + 1000 * (std::pow(camMotion(phi, 0.4).dx, 2) + std::pow(camMotion(phi + M_PI / 2, 0.4).dx, 2));
    EXPECT_NEAR(m.crankSideInertia(phi), J, 1e-12 * J);
  }
}

TEST(CamDrive, MultibodyCartFollowsTheCamAndTheCamForceIsMassTimesAcceleration) {
  // No loads, friction or gravity: the only horizontal force on the cart is the cam's, so the
  // reported cam force must be -σ·m·a (F_rod > 0 pulls the cart towards the shaft).
  const Scene s = parseSceneFile(kCamScene, {"simulation.t_end=7", "loads={gravity: 0}",
                                             "simulation.accuracy=1e-8"});
  const RunResult r = runMultibodyModel(s);
  ASSERT_TRUE(r.stats.complete) << r.stats.status;
  const Table& ts = r.timeseries;
  const int iphi = ts.index("phi_crank"), ix = ts.index("x_cart_1"), ia = ts.index("a_cart_1");
  const int iF = r.reactions.index("F_rod_1");
  double a_scale = 0;
  for (const auto& row : ts.rows) a_scale = std::max(a_scale, std::abs(row[ia]));
  ASSERT_GT(a_scale, 0.3);  // the run passes through reversals
  for (std::size_t k = 0; k < ts.rows.size(); ++k) {
    const auto& row = ts.rows[k];
    // The coupler holds x_B = σ·x(θ) to the constraint tolerance (accuracy 1e-8, relative to
    // the 0.4 m stroke: < 1e-7 m; 1e-6 m leaves a margin for the projection).
    EXPECT_NEAR(row[ix], camMotion(row[iphi], 0.4).x, 1e-6) << row[0];
    // Cam force = -m·a (σ = +1, m = 1000 kg), to 1e-6 of the force scale m·max|a|.
    EXPECT_NEAR(r.reactions.rows[k][iF], -1000.0 * row[ia], 1e-6 * 1000 * a_scale) << row[0];
  }
}

TEST(CamDrive, ReducedAndMultibodyModelsAgree) {
  // Same scene, 14 s (2.3 revolutions; window of 1 revolution after the first).
  const Scene s = parseSceneFile(kCamScene, {"simulation.t_end=14", "simulation.steady_window_revolutions=1"});
  const auto mb = makeSummary(s, runMultibodyModel(s));
  const auto rd = makeSummary(s, runReducedModel(s));
  // Both integrate the same equations to 1e-6 relative accuracy; the multibody model also holds
  // a constraint to 1e-6. The differences observed are < 1e-3 relative; 1 % separates a
  // modelling error (a wrong transfer function changes δ and the torque swing by tens of %).
  EXPECT_NEAR(mb["omega_crank"]["mean"].get<double>(), rd["omega_crank"]["mean"].get<double>(),
              1e-3 * rd["omega_crank"]["mean"].get<double>());
  EXPECT_NEAR(mb["delta"].get<double>(), rd["delta"].get<double>(), 0.01 * rd["delta"].get<double>());
  EXPECT_NEAR(mb["coupling_torque_swing"].get<double>(), rd["coupling_torque_swing"].get<double>(),
              0.01 * rd["coupling_torque_swing"].get<double>());
}

TEST(CamVsCrank, PeaksFollowTheKinematicsOfEqualStrokeAndCycleTime) {
  const CamVsCrank c = compareCamWithCrank(kCamScene, {}, "multibody");
  ASSERT_TRUE(c.cam.complete && c.crank.complete);
  ASSERT_TRUE(c.cam.steady && c.crank.steady);
  EXPECT_TRUE(c.note.empty()) << c.note;
  // Equal stroke and cycle time (same drive speed to 1e-3; the stroke is set by the kinematics).
  EXPECT_NEAR(c.cam.stroke, 0.4, 1e-5);
  EXPECT_NEAR(c.crank.stroke, 0.4, 1e-5);
  EXPECT_NEAR(c.cam.t3, c.crank.t3, 1e-3 * c.crank.t3);
  EXPECT_NEAR(c.cam.t3, 3.0, 0.01);  // the scene's design half-cycle time
  // Kinematic peaks at constant speed: cam 13.5·Δx/t3² (eq. (29): 7776Δx·max[τ²(6τ-1)²]/t3²,
  // max at τ = 1/12), crank r·ω²·(1 + r/l) at the dead point, so their ratio is
  // 27/(π²(1 + r/l)) = 2.1885 whatever t3.
  EXPECT_NEAR(c.cam.accel_peak_kinematic / c.crank.accel_peak_kinematic, 27 / (M_PI * M_PI * 1.25), 1e-3);
  EXPECT_NEAR(c.cam.accel_peak_kinematic, 13.5 * 0.4 / std::pow(c.cam.t3, 2), 1e-3 * c.cam.accel_peak_kinematic);
  // Dynamic peaks stay within the speed fluctuation of the kinematic ones: a = x''ω² + x'ε
  // deviates from x''ω̄² by about 2δ (δ = 0.08 cam, 0.04 crank) plus the x'ε term; 20 % bounds it.
  EXPECT_NEAR(c.cam.accel_peak, c.cam.accel_peak_kinematic, 0.2 * c.cam.accel_peak_kinematic);
  EXPECT_NEAR(c.crank.accel_peak, c.crank.accel_peak_kinematic, 0.2 * c.crank.accel_peak_kinematic);
  // The cam's constant-speed stroke lowers the peak speed and with it the peak load torque
  // F·x'(θ): cam x'max = 6Δx/(5π), crank x'max ≈ 1.0307·r (l/r = 4), ratio 0.741. The coupling
  // carries that torque quasi-statically (its mode is far above the cycle frequency), so the
  // coupling-torque peaks keep the ratio to a few %.
  const double ratio = (6 * 0.4 / (5 * M_PI)) / (0.2 * 1.0307);
  EXPECT_NEAR(c.cam.coupling_torque_max / c.crank.coupling_torque_max, ratio, 0.03);
  // The rolling resistance (2·7962 N) dominates both drive forces; the cam's is horizontal,
  // the rod's has the 1/cos β of Loveikin, Pochka, Romasevych (2018) eq. (14) and smaller inertial terms: within 2 %.
  EXPECT_NEAR(c.cam.force_abs_peak, c.crank.force_abs_peak, 0.02 * c.crank.force_abs_peak);
  EXPECT_GT(c.cam.force_abs_peak, 15924.0);
}

}  // namespace
}  // namespace rollerdyn
