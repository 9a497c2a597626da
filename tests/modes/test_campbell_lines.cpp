// The Campbell diagram's lines, against a case computed by hand: a drive of constant inertia
// (flywheel, carts of 1 mg, massless rods, no loads) whose coupling mode has Dyomin's p0 at every
// crank speed (Dyomin (two rotors) eq. (10), the project's two-rotor closed form). Order k's forced
// line p = k·ω meets it at ω = p0/k, its parametric line 2p = k·ω at ω = 2·p0/k, for odd k as for
// even k (an audit's plant computed k/2 in integers and moved the order-9 crossing by 12.6 %
// without any test failing). An overdamped coupling mode has no crossings.
#include <cmath>

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "modes/Campbell.h"
#include "modes/DriveOrbit.h"
#include "physics/TwoRotorClosedForm.h"
#include "reduced/ReducedModel.h"
#include "scene/SceneParser.h"

using namespace rollerdyn;
using namespace rollerdyn::modes;

namespace {

Scene constantInertia(const std::string& damping) {
  return parseSceneFile(std::string(ROLLERDYN_SOURCE_DIR) + "/model/balanced-4cart.yaml",
                        {"carts.mass=1e-6", "rods.model=massless", "flywheel.inertia=400", "loads.roller_force_front=0",
                         "loads.roller_force_rear=0", "loads.roller_normal_front=0", "loads.roller_normal_rear=0",
                         "loads.guide_friction.coefficient=0", "loads.gravity=0", "coupling.damping=" + damping});
}

double p0Of(const Scene& s) {
  TwoRotorParameters tp;
  tp.J1 = s.motorSideInertia();
  tp.J2 = ReducedModel(s).crankSideInertia(0.0);  // constant here
  tp.k = s.coupling.stiffness;
  return naturalFrequency(tp);
}

std::vector<double> speedsAround(double lo, double hi, int n) {
  std::vector<double> v;
  for (int i = 0; i < n; ++i) v.push_back(lo + (hi - lo) * i / (n - 1));
  return v;
}

const CampbellCrossing* crossing(const CampbellDiagram& d, int k, bool parametric) {
  for (const CampbellCrossing& c : d.crossings)
    if (c.order == k && c.parametric == parametric) return &c;
  return nullptr;
}

}  // namespace

TEST(CampbellLines, OrderKsForcedCrossingIsAtPOverKAndItsParametricOneAtTwoPOverKForOddKToo) {
  const Scene s = constantInertia("300");
  const double p0 = p0Of(s);
  const SteadyGuess g = steadyGuess(ReducedModel(s));
  ASSERT_TRUE(g.ok) << g.failure;
  // Speeds spanning p0/9 (forced, order 9) and 2·p0/9 (parametric, order 9), and p0/8, p0/4.
  const CampbellDiagram d =
      campbellDiagram(s, g.omega, speedsAround(0.8 * p0 / 9, 1.15 * 2 * p0 / 9, 11), {8, 9}, 12);
  ASSERT_TRUE(d.applicable) << d.note;
  for (const CampbellPoint& p : d.points) ASSERT_TRUE(p.found) << p.failure;
  for (int k : {8, 9}) {
    const CampbellCrossing* forced = crossing(d, k, false);
    const CampbellCrossing* parametric = crossing(d, k, true);
    ASSERT_TRUE(forced && parametric) << "order " << k;
    EXPECT_NEAR(forced->omega, p0 / k, 1e-6 * p0 / k) << "order " << k;
    EXPECT_NEAR(parametric->omega, 2 * p0 / k, 1e-6 * p0 / k) << "order " << k;
    EXPECT_NEAR(forced->frequency, p0, 1e-6 * p0);
    EXPECT_NEAR(parametric->frequency, p0, 1e-6 * p0);
  }
}

// A stiff, heavily damped coupling (c = 2e6 N·m/rad, k = 40000 N·m·s/rad): the two-mass drive with
// the motor's slope on the motor side (about 7450 N·m·s/rad at the crank, the Kloss curve's) has
// four real eigenvalues, checked here by hand: nothing oscillates at any speed, so no line meets
// the mode, and the diagram's note says so.
TEST(CampbellLines, AnOverdampedModeHasNoCrossings) {
  Scene s = constantInertia("40000");
  s.coupling.stiffness = 2e6;
  const double J1 = s.motorSideInertia(), J2 = ReducedModel(s).crankSideInertia(0.0);
  const double c = s.coupling.stiffness, k = s.coupling.damping, b = 7450;
  // (φ1, φ2): J1·φ̈1 = -b·φ̇1 - c·(φ1 - φ2) - k·(φ̇1 - φ̇2), J2·φ̈2 = c·(φ1 - φ2) + k·(φ̇1 - φ̇2)
  Eigen::Matrix4d S = Eigen::Matrix4d::Zero();
  S(0, 2) = S(1, 3) = 1;
  S(2, 0) = -c / J1, S(2, 1) = c / J1, S(2, 2) = -(b + k) / J1, S(2, 3) = k / J1;
  S(3, 0) = c / J2, S(3, 1) = -c / J2, S(3, 2) = k / J2, S(3, 3) = -k / J2;
  const Eigen::Vector4cd ev = Eigen::EigenSolver<Eigen::Matrix4d>(S).eigenvalues();
  for (int i = 0; i < 4; ++i) ASSERT_LT(std::abs(ev(i).imag()), 1e-9 * std::abs(ev(i))) << ev.transpose();
  const double p0 = p0Of(s);
  const SteadyGuess g = steadyGuess(ReducedModel(s));
  ASSERT_TRUE(g.ok) << g.failure;
  const CampbellDiagram d =
      campbellDiagram(s, g.omega, speedsAround(0.8 * p0 / 18, 1.15 * 2 * p0 / 17, 5), {17, 18}, 12);
  ASSERT_TRUE(d.applicable);
  EXPECT_TRUE(d.crossings.empty()) << d.crossings.size() << " crossings, first at " << d.crossings[0].omega;
  EXPECT_NE(d.note.find("overdamped"), std::string::npos) << d.note;
}
