// The reduced model with the reducer's backlash (reducer.backlash, physics/CouplingLaw.h): the
// gap's potential energy and the energy audit, a start from rest through the gap, a large
// backlash, a stiff contact and a thousand revolutions without drift.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "physics/CouplingLaw.h"
#include "reduced/ReducedModel.h"

namespace rollerdyn {
namespace test {
Scene loveikin2018LikeScene();
}

namespace {

constexpr double kBacklash = 0.0017453;  // 0.1°

// A free two-carts machine (no motor, no loads), its coupling undamped.
Scene freeMachine() {
  Scene s = test::loveikin2018LikeScene();
  s.carts.count = 2;
  s.carts.side = {1, -1};
  s.motor.enabled = false;
  s.loads.roller_force_front = s.loads.roller_force_rear = 0;
  s.loads.roller_normal_front = s.loads.roller_normal_rear = 0;
  s.loads.guide_friction = 0;
  s.loads.gravity = 0;
  s.coupling.damping = 0;
  s.initial.crank_speed = 10.0;
  s.simulation.t_end = 1.0;
  s.simulation.output_step = 1e-3;
  return s;
}

int rowsWithContact(const RunResult& r, int state) {
  const std::vector<double> c = r.timeseries.column("tooth_contact");
  return static_cast<int>(std::count(c.begin(), c.end(), static_cast<double>(state)));
}

TEST(ReducedBacklash, FreeMachineSwingsThroughTheGapAndKeepsItsEnergy) {
  Scene s = freeMachine();
  s.reducer.backlash = 0.01;  // b = 0.005 rad
  s.initial.twist = 0.02;
  s.simulation.accuracy = 1e-10;
  const RunResult r = runReducedModel(s);
  ASSERT_TRUE(r.stats.complete) << r.stats.status;
  // V(0) = ½·c·(0.02 − 0.005)² = ½·2e5·2.25e-4 = 22.5 J (not ½·c·0.02² = 40 J).
  EXPECT_NEAR(r.energy.potential_initial, 22.5, 1e-9);
  ASSERT_TRUE(r.timeseries.has("tooth_contact"));
  EXPECT_GT(rowsWithContact(r, 0), 10);   // the twist crosses the gap ...
  EXPECT_GT(rowsWithContact(r, -1), 10);  // ... to the reverse flank
  const double E0 = r.energy.kinetic_initial + r.energy.potential_initial;
  EXPECT_LT(std::abs(r.energy.residual()) / E0, 1e-8) << r.energy.residual() << " J of " << E0;
}

TEST(ReducedBacklash, EnergyAuditClosesWithBacklashAndDamping) {
  Scene s = test::loveikin2018LikeScene();
  s.reducer.backlash = kBacklash;
  s.simulation.accuracy = 1e-9;
  s.simulation.t_end = 2.0;
  const RunResult r = runReducedModel(s);
  ASSERT_TRUE(r.stats.complete) << r.stats.status;
  EXPECT_GT(rowsWithContact(r, 0), 0);
  EXPECT_GT(r.energy.damping_dissipation, 0.0);
  EXPECT_LT(std::abs(r.energy.residualRelative()), 1e-6) << r.energy.residual() << " J";
}

TEST(ReducedBacklash, StartsFromRestThroughTheGap) {
  Scene s = test::loveikin2018LikeScene();
  s.reducer.backlash = 5.0 * M_PI / 180.0;  // 5°: b = 0.0436 rad
  s.simulation.t_end = 3.0;
  const RunResult r = runReducedModel(s);
  ASSERT_TRUE(r.stats.complete) << r.stats.status;
  const std::vector<double> c = r.timeseries.column("tooth_contact"), q = r.timeseries.column("twist"),
                            M = r.timeseries.column("coupling_torque");
  EXPECT_EQ(c.front(), 0.0);  // at rest, twist 0: in the middle of the gap
  EXPECT_EQ(M.front(), 0.0);
  // The twist runs through the gap before the teeth meet: every row before the first contact
  // transmits no torque and has |twist| ≤ b, the first contact row is beyond b.
  const auto first = std::find_if(c.begin(), c.end(), [](double v) { return v != 0.0; });
  ASSERT_NE(first, c.end());
  const std::size_t k = first - c.begin();
  EXPECT_GT(k, 0u);
  EXPECT_GT(std::abs(q[k]), 0.5 * s.reducer.backlash);
  for (std::size_t i = 0; i < k; ++i) {
    ASSERT_EQ(M[i], 0.0) << "row " << i;
    ASSERT_LE(std::abs(q[i]), 0.5 * s.reducer.backlash) << "row " << i;
  }
  EXPECT_NE(std::find(c.begin(), c.end(), 1.0), c.end());  // the motor side drives in the end
  EXPECT_LT(std::abs(r.energy.residualRelative()), 1e-5);
  // and it drives the machine up to speed: mean crank speed over the last second > 90 % of ω0/u.
  const std::vector<double> w = r.timeseries.column("omega_crank"), t = r.timeseries.column("t");
  double sum = 0;
  int n = 0;
  for (std::size_t i = 0; i < w.size(); ++i)
    if (t[i] > 2.0) sum += w[i], ++n;
  EXPECT_GT(sum / n, 0.9 * 104.72 / 9.8);
}

TEST(ReducedBacklash, StiffContactRunsWithoutAnEventStorm) {
  Scene s = test::loveikin2018LikeScene();
  s.coupling.stiffness = 1e9;
  s.simulation.t_end = 1.0;
  const RunResult plain = runReducedModel(s);
  s.reducer.backlash = kBacklash;
  const RunResult r = runReducedModel(s);
  ASSERT_TRUE(plain.stats.complete && r.stats.complete) << r.stats.status;
  EXPECT_GT(rowsWithContact(r, 0), 0);
  EXPECT_LT(std::abs(r.energy.residualRelative()), 1e-5) << r.energy.residual() << " J";
  // Each contact costs a few short steps, not thousands (measured: see docs/models.md).
  EXPECT_LT(r.stats.steps, 5 * plain.stats.steps) << r.stats.steps << " against " << plain.stats.steps;
}

TEST(ReducedBacklash, AThousandRevolutionsWithoutDrift) {
  Scene s = test::loveikin2018LikeScene();
  s.reducer.backlash = kBacklash;
  s.simulation.output_step = 5e-3;
  s.simulation.t_end = 600.0;  // ≈ 1020 revolutions at 10.7 rad/s
  const RunResult r = runReducedModel(s);
  ASSERT_TRUE(r.stats.complete) << r.stats.status;
  const std::vector<double> t = r.timeseries.column("t"), phi = r.timeseries.column("phi_crank");
  EXPECT_GT(phi.back() / (2 * M_PI), 1000.0);
  // Mean crank speed over 100 s early in the steady running and over the last 100 s.
  auto meanSpeed = [&](double t0, double t1) {
    const std::size_t a = std::lower_bound(t.begin(), t.end(), t0) - t.begin();
    const std::size_t b = std::lower_bound(t.begin(), t.end(), t1) - t.begin();
    return (phi[b] - phi[a]) / (t[b] - t[a]);
  };
  const double early = meanSpeed(50.0, 150.0), late = meanSpeed(495.0, 595.0);
  EXPECT_NEAR(late, early, 1e-5 * early);
  EXPECT_LT(std::abs(r.energy.residualRelative()), 1e-5) << r.energy.residual() << " J";
}

}  // namespace
}  // namespace rollerdyn
