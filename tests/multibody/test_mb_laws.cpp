// The multibody model's own physics at hand-built states, each against a formula written out in
// this file (not the reduced model's code): its kinetic energy against ½·J(φ)·ω² with the reduced
// inertia of Loveikin and Pochka (2007) eq. (9) for distributed rods (and eq. (2)-(3) of Loveikin,
// Pochka, Romasevych (2018) for split rods), its potential energy against the rods' weight and the
// coupling spring, the coupling-torque and twist columns against c·ψ + k·ψ̇, and the crank-pin and
// main-bearing columns against the statics of a massless rod and of the crankshaft.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "multibody/MultibodyModel.h"
#include "multibody/MultibodySimulation.h"
#include "support/Loveikin2018Scene.h"

namespace rollerdyn {
namespace {

// Four carts on alternating sides at a crank offset that is no symmetry of the layout (70°).
Scene lawScene(RodModel rods) {
  Scene sc = test_scenes::loveikin2018Scene();
  sc.rods.model = rods;
  sc.carts.side = {1, -1, 1, -1};
  sc.crank.offset = 70.0 * M_PI / 180.0;
  sc.crank.inertia_per_crank = 0.5;
  sc.crank.shaft_inertia = 2.0;
  return sc;
}

double column(const std::vector<std::string>& names, const std::vector<double>& row, const std::string& c) {
  const auto it = std::find(names.begin(), names.end(), c);
  if (it == names.end()) throw std::out_of_range("no column " + c);
  return row[std::size_t(it - names.begin())];
}

// J(φ) at the crank axis written out here: motor side (J_p + J_m + J_red)·δ·u² (Loveikin,
// Pochka, Romasevych (2018) eq. (1)), crankshaft n·J'_K + J_shaft, and per cart j with
// θ = φ + j·Δφ, λ = r/l, w = √(1 − λ²·sin²θ):
//   x_B' = −r·sinθ − σ·r·λ·sinθ·cosθ/w         (Loveikin and Pochka (2007) eq. (6))
//   distributed rod: m_B·x_B'² + m_rod·(x_S'² + y_S'²) + I_S·β'², with x_S = (r·cosθ + x_B)/2,
//                    y_S = r·sinθ/2, β' = λ·cosθ/w  (Loveikin and Pochka (2007) eq. (9))
//   split rod:       (m_B + m_rod/2)·x_B'² and m_rod/2·r² at the pin (eq. (2)-(3) of 2018)
double reducedInertiaByHand(const Scene& sc, double phi) {
  const double u = sc.reducer.ratio, r = sc.crank.radius, l = sc.rods.length, lam = r / l;
  double J = (sc.motor.rotor_inertia + sc.coupling.inertia + sc.reducer.inertia) * sc.reducer.delta * u * u;
  J += sc.carts.count * sc.crank.inertia_per_crank + sc.crank.shaft_inertia;
  for (int j = 0; j < sc.carts.count; ++j) {
    const double th = phi + j * sc.crank.offset, S = std::sin(th), C = std::cos(th), sg = sc.carts.side[j];
    const double w = std::sqrt(1 - lam * lam * S * S);
    const double dxB = -r * S - sg * r * lam * S * C / w;
    if (sc.rods.model == RodModel::Distributed) {
      const double dxS = 0.5 * (-r * S + dxB), dyS = 0.5 * r * C, dbeta = lam * C / w;
      J += sc.carts.mass * dxB * dxB + sc.rods.mass * (dxS * dxS + dyS * dyS) + sc.rods.inertia_com * dbeta * dbeta;
    } else if (sc.rods.model == RodModel::Split) {
      J += (sc.carts.mass + 0.5 * sc.rods.mass) * dxB * dxB + 0.5 * sc.rods.mass * r * r;
    } else {
      J += sc.carts.mass * dxB * dxB;
    }
  }
  return J;
}

// Simbody's kinetic energy of the assembled machine (every body's mass and inertia as built)
// equals ½·J(φ)·ω² with J by hand. Tolerance 1e-12 relative: the state is assembled from the
// closed forms and projected to 1e-13; the rod's own rotation is ~1e-3 of the energy, so a rod
// inertia off by 1 % moves it by ~1e-5.
TEST(MultibodyLaws, KineticEnergyIsHalfTheReducedInertiaTimesSpeedSquared) {
  for (RodModel rods : {RodModel::Distributed, RodModel::Split, RodModel::Massless}) {
    const Scene sc = lawScene(rods);
    const MultibodyModel model(sc);
    for (double phi : {0.1, 0.9, 2.3, 3.7, 5.5})
      for (double omega : {10.0, -4.0}) {
        const SimTK::State st = model.assembledState(phi, omega, 0.0);
        const double T = model.energy(st).kinetic, expected = 0.5 * reducedInertiaByHand(sc, phi) * omega * omega;
        EXPECT_NEAR(T, expected, 1e-12 * expected) << toString(rods) << " phi " << phi << " omega " << omega;
      }
  }
}

// The potential energy changes with φ and the twist ψ by the rods' weight and the coupling
// spring alone: a distributed rod's centre is at y = r·sinθ/2 (the pin at r·sinθ, the cart on the
// axis), a split rod's pin half-mass at r·sinθ; the carts move horizontally. ΔV = Σ m·g·Δy + ½·c·ψ².
TEST(MultibodyLaws, PotentialEnergyIsTheRodsWeightAndTheCouplingSpring) {
  for (RodModel rods : {RodModel::Distributed, RodModel::Split}) {
    const Scene sc = lawScene(rods);
    const MultibodyModel model(sc);
    const double g = sc.loads.gravity, r = sc.crank.radius, m = sc.rods.mass;
    const double h = rods == RodModel::Distributed ? 0.5 : 1.0, mass = rods == RodModel::Distributed ? m : 0.5 * m;
    auto heights = [&](double phi) {
      double y = 0;
      for (int j = 0; j < sc.carts.count; ++j) y += h * r * std::sin(phi + j * sc.crank.offset);
      return y;
    };
    const double V0 = model.energy(model.assembledState(0.0, 0.0, 0.0)).potential;
    for (double phi : {0.4, 1.9, 3.3, 4.8})
      for (double psi : {0.0, 2e-3, -5e-3}) {
        const double dV = model.energy(model.assembledState(phi, 0.0, psi)).potential - V0;
        const double expected = mass * g * (heights(phi) - heights(0.0)) + 0.5 * sc.coupling.stiffness * psi * psi;
        EXPECT_NEAR(dV, expected, 1e-9 * (mass * g * r * sc.carts.count)) << toString(rods) << " phi " << phi << " psi " << psi;
      }
  }
}

// Coupling columns at a hand-built state: twist ψ = φ_motor − φ_crank and twist rate ψ̇ set on
// the motor side; the coupling torque on the crank is c·ψ + k·ψ̇ (positive when the motor leads),
// in the time series and in the reactions, and the motor speed at the crank axis is ω + ψ̇.
TEST(MultibodyLaws, CouplingColumnsFollowTheTwistAndItsRate) {
  Scene sc = lawScene(RodModel::Distributed);
  const MultibodyModel model(sc);
  const double c = sc.coupling.stiffness, k = sc.coupling.damping;
  for (double psi : {3e-3, -2e-3})
    for (double rate : {0.5, -0.25}) {
      SimTK::State st = model.assembledState(1.2, 10.0, psi);
      model.motorSide().setOneU(st, 0, rate);
      model.system().realize(st, SimTK::Stage::Acceleration);
      std::vector<double> ts, re;
      model.observe(st, ts, re);
      const auto tsn = model.timeseriesColumns(), ren = model.reactionColumns();
      const double M = c * psi + k * rate;
      EXPECT_NEAR(column(tsn, ts, "twist"), psi, 1e-15);
      EXPECT_NEAR(column(tsn, ts, "phi_motor") - column(tsn, ts, "phi_crank"), psi, 1e-14);
      EXPECT_NEAR(column(tsn, ts, "twist_rate"), rate, 1e-15);
      EXPECT_NEAR(column(tsn, ts, "omega_motor"), 10.0 + rate, 1e-12);
      EXPECT_NEAR(column(tsn, ts, "coupling_torque"), M, 1e-9 * std::abs(M)) << "psi " << psi << " rate " << rate;
      EXPECT_NEAR(column(ren, re, "coupling_torque"), M, 1e-9 * std::abs(M));
    }
}

// Crank pin and main bearing at a quasi-static state (crank turned slowly at a prescribed speed,
// motor off, rigid drive). A massless rod carries its force along its axis: the force on crank
// pin A is F_rod·(B − A)/l (F_rod > 0 in tension pulls the pin towards the cart). The
// crankshaft's own balance then gives the bearing force: bearing + Σ pin forces − m_c·g·ŷ = 0,
// with m_c the pins' half rod masses of split rods (and a 1 g token mass on the axis). A, B from
// the closed-form slider-crank here. Tolerance 0.01 N of forces up to ~2e4 N: the inertial forces
// at 0.01 rad/s are below 1e-3 N.
TEST(MultibodyLaws, CrankPinAndBearingColumnsFollowRodAndCrankshaftStatics) {
  for (RodModel rods : {RodModel::Massless, RodModel::Split}) {
    Scene sc = lawScene(rods);
    sc.motor.enabled = false;
    sc.coupling.type = CouplingType::Rigid;
    const double omega = 0.01;
    const MultibodyModel model(sc, MultibodyOptions{true, omega});
    const auto ren = model.reactionColumns();
    const double r = sc.crank.radius, l = sc.rods.length, g = sc.loads.gravity;
    const double m_c = 1e-3 + (rods == RodModel::Split ? sc.carts.count * 0.5 * sc.rods.mass : 0.0);
    for (double phi : {0.3, 1.4, 2.6, 4.1, 5.9}) {
      const SimTK::State st = model.assembledState(phi, omega, 0.0);
      std::vector<double> ts, re;
      model.observe(st, ts, re);
      double sum_x = 0, sum_y = 0;
      for (int j = 0; j < sc.carts.count; ++j) {
        const std::string n = std::to_string(j + 1);
        const double th = phi + j * sc.crank.offset, sg = sc.carts.side[j];
        const double xA = r * std::cos(th), yA = r * std::sin(th);
        const double xB = xA + sg * l * std::sqrt(1 - std::pow(r * std::sin(th) / l, 2));
        const double F = column(ren, re, "F_rod_" + n);
        const double px = column(ren, re, "crankpin_x_" + n), py = column(ren, re, "crankpin_y_" + n);
        EXPECT_NEAR(px, F * (xB - xA) / l, 1e-2) << toString(rods) << " cart " << n << " phi " << phi;
        EXPECT_NEAR(py, F * (0.0 - yA) / l, 1e-2) << toString(rods) << " cart " << n << " phi " << phi;
        EXPECT_GT(std::abs(F), 100.0);  // a real load, so a sign or axis error shows
        sum_x += px;
        sum_y += py;
      }
      EXPECT_NEAR(column(ren, re, "bearing_x"), -sum_x, 1e-2) << toString(rods) << " phi " << phi;
      EXPECT_NEAR(column(ren, re, "bearing_y"), -sum_y + m_c * g, 1e-2) << toString(rods) << " phi " << phi;
    }
  }
}


// The guide friction's normal forces N̂ follow the guide reactions N with the lag τ_N:
// dN̂/dt = (N − N̂)/τ_N (GuideFriction.h). At an assembled state N̂ = N; here every N̂ is moved
// away from it by hand and the rates Simbody computes are compared with (N − N̂)/τ_N, N being the
// guide reactions reported at that same state. The N̂ states are found among the force
// subsystem's z by their values at the assembled state (they equal the reported reactions there).
TEST(MultibodyLaws, FrictionNormalsRelaxWithTheLagTimeConstant) {
  Scene sc = lawScene(RodModel::Distributed);
  sc.loads.guide_friction = 0.05;  // enough friction that N̂ visibly matters
  sc.loads.guide_normal_force = GuideNormalForce::Lagged;  // the law under test
  const MultibodyModel model(sc);
  SimTK::State st = model.assembledState(1.1, 9.0, 0.0);
  std::vector<double> ts, re;
  model.observe(st, ts, re);
  const auto ren = model.reactionColumns();
  std::vector<int> z_of;  // z index of N_front_j, N_rear_j in cart order
  for (int j = 1; j <= sc.carts.count; ++j)
    for (const char* side : {"N_front_", "N_rear_"}) {
      const double N = column(ren, re, side + std::to_string(j));
      int found = -1;
      for (int i = 0; i < st.getNZ(); ++i)
        if (std::abs(st.getZ()[i] - N) <= 1e-9 * std::max(1.0, std::abs(N))) found = i;
      ASSERT_GE(found, 0) << "no friction normal state equals " << side << j << " = " << N;
      z_of.push_back(found);
    }
  // Move N̂ away from N: 0.7·N + 300 N.
  for (int i : z_of) st.updZ()[i] = 0.7 * st.getZ()[i] + 300.0;
  model.system().realize(st, SimTK::Stage::Acceleration);
  model.observe(st, ts, re);
  int k = 0;
  for (int j = 1; j <= sc.carts.count; ++j)
    for (const char* side : {"N_front_", "N_rear_"}) {
      const double N = column(ren, re, side + std::to_string(j)), Nhat = st.getZ()[z_of[k]];
      const double expected = (N - Nhat) / sc.loads.guide_friction_lag;
      EXPECT_NEAR(st.getZDot()[z_of[k]], expected, 1e-9 * std::abs(expected)) << side << j;
      EXPECT_GT(std::abs(expected), 1e4);  // the states really are away from the reactions
      ++k;
    }
}

}  // namespace
}  // namespace rollerdyn
