// The crankshaft as a torsional chain in the multibody model (crankshaft.torsional_stiffness: one
// body per throw, a spring between neighbours): it rings at the chain's natural frequency, tends to
// the rigid crankshaft as the shaft stiffens, and its springs close the energy audit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "multibody/MultibodySimulation.h"
#include "support/Loveikin2018Scene.h"

namespace rollerdyn {
namespace {

// The four-cart drive of Loveikin, Pochka, Romasevych (2018), throws 0.3 m apart in the order
// 1-3-4-2 from the coupling; G·I_p 0 = the rigid crankshaft.
Scene fourCartChain(double GIp, double t_end) {
  Scene sc = test_scenes::loveikin2018Scene();
  sc.simulation.formulation = Formulation::Constrained;
  sc.simulation.t_end = t_end;
  sc.simulation.output_step = 1e-3;
  sc.simulation.accuracy = 1e-8;
  // Loads whose direction follows the carts' velocity (guide friction, the rollers' tanh(v/v_s))
  // rectify the chain's ringing at every dead centre; without them the departure from the rigid
  // shaft is the twist's alone.
  sc.loads.guide_friction = 0.0;
  sc.loads.roller_force_front = sc.loads.roller_force_rear = 0.0;
  if (GIp > 0) {
    sc.crankshaft.throw_positions = {0.0, 0.9, 0.3, 0.6};
    sc.crankshaft.torsional_stiffness = GIp;
  }
  return sc;
}

// Two throws, the drive end's carrying the motor side through a rigid coupling, carts of 1 g on
// massless rods without loads: a two-rotor chain J1 = J'_K + J_n1, J2 = J'_K, c = 2e5 N·m/rad.
Scene twoThrows(double torsional_damping) {
  Scene sc = test_scenes::loveikin2018Scene();
  sc.simulation.formulation = Formulation::Constrained;
  sc.simulation.t_end = 0.3;
  sc.simulation.output_step = 1e-4;
  sc.simulation.accuracy = 1e-9;
  sc.carts.count = 2;
  sc.carts.side = {1, 1};
  sc.carts.mass = 1e-3;
  sc.crank.offset = M_PI;
  sc.crank.inertia_per_crank = 2.0;
  sc.rods = {RodModel::Massless, 0.8, 0.0, 0.0};
  sc.coupling = {CouplingType::Rigid, 0.0, 0.0, 0.32};
  sc.loads = {0, 0, 0, 0, RollerForceDirection::AsPrinted, 0.0, 0.0, 1e-3};
  sc.crankshaft.throw_positions = {0.5, 0.0};  // cart 2's throw at the drive end
  sc.crankshaft.torsional_stiffness = 1e5;     // c = 2e5 N·m/rad over 0.5 m
  sc.crankshaft.torsional_damping = torsional_damping;
  return sc;
}

double maxDifference(const RunResult& a, const RunResult& b, const char* column) {
  const std::vector<double> x = a.timeseries.column(column), y = b.timeseries.column(column);
  double d = 0;
  for (size_t i = 0; i < std::min(x.size(), y.size()); ++i) d = std::max(d, std::abs(x[i] - y[i]));
  return d;
}

// Times and values of the local maxima (max = true) or minima of a sampled signal, refined by a
// parabola through three rows.
std::vector<std::pair<double, double>> extremes(const std::vector<double>& t, const std::vector<double>& y, bool max) {
  std::vector<std::pair<double, double>> e;
  for (size_t i = 1; i + 1 < y.size(); ++i) {
    const double a = max ? y[i - 1] : -y[i - 1], b = max ? y[i] : -y[i], c = max ? y[i + 1] : -y[i + 1];
    if (b > a && b >= c) {
      const double d = a - 2 * b + c, x = d != 0 ? 0.5 * (a - c) / d : 0.0;
      const double v = b - 0.25 * (a - c) * x;
      e.push_back({t[i] + x * (t[1] - t[0]), max ? v : -v});
    }
  }
  return e;
}

}  // namespace

// Two throws, the drive end's carrying the motor side through a rigid coupling, carts of 1 g on
// massless rods without loads: a two-rotor chain J1 = J'_K + J_n1, J2 = J'_K. Started from rest by
// the motor, the segment's torque rings at p = √(c·(J1 + J2)/(J1·J2)), the chain's natural
// frequency; the period is read from the torque's maxima over 12 cycles.
TEST(TorsionalChain, TwoThrowsRingAtTheChainsNaturalFrequency) {
  const Scene sc = twoThrows(0.0);
  // The two-mass frequency of the chain (Holzer's root for two rotors; tests/modes checks Holzer's
  // method itself); the carts' 1 g adds ~4e-5 kg·m² to 2 kg·m², below the tolerance.
  const double J1 = 2.0 + sc.motorSideInertia(), J2 = 2.0, c = 1e5 / 0.5;
  const double p = std::sqrt(c * (J1 + J2) / (J1 * J2));

  const RunResult r = runMultibodyModel(sc);
  ASSERT_TRUE(r.stats.complete) << r.stats.status;
  ASSERT_TRUE(r.timeseries.has("shaft_torque_1"));
  const std::vector<double> t = r.timeseries.column("t"), T = r.timeseries.column("shaft_torque_1");
  std::vector<double> peaks;  // times of the maxima, refined by a parabola through three rows
  for (size_t i = 1; i + 1 < T.size(); ++i)
    if (T[i] > T[i - 1] && T[i] >= T[i + 1]) {
      const double d = T[i - 1] - 2 * T[i] + T[i + 1];
      peaks.push_back(t[i] + (d != 0 ? 0.5 * (T[i - 1] - T[i + 1]) / d : 0.0) * (t[1] - t[0]));
    }
  ASSERT_GE(peaks.size(), 12u);
  const double period = (peaks[11] - peaks[0]) / 11.0;
  EXPECT_NEAR(2 * M_PI / period, p, 2e-3 * p);
}

// As G·I_p grows the chain's run tends to the rigid crankshaft's. The shaft's twist, and with it
// the crank angle's departure from the rigid shaft's, goes as 1/G·I_p: tenfold stiffness, about a
// tenth (asserted: below a quarter). The start from rest sets the chain's undamped modes ringing
// (no material damping), and their speed ripple, twist amplitude T/c times p ~ √(c/J), goes as
// 1/√(G·I_p): tenfold stiffness, about 1/√10 = 0.32 (asserted: below a half).
TEST(TorsionalChain, AStifferShaftTendsToTheRigidCrankshaft) {
  const RunResult rigid = runMultibodyModel(fourCartChain(0, 0.6));
  const RunResult soft = runMultibodyModel(fourCartChain(2e6, 0.6));
  const RunResult stiff = runMultibodyModel(fourCartChain(2e7, 0.6));
  ASSERT_TRUE(rigid.stats.complete && soft.stats.complete && stiff.stats.complete)
      << soft.stats.status << " / " << stiff.stats.status;
  const double a_soft = maxDifference(soft, rigid, "phi_crank"), a_stiff = maxDifference(stiff, rigid, "phi_crank");
  const double w_soft = maxDifference(soft, rigid, "omega_crank"), w_stiff = maxDifference(stiff, rigid, "omega_crank");
  EXPECT_GT(a_soft, 0.0);
  EXPECT_LT(a_stiff, 0.25 * a_soft) << a_soft << " vs " << a_stiff << " rad";
  EXPECT_LT(w_stiff, 0.5 * w_soft) << w_soft << " vs " << w_stiff << " rad/s";
  std::printf("departure from the rigid shaft: angle %.3g -> %.3g rad, speed %.3g -> %.3g rad/s\n", a_soft, a_stiff, w_soft, w_stiff);
  // The chain's springs store energy that the audit counts with the kinetic and potential energy.
  EXPECT_LT(std::abs(soft.energy.residualRelative()), 1e-6) << soft.energy.residual() << " J";
  ASSERT_TRUE(soft.timeseries.has("shaft_torque_3"));
  EXPECT_FALSE(rigid.timeseries.has("shaft_torque_1"));
}


// The same two throws with a Kelvin-Voigt damper across the segment, d = β·G·I_p/Δz, chosen for a
// damping ratio ζ = d/(2·√(c·J1·J2/(J1 + J2))) = 0.02: the ringing's amplitude (half the distance
// from a maximum to the next minimum) decays as exp(-ζ·p·t), so over five periods by exp(-10π·ζ)
// (= 0.53); the motor's slowly changing torque moves the ringing's centre, hence 15 % on ζ. The
// dampers' power joins the energy audit's damping, which still closes.
TEST(TorsionalChain, ADampedShaftRingsDownAtItsDampingRatio) {
  const double J1 = 2.0 + twoThrows(0).motorSideInertia(), J2 = 2.0, c = 2e5, zeta = 0.02;
  const double d = 2 * zeta * std::sqrt(c * J1 * J2 / (J1 + J2));
  const Scene sc = twoThrows(d * 0.5);  // β·G·I_p = d·Δz
  const RunResult r = runMultibodyModel(sc);
  ASSERT_TRUE(r.stats.complete) << r.stats.status;
  const std::vector<double> t = r.timeseries.column("t"), T = r.timeseries.column("shaft_torque_1");
  const auto hi = extremes(t, T, true), lo = extremes(t, T, false);
  ASSERT_GE(hi.size(), 8u);
  ASSERT_GE(lo.size(), 8u);
  auto amplitude = [&](size_t i) { return 0.5 * (hi[i].second - lo[i].second); };  // the first extreme is a maximum
  ASSERT_LT(hi[0].first, lo[0].first);
  const double p = std::sqrt(c * (J1 + J2) / (J1 * J2));
  const double measured = std::log(amplitude(1) / amplitude(6)) / (p * (hi[6].first - hi[1].first));
  EXPECT_NEAR(measured, zeta, 0.15 * zeta);
  EXPECT_GT(r.energy.damping_dissipation, 0.0);
  EXPECT_LT(std::abs(r.energy.residualRelative()), 1e-6) << r.energy.residual() << " J";
}

}  // namespace rollerdyn
