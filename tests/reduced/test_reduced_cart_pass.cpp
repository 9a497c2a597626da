// The reduced model's pass over the carts (kinematics, loads, inertia terms) depends only on the
// crank angle and speed: evaluations that differ in twist, twist rate or motor states only (a
// finite-difference Jacobian's columns) reuse it, and give the same numbers bit for bit as a model
// that computes everything afresh.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "reduced/ReducedModel.h"
#include "scene/SceneParser.h"

namespace rollerdyn {
namespace {

Scene balanced(const std::vector<std::string>& sets = {}) {
  return parseSceneFile(std::string(ROLLERDYN_SOURCE_DIR) + "/model/balanced-4cart.yaml", sets);
}

std::vector<double> stateAt(const ReducedModel& m, double phi, double omega, double twist, double rate) {
  std::vector<double> y(size_t(m.stateSize()), 0.0);
  y[size_t(m.iPhi())] = phi;
  y[size_t(m.iOmega())] = omega;
  y[size_t(m.iTwist())] = twist;
  y[size_t(m.iTwistRate())] = rate;
  return y;
}

std::vector<double> derivativesOf(const ReducedModel& m, const std::vector<double>& y) {
  std::vector<double> d(y.size(), 0.0);
  m.derivatives(y.data(), d.data());
  return d;
}

// A Jacobian's stencil at one point: the point, ω ± h, twist ± h, twist rate ± h.
std::vector<std::vector<double>> stencil(const ReducedModel& m) {
  const double phi = 0.7, w = 9.5, psi = 2e-4, rate = 0.03, h = 1e-6;
  return {stateAt(m, phi, w, psi, rate),     stateAt(m, phi, w + h, psi, rate), stateAt(m, phi, w - h, psi, rate),
          stateAt(m, phi, w, psi + h, rate), stateAt(m, phi, w, psi - h, rate), stateAt(m, phi, w, psi, rate + h),
          stateAt(m, phi, w, psi, rate - h)};
}

}  // namespace

TEST(ReducedCartPass, JacobianStencilComputesTheCartsOncePerCrankSpeed) {
  const ReducedModel m(balanced());
  ASSERT_FALSE(m.rigid());
  for (const std::vector<double>& y : stencil(m)) derivativesOf(m, y);
  // Three distinct (φ2, φ̇2): the point and its two speed perturbations; the four twist and
  // twist-rate perturbations share the point's crank angle and speed.
  EXPECT_EQ(m.cartPassesComputed(), 3);
}

TEST(ReducedCartPass, AnotherCrankAngleOrSpeedComputesTheCartsAgain) {
  const ReducedModel m(balanced());
  derivativesOf(m, stateAt(m, 0.7, 9.5, 0, 0));
  derivativesOf(m, stateAt(m, 0.7, 9.5, 1e-4, 0));
  derivativesOf(m, stateAt(m, 0.8, 9.5, 0, 0));
  derivativesOf(m, stateAt(m, 0.8, 9.6, 0, 0));
  EXPECT_EQ(m.cartPassesComputed(), 3);
}

// Kinetostatic normals with guide friction (the friction loop's terms come from the pass) and the
// quasi-static normals with friction (the friction-work check's terms too): each derivative equals
// the one of a model that evaluates that state first.
TEST(ReducedCartPass, ReusedPassGivesTheFreshModelsDerivativesBitForBit) {
  for (const char* normals : {"kinetostatic", "quasi_static"}) {
    const Scene s = balanced({std::string("reduced.guide_normals=") + normals});
    const ReducedModel reused(s);
    for (const std::vector<double>& y : stencil(reused)) {
      const std::vector<double> a = derivativesOf(reused, y);
      const ReducedModel fresh(s);
      const std::vector<double> b = derivativesOf(fresh, y);
      ASSERT_EQ(a.size(), b.size());
      for (size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i], b[i]) << normals << " state " << i;
    }
    EXPECT_LT(reused.cartPassesComputed(), 7) << normals;
  }
}

}  // namespace rollerdyn
