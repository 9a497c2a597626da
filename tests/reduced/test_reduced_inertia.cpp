// Reduced inertia J(φ), its derivative, kinematic forms and the load torque of the reduced model.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "reduced/ReducedModel.h"

namespace rollerdyn {
namespace test {
Scene loveikin2018LikeScene();
}

namespace {

// Loveikin and Pochka (2007) set-up: two carts on opposite sides, Δφ = 90°, distributed rods q = 80 kg/m,
// one-mass (rigid) drive, I_o = 0.504 kg·m² reduced by u².
Scene loveikinPochka2007LikeScene() {
  Scene s = test::loveikin2018LikeScene();
  s.carts.count = 2;
  s.carts.side = {1, -1};
  s.carts.mass = 1000;
  s.rods.model = RodModel::Distributed;
  s.rods.mass = 80 * 0.8;                  // l·q
  s.rods.inertia_com = 80 * std::pow(0.8, 3) / 12;  // I_s = q·l³/12
  s.motor.rotor_inertia = 0.138;
  s.coupling.inertia = 0.32;
  s.reducer.inertia = 0.046;
  s.coupling.type = CouplingType::Rigid;
  return s;
}

TEST(ReducedInertia, MatchesLoveikinPochka2007Eq9ForTwoCartsOnOppositeSides) {
  const Scene s = loveikinPochka2007LikeScene();
  const ReducedModel m(s);
  const double r = 0.2, l = 0.8, q = 80, u = 9.8, Io = 0.138 + 0.32 + 0.046, mc = 1000;
  const double Is = q * l * l * l / 12;
  for (double phi = -3.3; phi < 7.0; phi += 0.173) {
    // Loveikin and Pochka (2007) eq. (6), (9) written out, γ = rod angle of cart 2, crank at φ + π/2
    const double S1 = std::sin(phi), C1 = std::cos(phi);
    const double S2 = std::sin(phi + M_PI / 2), C2 = std::cos(phi + M_PI / 2);
    const double w1 = std::sqrt(1 - r * r / (l * l) * S1 * S1);
    const double w2 = std::sqrt(1 - r * r / (l * l) * S2 * S2);
    const double dx1 = -r * S1 * (1 + r / l * C1 / w1);
    const double dx2 = -r * S2 * (1 - r / l * C2 / w2);
    const double dxs6 = -r * S1 * (1 + r / (2 * l) * C1 / w1), dys6 = r / 2 * C1;
    const double dxs7 = -r * S2 * (1 - r / (2 * l) * C2 / w2), dys7 = r / 2 * C2;
    const double db = r / l * C1 / w1, dg = r / l * C2 / w2;
    const double I = Io * u * u + mc * dx1 * dx1 + l * q * (dxs6 * dxs6 + dys6 * dys6) +
                     Is * db * db + mc * dx2 * dx2 + l * q * (dxs7 * dxs7 + dys7 * dys7) +
                     Is * dg * dg;
    EXPECT_NEAR(m.reducedInertia(phi), I, 1e-12 * I) << "phi " << phi;
  }
}

TEST(ReducedInertia, SplitRodsFollowLoveikin2018Eq2And9) {
  const Scene s = test::loveikin2018LikeScene();
  const ReducedModel m(s);
  const double r = 0.2, l = 0.8, mB = 1032;
  for (double phi = 0.0; phi < 6.3; phi += 0.31) {
    double J = 2 * 64 * r * r;  // eq. (2) with J'_K = 0
    for (int j = 0; j < 4; ++j) {
      const double th = phi + j * M_PI / 2;
      const double dx = -r * std::sin(th) -
                        r * r / l * std::sin(th) * std::cos(th) /
                            std::sqrt(1 - std::pow(r / l * std::sin(th), 2));
      J += mB * dx * dx;  // eq. (9), m_B = 1032 kg (eq. (3))
    }
    EXPECT_NEAR(m.crankSideInertia(phi), J, 1e-12 * J);
    EXPECT_NEAR(m.reducedInertia(phi), J, 1e-12 * J);  // elastic: the φ2 equation's inertia
  }
  EXPECT_NEAR(m.motorSideInertia(), (0.4 + 0.32 + 0.046) * 9.8 * 9.8, 1e-12);
}

TEST(ReducedInertia, DerivativeMatchesCentralDifference) {
  for (RodModel model : {RodModel::Distributed, RodModel::Split, RodModel::Massless}) {
    for (KinematicsForm form : {KinematicsForm::Exact, KinematicsForm::Truncated}) {
      Scene s = loveikinPochka2007LikeScene();
      s.carts.count = 3;
      s.carts.side = {1, -1, 1};
      s.crank.offset = 2.0;
      s.rods.model = model;
      s.reduced.kinematics = form;
      const ReducedModel m(s);
      const double h = 1e-5;
      for (double phi = -1.0; phi < 6.0; phi += 0.37) {
        const double fd = (m.reducedInertia(phi + h) - m.reducedInertia(phi - h)) / (2 * h);
        const double an = m.reducedInertiaDerivative(phi);
        EXPECT_NEAR(an, fd, 1e-7 * std::max(1.0, std::abs(fd)))
            << toString(model) << " " << toString(form) << " phi " << phi;
      }
    }
  }
}

// max over a revolution of |J_exact - J_truncated| (carts only) for a given r/l
double maxTruncationDifference(double lambda) {
  Scene s = loveikinPochka2007LikeScene();
  s.rods.model = RodModel::Massless;
  s.rods.length = s.crank.radius / lambda;
  Scene t = s;
  t.reduced.kinematics = KinematicsForm::Truncated;
  const ReducedModel me(s), mt(t);
  double d = 0;
  for (double phi = 0; phi < 2 * M_PI; phi += 0.01) {
    d = std::max(d, std::abs(me.crankSideInertia(phi) - mt.crankSideInertia(phi)));
    for (int j = 0; j < 2; ++j)
      d = std::max(d, 1e3 * std::abs(me.cartPose(j, phi).x_B - mt.cartPose(j, phi).x_B));
  }
  return d;
}

TEST(ReducedInertia, ExactAndTruncatedKinematicsDifferByThirdOrderInRoverL) {
  // x_B: l·[√(1 - λ²sin²θ) - (1 - ½λ²sin²θ)] ≈ -r·λ³·sin⁴θ/8; so halving λ = r/l divides the
  // difference (in x_B and in J) by ≈ 8.
  const double d1 = maxTruncationDifference(0.25);
  const double d2 = maxTruncationDifference(0.125);
  const double d3 = maxTruncationDifference(0.0625);
  EXPECT_GT(d1, 0.0);
  EXPECT_NEAR(std::log2(d1 / d2), 3.0, 0.3);
  EXPECT_NEAR(std::log2(d2 / d3), 3.0, 0.15);
}

TEST(ReducedLoads, LoadTorqueEqualsRodForceMomentOnTheCrank) {
  // Virtual work in world x must agree with the rod force's moment on the crank pin, Loveikin, Pochka, Romasevych (2018)
  // eq. (26)-(30) for σ = +1 (F·r·sin(θ + β)); for σ = -1 the mirrored rod gives
  // F·r·(σ·sin θ·cos β + cos θ·sin β).
  for (auto dir : {RollerForceDirection::AsPrinted, RollerForceDirection::OpposesVelocity}) {
    Scene s = test::loveikin2018LikeScene();
    s.carts.side = {1, -1, -1, 1};
    s.loads.roller_force_direction = dir;
    s.loads.gravity = 9.81;
    s.rods.model = RodModel::Massless;  // no rod gravity torque: M_load is the rod forces only
    const ReducedModel m(s);
    for (double phi = 0.05; phi < 6.3; phi += 0.29) {
      for (double w : {10.0, -7.0}) {
        std::vector<CartEvaluation> carts;
        const double M = m.loadTorque(phi, w, &carts);
        double M_rod = 0.0;
        for (int j = 0; j < 4; ++j) {
          const double th = phi + j * M_PI / 2, b = carts[j].pose.beta, sg = s.carts.side[j];
          M_rod += carts[j].statics.F_rod * 0.2 *
                   (sg * std::sin(th) * std::cos(b) + std::cos(th) * std::sin(b));
        }
        EXPECT_NEAR(M, M_rod, 1e-9 * (1 + std::abs(M_rod))) << "phi " << phi << " w " << w;
      }
    }
  }
}

TEST(ReducedLoads, OpposingRollerForcesAverageToLoveikinPochka2007MeanTorque) {
  // Loveikin and Pochka (2007): two carts, F0 = 3562 N opposing velocity, mean M_o = 2·F0·2r/π = 907 N·m.
  Scene s = loveikinPochka2007LikeScene();
  s.loads.roller_force_front = 3562;
  s.loads.roller_force_rear = 0;
  s.loads.roller_normal_front = s.loads.roller_normal_rear = 0;
  s.loads.guide_friction = 0;
  s.loads.gravity = 9.81;  // rod gravity averages out over a turn
  s.loads.roller_force_direction = RollerForceDirection::OpposesVelocity;
  s.loads.velocity_smoothing = 1e-6;
  const ReducedModel m(s);
  const int N = 20000;
  double mean = 0;
  for (int i = 0; i < N; ++i) mean += m.loadTorque((i + 0.5) * 2 * M_PI / N, 10.0) / N;
  EXPECT_NEAR(mean, 2 * 3562 * 2 * 0.2 / M_PI, 0.5);  // 907.03 N·m printed
}

// The rods' weight as the derivative of their potential, V written out here from the geometry:
// a distributed rod's centre lies halfway between its crank pin (height r·sin θ) and its cart (on
// the axis, height 0), V = Σ m_rod·g·r·sin θ_j/2; a split rod's pin half-mass sits at r·sin θ,
// V = Σ (m_rod/2)·g·r·sin θ_j; a massless rod has none. With no roller forces and no friction
// the resisting torque is dV/dφ (central difference, h = 1e-5: error ~h²·|V'''|/6 ≈ 1e-9 N·m),
// both from loadTorque() and in the right-hand side the integrator uses (evaluate()).
TEST(ReducedLoads, GravityTorqueIsTheDerivativeOfTheRodsPotential) {
  for (RodModel rods : {RodModel::Distributed, RodModel::Split, RodModel::Massless}) {
    Scene s = loveikinPochka2007LikeScene();
    s.carts.count = 3;
    s.carts.side = {1, -1, 1};
    s.crank.offset = 2.0;
    s.rods.model = rods;
    s.loads.roller_force_front = s.loads.roller_force_rear = 0.0;
    s.loads.roller_normal_front = s.loads.roller_normal_rear = 0.0;
    s.loads.guide_friction = 0.0;
    s.loads.gravity = 9.81;
    const ReducedModel m(s);
    const double r = s.crank.radius, g = s.loads.gravity;
    const double mass = rods == RodModel::Distributed ? s.rods.mass : rods == RodModel::Split ? 0.5 * s.rods.mass : 0.0;
    const double height = rods == RodModel::Distributed ? 0.5 : 1.0;
    auto V = [&](double phi) {
      double v = 0;
      for (int j = 0; j < 3; ++j) v += mass * g * height * r * std::sin(phi + j * s.crank.offset);
      return v;
    };
    const double h = 1e-5;
    double largest = 0;
    for (double phi = -1.0; phi < 6.0; phi += 0.37) {
      const double dV = (V(phi + h) - V(phi - h)) / (2 * h);
      largest = std::max(largest, std::abs(dV));
      EXPECT_NEAR(m.loadTorque(phi, 3.0), dV, 1e-6) << toString(rods) << " phi " << phi;
      Eigen::VectorXd y = m.initialState();
      y(m.iPhi()) = phi;
      y(m.iOmega()) = 3.0;
      EXPECT_NEAR(m.evaluate(y).load_torque, dV, 1e-6) << toString(rods) << " phi " << phi << " (right-hand side)";
    }
    if (rods != RodModel::Massless) EXPECT_GT(largest, 10.0);  // torques of tens of N·m: the check has teeth
  }
}

}  // namespace
}  // namespace rollerdyn

namespace rollerdyn {

// Per-cart inputs (docs/per-cart.md): each cart its own m'_B and crank angle.
TEST(ReducedInertia, PerCartMassesAndCrankErrorsFollowTheHandSum) {
  Scene s = test::loveikin2018LikeScene();  // 4 carts, split rods: m_B = m'_B + 32 kg
  s.carts.masses = {1000, 400, 1000, 1000};  // cart 2 empty: the steel frame only, ASSUMED 400 kg
  s.carts.mass = std::nan("");
  s.crank.angle_errors = {0, 0, 2 * M_PI / 180, 0};  // cart 3's crank 2° ahead
  const ReducedModel m(s);
  const double r = 0.2, l = 0.8;
  const double theta0[4] = {0, M_PI / 2, M_PI + 2 * M_PI / 180, 3 * M_PI / 2};
  const double mB[4] = {1032, 432, 1032, 1032};
  for (double phi = 0.0; phi < 6.3; phi += 0.31) {
    double J = 4 * 32 * r * r;  // eq. (2): the rods' halves at the pins, J'_K = 0
    for (int j = 0; j < 4; ++j) {
      const double th = phi + theta0[j];
      const double dx = -r * std::sin(th) -
                        r * r / l * std::sin(th) * std::cos(th) /
                            std::sqrt(1 - std::pow(r / l * std::sin(th), 2));
      J += mB[j] * dx * dx;  // eq. (9) cart by cart
    }
    EXPECT_NEAR(m.crankSideInertia(phi), J, 1e-12 * J) << "phi " << phi;
    const double h = 1e-5;
    const double fd = (m.reducedInertia(phi + h) - m.reducedInertia(phi - h)) / (2 * h);
    EXPECT_NEAR(m.reducedInertiaDerivative(phi), fd, 1e-7 * std::max(1.0, std::abs(fd))) << "phi " << phi;
  }
}

TEST(ReducedLoads, AnEmptyCartDropsExactlyItsOwnLoadTorque) {
  // Without guide friction each cart's generalized force is its own roller force times x_B',
  // so emptying cart 2 (no mix: F_j1 = F_j2 = R_j1 = R_j2 = 0) must change M_load by exactly
  // the term that cart contributed in the uniform scene.
  Scene u = test::loveikin2018LikeScene();
  u.loads.guide_friction = 0;
  u.loads.roller_force_direction = RollerForceDirection::OpposesVelocity;
  Scene e = u;
  e.cart_loads.assign(4, CartLoads{u.loads.roller_force_front, u.loads.roller_force_rear,
                                   u.loads.roller_normal_front, u.loads.roller_normal_rear, 0.0});
  e.cart_loads[1] = CartLoads{};
  const ReducedModel mu(u), me(e);
  for (double phi = 0.05; phi < 6.3; phi += 0.29) {
    std::vector<CartEvaluation> cu;
    const double Mu = mu.loadTorque(phi, 10.0, &cu);
    const double Me = me.loadTorque(phi, 10.0);
    ASSERT_NE(cu[1].generalized_force, 0.0);
    EXPECT_NEAR(Me, Mu + cu[1].generalized_force, 1e-9 * (1 + std::abs(Mu))) << "phi " << phi;
  }
}
}  // namespace rollerdyn
