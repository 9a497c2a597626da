// The guide-friction loop (physics/GuideFrictionLoop.h) against a brute-force fixed point of its
// own definition, F_j = c_j·(|N_front,j| + |N_rear,j|) with N_j = n0_j + n_eps_j·ε + n_F_j·F_j and
// ε = ε0 + Σ w_j·F_j, and its reports where the loop has no unique solution. The expected values
// come from iterating the definition (plain fixed point, no sign logic), never from the solver.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "physics/GuideFrictionLoop.h"

namespace rollerdyn {
namespace {

// The definition iterated 400 times from F = 0 (a contraction of ratio <= 0.5 here: round-off).
void bruteForce(const std::vector<GuideLoopCart>& carts, double eps0, std::vector<double>& F, double& eps) {
  F.assign(carts.size(), 0.0);
  eps = eps0;
  for (int it = 0; it < 400; ++it) {
    double e = eps0;
    for (size_t j = 0; j < carts.size(); ++j) e += carts[j].w * F[j];
    eps = e;
    for (size_t j = 0; j < carts.size(); ++j) {
      const GuideLoopCart& c = carts[j];
      const double n0 = c.n0[0] + c.n_eps[0] * eps + c.n_F[0] * F[j];
      const double n1 = c.n0[1] + c.n_eps[1] * eps + c.n_F[1] * F[j];
      F[j] = c.c * (std::abs(n0) + std::abs(n1));
    }
  }
}

TEST(GuideFrictionLoop, SolvesTheDefinitionForRandomCartsWithSignChanges) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  int with_sign_change = 0;
  for (int trial = 0; trial < 500; ++trial) {
    const int n = 1 + trial % 8;
    std::vector<GuideLoopCart> carts(n);
    for (GuideLoopCart& c : carts) {
      for (int i = 0; i < 2; ++i) {
        c.n0[i] = 5000.0 * U(rng);
        c.n_eps[i] = 300.0 * U(rng);
        c.n_F[i] = 2.0 * U(rng);  // a rod at up to 60°: the friction tips the cart
      }
      c.c = 0.1 * U(rng);  // up to f = 0.1, either direction
      c.w = 1e-4 * U(rng);  // the brute force below must contract: Lipschitz <= 0.1·(4 + 600·8e-4) < 0.5
    }
    const double eps0 = 20.0 * U(rng);
    std::vector<double> F(n), N(2 * n);
    const GuideLoopResult r = solveGuideFrictionLoop(carts.data(), n, eps0, F.data(), N.data());
    ASSERT_EQ(r.status, LoopStatus::Solved) << "trial " << trial;
    std::vector<double> F_ref;
    double eps_ref = 0;
    bruteForce(carts, eps0, F_ref, eps_ref);
    EXPECT_NEAR(r.eps, eps_ref, 1e-9 * (1.0 + std::abs(eps_ref))) << "trial " << trial;
    for (int j = 0; j < n; ++j) {
      EXPECT_NEAR(F[j], F_ref[j], 1e-9 * (1.0 + std::abs(F_ref[j]))) << "trial " << trial << " cart " << j;
      for (int i = 0; i < 2; ++i) {
        const double N_ref = carts[j].n0[i] + carts[j].n_eps[i] * eps_ref + carts[j].n_F[i] * F_ref[j];
        EXPECT_NEAR(N[2 * j + i], N_ref, 1e-8 * (1.0 + std::abs(N_ref)));
        const double N_free = carts[j].n0[i] + carts[j].n_eps[i] * eps0;
        if (N_free * N_ref < 0) ++with_sign_change;
      }
    }
    EXPECT_LE(r.passes, 6) << "trial " << trial;  // a few linear solves, not an iteration to round-off
  }
  EXPECT_GT(with_sign_change, 10);  // the sign logic was exercised
}

TEST(GuideFrictionLoop, WithoutFrictionReturnsTheFrictionFreeValuesInOnePass) {
  GuideLoopCart c;
  c.n0[0] = 1200;
  c.n0[1] = -300;
  c.n_eps[0] = 40;
  c.n_eps[1] = -10;
  c.n_F[0] = 0.5;
  c.w = 0.01;
  double F = 1, N[2];
  const GuideLoopResult r = solveGuideFrictionLoop(&c, 1, 3.0, &F, N);
  EXPECT_EQ(r.status, LoopStatus::Solved);
  EXPECT_EQ(r.passes, 1);
  EXPECT_EQ(F, 0.0);
  EXPECT_EQ(r.eps, 3.0);
  EXPECT_EQ(N[0], 1200 + 40 * 3.0);
  EXPECT_EQ(N[1], -300 - 10 * 3.0);
}

TEST(GuideFrictionLoop, ReportsSelfLockingInsteadOfIterating) {
  // Friction 0.3 per newton of normal force, and the normal force grows by 4 N per newton of
  // friction: the cart's own loop gain is 1.2 >= 1.
  GuideLoopCart c;
  c.n0[0] = 1000;
  c.n0[1] = 500;
  c.n_F[0] = 2.0;
  c.n_F[1] = 2.0;
  c.c = 0.3;
  double F = 0, N[2];
  const GuideLoopResult r = solveGuideFrictionLoop(&c, 1, 0.0, &F, N);
  EXPECT_EQ(r.status, LoopStatus::SelfLocking);
  EXPECT_EQ(r.cart, 0);
  EXPECT_NEAR(r.gain, 1.2, 1e-12);
  EXPECT_NE(describeLoopFailure(r).find("locks cart 1"), std::string::npos) << describeLoopFailure(r);
}

TEST(GuideFrictionLoop, ReportsANonPositiveEffectiveInertia) {
  // Each newton of friction raises ε by 0.02 rad/s², each rad/s² of ε the normal force by 100 N,
  // at f = 0.6: Σ w·β = 1.2 >= 1 (Painlevé's paradox), while each cart alone is stable.
  GuideLoopCart c;
  c.n0[0] = 2000;
  c.n_eps[0] = 100;
  c.c = 0.6;
  c.w = 0.02;
  double F = 0, N[2];
  const GuideLoopResult r = solveGuideFrictionLoop(&c, 1, 1.0, &F, N);
  EXPECT_EQ(r.status, LoopStatus::Undetermined);
  EXPECT_NEAR(r.gain, 1.2, 1e-12);
}

}  // namespace
}  // namespace rollerdyn
