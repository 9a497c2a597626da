// Guide reactions and rod forces of the multibody model against the quasi-static cart
// equilibrium of Loveikin, Pochka, Romasevych (2018) eq. (10)-(25) (src/reduced/CartStatics.h), and the dynamic (inertial)
// part of the guide reactions at running speed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

#include "multibody/IntegratorFactory.h"
#include "multibody/MultibodyModel.h"
#include "multibody/MultibodySimulation.h"
#include "physics/RollerLoads.h"
#include "physics/SliderCrank.h"
#include "reduced/CartStatics.h"
#include "support/Loveikin2018Scene.h"

namespace rollerdyn {
namespace {

// One output row of each table for a state assembled at (φ, ω) with the crank speed prescribed
// (so the cart accelerations are the kinematic ones, d²x_B/dθ²·ω²).
struct Snapshot {
  std::vector<std::string> ts_cols, re_cols;
  std::vector<double> ts, re;
  double t(const std::string& c) const { return ts[index(ts_cols, c)]; }
  double r(const std::string& c) const { return re[index(re_cols, c)]; }
  static size_t index(const std::vector<std::string>& cols, const std::string& c) {
    const auto it = std::find(cols.begin(), cols.end(), c);
    if (it == cols.end()) throw std::out_of_range("no column " + c);
    return size_t(it - cols.begin());
  }
};

Snapshot snapshot(const MultibodyModel& model, double phi, double omega) {
  Snapshot s;
  s.ts_cols = model.timeseriesColumns();
  s.re_cols = model.reactionColumns();
  const SimTK::State st = model.assembledState(phi, omega, 0.0);
  model.observe(st, s.ts, s.re);
  return s;
}

std::string label(const Scene& sc) {
  return std::string("rods=") + toString(sc.rods.model) + " dir=" + toString(sc.loads.roller_force_direction) +
         " f=" + std::to_string(sc.loads.guide_friction) + " h=" + std::to_string(sc.carts.geometry.com_height);
}

// The four-cart Loveikin, Pochka, Romasevych (2018) scene with alternating sides, so every comparison covers σ = +1 and -1.
Scene reactionScene(RodModel rods, RollerForceDirection dir, double f) {
  Scene sc = test_scenes::loveikin2018Scene();
  sc.rods.model = rods;
  sc.carts.side = {1, -1, 1, -1};
  sc.loads.roller_force_direction = dir;
  sc.loads.guide_friction = f;
  // tanh(v/v_s) = ±1 to double precision once |v| > 20·v_s = 2e-8 m/s, so the load and friction
  // directions are the sharp sign(v) that CartStatics is given.
  sc.loads.velocity_smoothing = 1e-9;
  // The crank speed is prescribed: the motor and the coupling cannot act on the carts, so the
  // motor is left out (it would only spin up its own side, and simulateMultibody's stall watch
  // would stop a slow run) and the drive is one rigid body.
  sc.motor.enabled = false;
  sc.coupling.type = CouplingType::Rigid;
  return sc;
}

// CartStatics for cart j of a snapshot: rod angle and local velocity from the closed-form
// kinematics at the snapshot's crank angle, local d'Alembert force -m_B·a'.
struct Expected {
  CartStaticsResult statics;
  double beta = 0, v_local = 0, a_local = 0;
};
Expected expectedStatics(const Scene& sc, const Snapshot& s, int j, bool with_inertia) {
  const int side = sc.carts.side[j];
  const std::string n = std::to_string(j + 1);
  Expected e;
  e.beta = sliderCrankExact(s.t("phi_crank") + sc.crankPhase(j), sc.crank.radius, sc.rods.length, side).beta;
  e.v_local = side * s.t("v_cart_" + n);
  e.a_local = side * s.t("a_cart_" + n);
  const double Fin = with_inertia ? -sc.cartMassWithRodShare() * e.a_local : 0.0;
  e.statics = solveCartStatics(sc, e.beta, rollerHorizontalForce(sc.loads, e.v_local),
                               frictionDirection(sc.loads, e.v_local), Fin);
  return e;
}

// For distributed rods the multibody F_rod is the axial force at the rod's B end (projection of
// the whole rod-on-cart force on B->A), while CartStatics splits that force into half the rod
// weight, vertical at B, plus an axial force F along the rod, which is the axial force at
// mid-rod. The end force is (0, -m·g/2) + F·e_BA and e_BA·ŷ = sin β, so the two differ by
// exactly m_rod·g/2·sin β (≤ 79 N for Loveikin, Pochka, Romasevych (2018)); split and massless rods carry no such term.
double rodEndCorrection(const Scene& sc, double beta) {
  return sc.rods.model == RodModel::Distributed ? -0.5 * sc.rods.mass * sc.loads.gravity * std::sin(beta) : 0.0;
}

// 3a. Quasi-static snapshots: slow prescribed rotation (ω = ±0.01 rad/s, both friction
//     directions at every angle), crank angles every 5° offset by 2.5° (no cart exactly at a
//     dead centre: |v'| ≥ r·ω·sin 2.5° ≈ 9e-5 m/s, far above the 2e-8 m/s where tanh leaves ±1).
//     Both roller-force readings, f = 0.008 and 0, all rod models, both sides.
TEST(MultibodyReactions, QuasiStaticSnapshotsMatchCartStatics) {
  const double omega_abs = 0.01;
  double worst = 0;
  for (RollerForceDirection dir : {RollerForceDirection::OpposesVelocity, RollerForceDirection::AsPrinted})
    for (double f : {0.008, 0.0})
      for (RodModel rods : {RodModel::Split, RodModel::Massless, RodModel::Distributed})
        for (double omega : {omega_abs, -omega_abs}) {
          const Scene sc = reactionScene(rods, dir, f);
          const MultibodyModel model(sc, MultibodyOptions{true, omega});
          double dev = 0;
          int compared = 0;
          for (int k = 0; k < 72; ++k) {
            const double phi = (2.5 + 5.0 * k) * M_PI / 180.0;
            const Snapshot s = snapshot(model, phi, omega);
            for (int j = 0; j < sc.carts.count; ++j) {
              const std::string n = std::to_string(j + 1);
              const Expected e = expectedStatics(sc, s, j, /*with_inertia=*/true);
              ASSERT_GT(std::abs(e.v_local), 1e-6);
              dev = std::max({dev, std::abs(s.r("N_front_" + n) - e.statics.N_front),
                              std::abs(s.r("N_rear_" + n) - e.statics.N_rear),
                              std::abs(s.r("F_rod_" + n) - (e.statics.F_rod + rodEndCorrection(sc, e.beta))),
                              std::abs(sc.carts.side[j] * s.r("friction_" + n) - e.statics.friction)});
              ++compared;
            }
          }
          EXPECT_EQ(compared, 288);
          // What the comparison leaves out: the inertia of a distributed rod, m_rod·|a_S| ≤
          // 64 kg · r·ω²·(1 + r/l) ≈ 1.6e-3 N at ω = 0.01 (the carts' own d'Alembert force IS
          // passed to CartStatics, so the result is exact for split and massless rods), the
          // start-up fixed point of the lagged friction (contracts by ~f per pass, 8 passes:
          // nothing left), and round-off of reactions of ~2e4 N (~1e-11 N). 1e-2 N is six times
          // the largest of these and 1e-6 of the forces compared; a wrong moment arm, a missing
          // e-term (4.5 kN), a friction at the wrong height (f·ΣN·d/2/2b ≈ 5 N) or a side
          // mirrored wrongly would all show.
          EXPECT_LT(dev, 1e-2) << label(sc) << " omega=" << omega;
          worst = std::max(worst, dev);
        }
  std::cout << "[statics snapshots] max |multibody - CartStatics| = " << worst << " N\n";
}

// Largest step the scene's integrator takes on this model (a twin run that returns after every
// internal step; simulateMultibody integrates the same system with the same settings).
double largestStep(const MultibodyModel& model) {
  const Scene& sc = model.scene();
  auto integ = makeIntegrator(sc.simulation.integrator, model.system(), sc.simulation.accuracy,
                              sc.simulation.constraint_tolerance);
  integ->setReturnEveryInternalStep(true);
  integ->initialize(model.initialState());
  double h = 0;
  while (integ->getTime() < sc.simulation.t_end - 1e-12) {
    integ->stepTo(sc.simulation.t_end);
    h = std::max(h, integ->getPreviousStepSizeTaken());
  }
  return h;
}

// 3b. The same comparison along a simulated slow run, where the guide friction works from normal
//     forces N̂ that relax to the reactions with time constant τ_N (GuideFriction.h). Crank from
//     -0.04 rad to +0.04 rad at 0.01 rad/s: carts 1 and 3 pass their dead centres (velocity
//     reversal) in the middle of the run, carts 2 and 4 stay near mid-stroke.
TEST(MultibodyReactions, SlowRunMatchesCartStaticsAwayFromReversal) {
  const double omega = 0.01;
  double worst_far = 0, worst_near = 0, worst_lag_far = 0;
  for (RollerForceDirection dir : {RollerForceDirection::OpposesVelocity, RollerForceDirection::AsPrinted})
    for (RodModel rods : {RodModel::Split, RodModel::Massless, RodModel::Distributed}) {
      Scene sc = reactionScene(rods, dir, 0.008);
      // The lagged normal forces N̂ under test, in the constrained formulation whose Simbody
      // integrator largestStep() repeats.
      sc.simulation.formulation = Formulation::Constrained;
      sc.loads.guide_normal_force = GuideNormalForce::Lagged;
      const double f = sc.loads.guide_friction;
      sc.initial.crank_angle = -0.04;
      sc.initial.crank_speed = omega;
      sc.simulation.t_end = 8.0;
      // Output every 0.02 s (2e-4 rad). This does NOT bound the integrator step: Simbody's
      // Runge-Kutta integrators step past report times and interpolate, and the prescribed
      // mechanism is so smooth at 0.01 rad/s that the steps grow to tenths of a second. The
      // bounds below therefore use the largest step actually taken (h_max, measured).
      sc.simulation.output_step = 0.02;
      sc.simulation.accuracy = 1e-8;
      const MultibodyModel model(sc, MultibodyOptions{true, omega});
      const RunResult r = simulateMultibody(model);
      ASSERT_TRUE(r.stats.complete) << r.stats.status;
      const double h_max = largestStep(model);
      const Table& ts = r.timeseries;
      const Table& re = r.reactions;
      double far = 0, near = 0, lag_far = 0, lag_near = 0, excess = 0, ndot_max = 0;
      int compared_far = 0, compared_near = 0;
      for (size_t i = 0; i < ts.rows.size(); ++i) {
        Snapshot s{ts.columns, re.columns, ts.rows[i], re.rows[i]};
        const double phi = s.t("phi_crank");
        for (int j = 0; j < sc.carts.count; ++j) {
          const std::string n = std::to_string(j + 1);
          const Expected e = expectedStatics(sc, s, j, true);
          if (std::abs(e.v_local) < 1e-6) continue;  // at reversal itself the direction is 0/0
          const double Nf = s.r("N_front_" + n), Nr = s.r("N_rear_" + n);
          const double dev =
              std::max({std::abs(Nf - e.statics.N_front), std::abs(Nr - e.statics.N_rear),
                        std::abs(s.r("F_rod_" + n) - (e.statics.F_rod + rodEndCorrection(sc, e.beta))),
                        std::abs(sc.carts.side[j] * s.r("friction_" + n) - e.statics.friction)});
          // Lag error of this row: the friction applied, f·(|N| used), against f·(|N| now).
          const double lag = std::abs(std::abs(s.r("friction_" + n)) - f * (std::abs(Nf) + std::abs(Nr)));
          // (i) The whole deviation is the lag: a friction error δ moves F_rod by δ/cos β
          //     (≤ 1.033·δ) and the guide reactions by less (moment arms d/2, p·tan β over 2b),
          //     and feeds back on itself only at order f. 1.1·δ, plus the 2e-3 N inertia of 3a.
          excess = std::max(excess, dev - 1.1 * lag - 2e-3);
          // Distance in crank angle from the cart's nearest dead centre (velocity reversal).
          const double theta = std::remainder(phi + sc.crankPhase(j), M_PI);
          if (std::abs(theta) > 0.01) {
            far = std::max(far, dev);
            lag_far = std::max(lag_far, lag);
            ++compared_far;
            // |dN/dt| of the quasi-static solution, by a central difference in crank angle.
            const double dth = 1e-4;
            auto N_at = [&](double th) {
              const SliderCrankPose p = sliderCrankExact(th, sc.crank.radius, sc.rods.length, sc.carts.side[j]);
              const CartStaticsResult c = solveCartStatics(sc, p.beta, rollerHorizontalForce(sc.loads, e.v_local),
                                                           frictionDirection(sc.loads, e.v_local));
              return std::make_pair(c.N_front, c.N_rear);
            };
            const auto a = N_at(phi + sc.crankPhase(j) + dth), b = N_at(phi + sc.crankPhase(j) - dth);
            ndot_max = std::max({ndot_max, std::abs(a.first - b.first) / (2 * dth) * omega,
                                 std::abs(a.second - b.second) / (2 * dth) * omega});
          } else {
            near = std::max(near, dev);
            lag_near = std::max(lag_near, lag);
            ++compared_near;
          }
        }
      }
      std::cout << "[statics slow run] " << label(sc) << " steps " << r.stats.steps << " h_max " << h_max
                << " s, far/near rows " << compared_far << "/" << compared_near << ", max dev far " << far
                << " N (lag " << lag_far << "), near " << near << " N (lag " << lag_near
                << "), max dN/dt " << ndot_max << " N/s\n";
      EXPECT_GT(compared_far, 1000);
      EXPECT_GT(compared_near, 80);
      EXPECT_LE(excess, 0.0) << label(sc) << ": deviation not explained by the friction lag";
      // (ii) Far from reversal (more than 0.01 rad = 1 s from it) N̂ trails N by τ_N·dN/dt once
      //      the start-up transient (decaying as e^{-t/τ_N}, gone within milliseconds) is over,
      //      so the friction lag is at most f·|dN/dt|·τ_N; the factor 2 covers dN/dt changing
      //      within a few τ_N, and 2e-3 N the reaction round-off. (h_max is printed only to show
      //      that the bound no longer depends on the step size.)
      const double far_bound = 2.0 * f * ndot_max * sc.loads.guide_friction_lag + 2e-3;
      EXPECT_LT(lag_far, far_bound) << label(sc);
      EXPECT_LT(far, 1.1 * far_bound) << label(sc);
      // (iii) Near reversal the friction flips by 2·f·ΣN ≈ 2·0.008·2e4 ≈ 300 N in ~1e-4 s, which
      //      moves the guide reactions by the moment of that jump at d/2 over the guide base 2b,
      //      300·0.023/0.74 ≈ 10 N (F·sin β adds little at β ≈ 0). N̂ needs a few τ_N to follow
      //      that step, during which it can miss by up to those 10 N, i.e. f·10 ≈ 0.08 N of
      //      friction and of the reactions; 0.5 N leaves room for the flip's own moment arm.
      EXPECT_LT(near, 0.5) << label(sc);
      worst_far = std::max(worst_far, far);
      worst_near = std::max(worst_near, near);
      worst_lag_far = std::max(worst_lag_far, lag_far);
    }
  std::cout << "[statics slow run] worst dev far " << worst_far << " N (lag " << worst_lag_far << "), near "
            << worst_near << " N\n";
}

// 8. At running speed the carts' inertia changes the guide reactions. For a translating cart the
//    dynamic reactions are exactly the static ones with the d'Alembert force -m_B·a' applied at
//    the centre of mass (height com_height above B). Loveikin, Pochka, Romasevych (2018) eq. (10) leaves inertia out.
//    Derivation (f = 0; ΣX, ΣY, ΣM of CartStatics.h with Fin = -m·a'):
//      ΔF = Fin/cos β,  Δ(N1 + N2) = Fin·tan β,  Δ[N1(p - b) + N2(p + b)] = -h·Fin
//      => Δ(N_rear - N_front) = m·a'·(h + p·tan β)/b.
//    With h = com_height = 0.3 m > p·|tan β|max = 0.52·0.258 = 0.134 m, the rear guide gains load
//    and the front one loses it whenever the cart accelerates away from the shaft (a' > 0).
//    With h = 0 the inertia force has no moment about B, yet N still changes: it changes the rod
//    force, whose vertical component F·sin β acts at B, giving m·a'·p·tan β/b, which has the
//    sign of a'·β instead.
TEST(MultibodyReactions, CartInertiaShiftsGuideReactionsAtSpeed) {
  const double omega = 10.7;  // near synchronous crank speed ω0/u
  for (double f : {0.0, 0.008})
  for (double h : {0.3, 0.0})
    for (RodModel rods : {RodModel::Split, RodModel::Massless}) {
      Scene sc = reactionScene(rods, RollerForceDirection::AsPrinted, f);
      sc.carts.geometry.com_height = h;
      const MultibodyModel model(sc, MultibodyOptions{true, omega});
      const CartGeometry& g = sc.carts.geometry;
      const double m = sc.cartMassWithRodShare();
      double dev_dyn = 0, max_shift = 0, dev_formula = 0;
      int sign_ok = 0, sign_checked = 0;
      for (int k = 0; k < 72; ++k) {
        const double phi = (2.5 + 5.0 * k) * M_PI / 180.0;
        const Snapshot s = snapshot(model, phi, omega);
        for (int j = 0; j < sc.carts.count; ++j) {
          const std::string n = std::to_string(j + 1);
          const Expected dyn = expectedStatics(sc, s, j, true);
          const Expected sta = expectedStatics(sc, s, j, false);
          const double Nf = s.r("N_front_" + n), Nr = s.r("N_rear_" + n);
          // The multibody reactions are the kinetostatic ones (tight: round-off of ~3e4 N forces).
          dev_dyn = std::max({dev_dyn, std::abs(Nf - dyn.statics.N_front), std::abs(Nr - dyn.statics.N_rear),
                              std::abs(s.r("F_rod_" + n) - dyn.statics.F_rod)});
          const double shift = (Nr - Nf) - (sta.statics.N_rear - sta.statics.N_front);
          const double predicted = m * dyn.a_local * (h + g.p * std::tan(dyn.beta)) / g.b;
          dev_formula = std::max(dev_formula, std::abs(shift - predicted));
          max_shift = std::max(max_shift, std::abs(shift));
          if (std::abs(predicted) > 100.0) {
            ++sign_checked;
            const double expected_sign = h > 0 ? dyn.a_local : dyn.a_local * dyn.beta;
            if (shift * expected_sign > 0) ++sign_ok;
          }
        }
      }
      std::cout << "[inertia] " << label(sc) << " max |N_dyn - kinetostatic| " << dev_dyn
                << " N, max |shift of N_rear - N_front| " << max_shift << " N, max |shift - formula| "
                << dev_formula << " N, sign ok " << sign_ok << "/" << sign_checked << "\n";
      // Round-off on ~3e4 N reactions and the 1e-3 kg rotor token mass (a weight of 1e-2 N on the
      // crank, not on a cart): 1e-6 N would do; 1e-3 N. With f = 0.008 the friction is the fixed
      // point of assembledState (8 passes contracting by ~f each), still exact to round-off.
      // Distributed rods are left out: their own inertia (m_rod·a_S ≈ 64 kg · 20 m/s² ≈ 1.3 kN
      // and the rod's rotation) reaches the cart at B, which a cart-only d'Alembert force
      // does not describe.
      EXPECT_LT(dev_dyn, 1e-3) << label(sc);
      if (f > 0) continue;  // the closed-form shift and its sign are derived for f = 0
      EXPECT_LT(dev_formula, 1e-3) << label(sc);
      EXPECT_EQ(sign_ok, sign_checked) << label(sc);
      EXPECT_GT(sign_checked, 200) << label(sc);
      // |a'| reaches r·ω²·(1 + r/l) = 28.6 m/s², m·a' ≈ 30 kN. With h = 0.3 m the shift at the
      // dead centres alone is m·a'·h/b ≈ 24 kN, more than twice the static N ~ 1e4 N; with h = 0
      // it is still ≥ 10 % of N (above 1 kN) wherever a'·tan β is large.
      EXPECT_GT(max_shift, h > 0 ? 2e4 : 1e3) << label(sc);
    }
}

}  // namespace
}  // namespace rollerdyn
