// Each frozen-angle mode's frequency without damping, its damping ratio, natural and damped
// frequency come from one mode's own damped pair. The trials found `modes` printing the coupling
// mode's 63.2 rad/s beside the damping ratio 0.823 of the other mode (a 23 rad/s oscillation),
// because the damped pairs were matched to the modes by the nearest |λ| and an overdamped coupling
// mode has no complex pair to be matched with.
#include <cmath>

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "modes/FrozenModes.h"
#include "scene/SceneParser.h"
#include "reduced/ReducedModel.h"

using namespace rollerdyn;
using namespace rollerdyn::modes;

namespace {

Scene anyScene() { return parseSceneFile(std::string(ROLLERDYN_SOURCE_DIR) + "/model/balanced-4cart.yaml"); }

// A linear drive with known modes: physical coordinates (φ1, φ2) with M = diag(J1, J2); mode B
// (1, 1) (motor side and crank side together) and mode A (J2, -J1) (against each other, the
// coupling's shape) are M-orthogonal. K and C are built diagonal in these modes, so each mode has
// its own damping ratio exactly: λ = -ζω ± iω√(1 - ζ²), or two real λ for ζ > 1. The drive sees
// them in (φ2, ψ = φ1 - φ2), as the models do.
class KnownModesDrive : public DriveModel {
 public:
  KnownModesDrive(double J1, double J2, double wA, double zA, double wB, double zB) : kinematics_(anyScene()) {
    Eigen::Matrix2d Mp = Eigen::Vector2d(J1, J2).asDiagonal();
    Eigen::Matrix2d Phi;
    Phi.col(0) = Eigen::Vector2d(J2, -J1);  // A
    Phi.col(1) = Eigen::Vector2d(1, 1);     // B
    for (int i = 0; i < 2; ++i) Phi.col(i) /= std::sqrt(Phi.col(i).dot(Mp * Phi.col(i)));  // M-orthonormal
    const Eigen::Matrix2d Kp = Mp * Phi * Eigen::Vector2d(wA * wA, wB * wB).asDiagonal() * Phi.transpose() * Mp;
    const Eigen::Matrix2d Cp = Mp * Phi * Eigen::Vector2d(2 * zA * wA, 2 * zB * wB).asDiagonal() * Phi.transpose() * Mp;
    Eigen::Matrix2d T;  // (φ1, φ2) = T·(φ2, ψ)
    T << 1, 1, 1, 0;
    M_ = T.transpose() * Mp * T;
    K_ = T.transpose() * Kp * T;
    C_ = T.transpose() * Cp * T;
  }
  const char* name() const override { return "reduced"; }
  bool elastic() const override { return true; }
  Eigen::Vector2d accelerations(const DrivePoint& p) override {
    return -M_.inverse() * (K_ * Eigen::Vector2d(p.phi, p.twist) + C_ * Eigen::Vector2d(p.omega, p.twist_rate));
  }
  Eigen::MatrixXd massMatrix(double) override { return M_; }
  // The mode names' kinematics: a shipped scene's (the modes' frequencies and damping are this
  // drive's own).
  const ReducedModel& reducedModel() const override { return kinematics_; }

 private:
  Eigen::Matrix2d M_, K_, C_;
  ReducedModel kinematics_;
};

const FrozenMode* modeOf(const FrozenAngle& f, bool torsional) {
  for (const FrozenMode& m : f.modes)
    if (m.torsional == torsional) return &m;
  return nullptr;
}

}  // namespace

// The trial's case: the coupling mode at 63.2 rad/s overdamped (ζ = 1.5), the other mode at
// 40.5 rad/s with ζ = 0.823, oscillating at 40.5·√(1 - 0.823²) = 23.0 rad/s. The coupling mode
// keeps its own ζ = 1.5 and has no damped frequency; the 0.823 and the 23 rad/s stay with the other.
TEST(FrozenModePairs, AnOverdampedCouplingModeKeepsItsOwnDampingRatio) {
  const double wA = 63.2, zA = 1.5, wB = 40.5, zB = 0.823;
  KnownModesDrive drive(73.6, 400.0, wA, zA, wB, zB);
  DrivePoint p;
  p.omega = 10.6;
  const FrozenAngle f = frozenModes(drive, anyScene(), p);
  const FrozenMode* a = modeOf(f, true);
  const FrozenMode* b = modeOf(f, false);
  ASSERT_TRUE(a && b);
  EXPECT_NEAR(a->frequency, wA, 1e-6 * wA);
  EXPECT_NEAR(a->damping_ratio, zA, 1e-6);
  EXPECT_NEAR(a->natural_frequency, wA, 1e-6 * wA);
  EXPECT_FALSE(a->oscillates);  // overdamped: no damped frequency
  EXPECT_NEAR(b->frequency, wB, 1e-6 * wB);
  EXPECT_NEAR(b->damping_ratio, zB, 1e-6);
  EXPECT_TRUE(b->oscillates);
  EXPECT_NEAR(b->damped_frequency, wB * std::sqrt(1 - zB * zB), 1e-6 * wB);
}

// Two oscillating modes 9 % apart in frequency keep their own pairs through the continuation (a
// guard for the matching, not a case the old matching got wrong): each triple satisfies
// ω_d = ω_n·√(1 - ζ²) with the mode's own ω_n, ζ.
TEST(FrozenModePairs, EachModesTripleBelongsToItsOwnPair) {
  const double wA = 63.2, zA = 0.3, wB = 58.0, zB = 0.05;
  KnownModesDrive drive(73.6, 400.0, wA, zA, wB, zB);
  const FrozenAngle f = frozenModes(drive, anyScene(), DrivePoint{});
  const FrozenMode* a = modeOf(f, true);
  const FrozenMode* b = modeOf(f, false);
  ASSERT_TRUE(a && b);
  EXPECT_NEAR(a->damping_ratio, zA, 1e-6);
  EXPECT_NEAR(a->damped_frequency, wA * std::sqrt(1 - zA * zA), 1e-6 * wA);
  EXPECT_NEAR(b->damping_ratio, zB, 1e-6);
  EXPECT_NEAR(b->damped_frequency, wB * std::sqrt(1 - zB * zB), 1e-6 * wB);
}
