// Hard cases of issue #4: one test per case, each running both models at an accuracy a and at
// a/10 and asserting no exception/NaN, constraint error, energy audit and convergence
// (HardCaseSupport.h explains every tolerance). Machine: Loveikin, Pochka, Romasevych (2018) (tests/support/Seed000Scene.h:
// four carts on one side, Δφ = 90°, elastic damped coupling, roller forces as printed, guide
// friction, gravity) unless a case says otherwise. Runs are kept short (0.5 ... 1.5 s of machine
// time) except where the case itself is about length (100 and 1000 revolutions).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "HardCaseSupport.h"
#include "multibody/IntegratorFactory.h"
#include "physics/KlossMotor.h"

namespace rollerdyn::hardcases {
namespace {

using test_scenes::seed000Scene;

Scene seed(const std::string& name, double t_end) {
  Scene s = seed000Scene();
  s.name = name;
  s.simulation.t_end = t_end;
  return s;
}

void noLoads(Scene& s) {
  s.loads.roller_force_front = s.loads.roller_force_rear = 0.0;
  s.loads.roller_normal_front = s.loads.roller_normal_rear = 0.0;
  s.loads.guide_friction = 0.0;
}

// Coupling stiffness 1e9 N·m/rad (5000x the paper's): torsional frequency
// p0 = √(c·(J1 + J2)/(J1·J2)) ≈ 4.5e3 rad/s (Dyomin (two rotors) eq. (10)), ~400x the crank speed, so an
// explicit integrator's step is bounded by stability, not accuracy. Damped (k = 8000).
//
// History: this case found that the multibody coupling torque carried errors of order c·a (the
// twist was the difference of two absolute angles, each held to ~a rad: 104 N·m, 12 %, at
// c = 1e9, a = 1e-6, against 0.6 N·m for the reduced model); fixed by mobilizing the motor side
// on the crankshaft with a weighted twist coordinate (commit 21ac486).
TEST(HardCases, StiffCoupling1e9WithDamping) {
  Scene s = seed("stiff-1e9-damped", 0.5);
  s.coupling.stiffness = 1e9;
  for (Model m : {Model::Multibody, Model::Reduced}) checkCase(m, s, 1e-6);
}

// Same, undamped (k = 0): the 4.5e3 rad/s mode is excited at every cart reversal, where the
// guide friction flips sign within ~v_s/a_cart (tanh, v_s = 1 mm/s), and never decays. Its
// amplitude depends on how exactly each flip is traversed and converges slowly: reduced model,
// largest coupling torque over 0.5 s at a = 1e-6 ... 1e-10: 1436.1, 1458.6, 1462.2, 1462.70,
// 1462.79 N·m, i.e. an error of 1.8 % = 1.8e4·a at a = 1e-6 (the multibody model: 1.3 %).
// The claim for the coupling torque is therefore 3e4·a here, not the default 1e3·a; the crank
// speed keeps the default claim. (Before commit 21ac486 the multibody model failed this case,
// 16 % at a = 1e-6, for the reason given above StiffCoupling1e9WithDamping.)
TEST(HardCases, StiffCoupling1e9WithoutDamping) {
  Scene s = seed("stiff-1e9-undamped", 0.5);
  s.coupling.stiffness = 1e9;
  s.coupling.damping = 0.0;
  Expect claim;
  claim.torque_claim = 3e4;
  for (Model m : {Model::Multibody, Model::Reduced}) checkCase(m, s, 1e-6, claim);
}

// k = 0, motor and loads off (gravity kept: it is conservative): the total energy T + V must be
// conserved over 100 crank revolutions. Started at 10 rad/s with a coupling twist of 1e-3 rad
// so the coupling oscillates as well. 100 revolutions ≈ 63 s of machine time; the four carts
// are kept (this is the paper's machine), so this case is one of the long ones.
TEST(HardCases, FreeMachineConservesEnergyOver100Revolutions) {
  Scene s = seed("free-100rev", 0.0);
  noLoads(s);
  s.motor.enabled = false;
  s.coupling.damping = 0.0;
  s.initial.crank_speed = 10.0;
  s.initial.twist = 1e-3;
  s.simulation.t_end = 100 * 2.0 * M_PI / 10.0;  // 100 revolutions at ~10 rad/s
  s.simulation.output_step = 0.05;
  // The undamped coupling mode (p0 ≈ 88 rad/s, Dyomin (two rotors) eq. (10)) runs through ~880 periods and
  // its phase error grows with every one of them, so the run claims less than a 1 s run does.
  // Measured against the reduced model at a = 1e-10 (model/balanced-4cart.yaml machine, same
  // case, before commit 21ac486): crank speed error over the run 4.2e3·a (multibody) and
  // 6.3e2·a (reduced) at a = 1e-6, falling tenfold per decade of a; largest coupling torque
  // 2.3e2·a and 8.3e3·a. (The multibody twist was then the difference of two absolute angles
  // held to ~a rad each, so its phase drifted fastest; it is now a weighted coordinate.)
  Expect claim;
  claim.speed_claim = 1e4;
  claim.torque_claim = 2e4;
  for (Model m : {Model::Multibody, Model::Reduced}) {
    const RunResult r = checkCase(m, s, 1e-6, claim);
    EXPECT_GE(revolutions(r), 95.0) << name(m);
    // Conservation itself: no motor, no dissipation, no load work; the audit's residual is
    // then ΔT + ΔV, checked above against 10·a·E·N_rev.
    EXPECT_EQ(r.energy.motor_work, 0.0) << name(m);
    EXPECT_EQ(r.energy.load_work, 0.0) << name(m);
    EXPECT_EQ(r.energy.friction_dissipation, 0.0) << name(m);
  }
}

// Δφ = 0: all four carts in phase. Their dead centres coincide (x_B' = 0 for all at once, so
// J_n2(φ) dips to the rods' share alone) and the as-printed roller-force torques add up to
// ≈ 12.8 kN·m peaks, nearly three times the motor's ≈ 4.6 kN·m at breakdown: from rest the
// drive cannot push the carts over and the crank rocks back and forth (both models agree).
TEST(HardCases, AllCartsInPhase) {
  Scene s = seed("in-phase", 1.0);
  s.crank.offset = 0.0;
  for (Model m : {Model::Multibody, Model::Reduced}) checkCase(m, s, 1e-6);
}

// Overload beyond the breakdown torque: the roller forces oppose the velocity (the other
// reading of Loveikin, Pochka, Romasevych (2018)), four carts need ≈ 8.1 kN·m mean crank torque against ≈ 4.6 kN·m at
// breakdown. The run must end early with "motor stalled at t = ..." and complete = false, not
// blow up or hang.
TEST(HardCases, OverloadStallsWithClearStatus) {
  Scene s = seed("overload", 3.0);
  s.loads.roller_force_direction = RollerForceDirection::OpposesVelocity;
  Expect stalled;
  stalled.complete = false;
  stalled.status_prefix = "motor stalled at t = ";
  for (Model m : {Model::Multibody, Model::Reduced}) {
    const RunResult r = checkCase(m, s, 1e-6, stalled);
    // Both models apply one rule (analysis/StallDetector.h): the drive never gets going, so
    // the stall is dated t = 0 and found 1 s later, well before t_end.
    EXPECT_EQ(r.stats.status, "motor stalled at t = 0 s") << name(m);
    EXPECT_LT(last(r.timeseries, "t"), 1.0 + 0.011) << name(m) << ": " << r.stats.status;
    EXPECT_LT(maxAbs(r.timeseries, "omega_crank"), 0.05 * syncCrankSpeed(s)) << name(m);
  }
}

// r/l = 0.95: the rod swings to β = asin(0.95) = 72°, x_B'(φ) and the rod force peak sharply
// near φ = ±90°, and the geometry is 5 % from the lock-up r = l.
TEST(HardCases, CrankToRodRatio095) {
  Scene s = seed("r-over-l-0.95", 1.0);
  s.rods.length = s.crank.radius / 0.95;
  s.rods.inertia_com = s.rods.mass * s.rods.length * s.rods.length / 12.0;
  for (Model m : {Model::Multibody, Model::Reduced}) checkCase(m, s, 1e-6);
}

// Start from rest: slip s = 1, motor at its starting torque, every cart velocity 0 (the
// smoothed sign laws at their steepest), coupling twist building from 0.
TEST(HardCases, StartFromRest) {
  Scene s = seed("from-rest", 1.0);
  ASSERT_EQ(s.initial.crank_speed, 0.0);
  for (Model m : {Model::Multibody, Model::Reduced}) {
    const RunResult r = checkCase(m, s, 1e-6);
    EXPECT_GT(last(r.timeseries, "omega_crank"), 0.5 * syncCrankSpeed(s)) << name(m) << ": drive did not start";
  }
}

// Exactly at synchronous speed: slip s = 0, where Loveikin, Pochka, Romasevych (2018) eq. (37) as printed divides by zero
// and the motor torque is 0. No loads, no gravity: the machine starts at ω0/u and the motor only
// answers the speed ripple of J(φ), crossing s = 0 in both directions (motor and generator).
TEST(HardCases, RunningAtSynchronousSpeed) {
  Scene s = seed("synchronous", 1.0);
  noLoads(s);
  s.loads.gravity = 0.0;
  s.initial.crank_speed = syncCrankSpeed(s);
  EXPECT_EQ(klossCrankTorque(s.motor, s.reducer.ratio, s.reducer.efficiency, syncCrankSpeed(s)), 0.0);
  for (Model m : {Model::Multibody, Model::Reduced}) {
    const RunResult r = checkCase(m, s, 1e-6);
    const Table& t = r.timeseries;
    EXPECT_EQ(t.rows.front()[t.index("motor_torque")], 0.0) << name(m);
    double lo = 0, hi = 0;  // the motor torque takes both signs: the speed crosses synchronous
    for (const auto& row : t.rows) {
      lo = std::min(lo, row[t.index("motor_torque")]);
      hi = std::max(hi, row[t.index("motor_torque")]);
    }
    EXPECT_LT(lo, 0.0) << name(m);
    EXPECT_GT(hi, 0.0) << name(m);
  }
}

// Samples of a multibody run every `block` seconds: energy-audit residual, constraint error,
// crank speed and coupling torque (MultibodySimulation's loop reports only the end of a run).
struct Samples {
  std::vector<double> revolutions, residual, constraint_error, omega, coupling_torque;
  long steps = 0;
  double motor_work = 0;
};

Samples sampleMultibody(const Scene& s, double block, int blocks) {
  Samples out;
  const MultibodyModel model(s);
  SimTK::State s0 = model.initialState();
  const EnergySnapshot e0 = model.energy(s0);
  auto integ = makeIntegrator(s.simulation.integrator, model.system(), s.simulation.accuracy,
                              s.simulation.constraint_tolerance);
  integ->initialize(s0);
  for (int k = 1; k <= blocks; ++k) {
    const double t = k * block;
    while (integ->getTime() < t - 1e-12) integ->stepTo(t, blocks * block);
    const SimTK::State& st = integ->getState();
    model.system().realize(st, SimTK::Stage::Acceleration);
    const EnergySnapshot e = model.energy(st);
    out.residual.push_back((e.motor_work - e0.motor_work) - (e.damping_dissipation - e0.damping_dissipation) -
                           (e.friction_dissipation - e0.friction_dissipation) - (e.load_work - e0.load_work) -
                           (e.kinetic - e0.kinetic) - (e.potential - e0.potential));
    out.constraint_error.push_back(model.constraintError(st));
    out.omega.push_back(model.crankSpeed(st));
    out.coupling_torque.push_back(model.couplingTorque(st));
    out.revolutions.push_back((model.crankAngle(st) - s.initial.crank_angle) / (2.0 * M_PI));
    out.motor_work = e.motor_work - e0.motor_work;
  }
  out.steps = integ->getNumStepsTaken();
  return out;
}

// 1000 revolutions (≈ 590 s of machine time): no drift of the constraint error or of the energy
// audit. Inherently long, so the leanest honest machine: two carts on opposite sides (Loveikin and Pochka's (2007)
// layout), massless rods (one rod-length constraint each), rigid coupling (1 DOF), the Loveikin, Pochka, Romasevych (2018)
// motor, roller forces as printed and gravity; no guide friction (its sign change at every
// reversal, tanh with v_s = 1 mm/s, would double the steps per revolution without bearing on
// drift). Started at nominal speed. Multibody at a = 1e-5 and 1e-6 (about 15 s and 27 s of CPU
// on an idle core), sampled every 100 revolutions in our own loop; reduced through checkCase.
TEST(HardCases, ThousandRevolutionsWithoutDrift) {
  Scene s = seed("1000rev", 0.0);
  s.carts.count = 2;
  s.carts.side = {1, -1};
  s.rods.model = RodModel::Massless;
  s.rods.mass = 0.0;
  s.rods.inertia_com = 0.0;
  s.coupling.type = CouplingType::Rigid;
  s.loads.guide_friction = 0.0;
  s.crank.shaft_inertia = 1.0;  // the crankshaft of a massless-rod machine needs its own inertia
  s.initial.crank_speed = 10.42;
  const double w_mean = 10.64;  // steady mean crank speed of this machine [rad/s]
  const double block = 100 * 2.0 * M_PI / w_mean;  // ≈ 100 revolutions [s]
  s.simulation.t_end = 10 * block;
  s.simulation.output_step = 1.0;

  const double a = 1e-5;
  Samples run[2];
  for (int i = 0; i < 2; ++i) {
    const double acc = i == 0 ? a : a / 10.0;
    run[i] = sampleMultibody(withAccuracy(s, acc), block, 10);
    const Samples& r = run[i];
    const double E_ref = referenceKineticEnergy(s);
    for (size_t k = 0; k < r.residual.size(); ++k) {
      ASSERT_TRUE(std::isfinite(r.residual[k]) && std::isfinite(r.omega[k]) && std::isfinite(r.coupling_torque[k]))
          << "a = " << acc << ", block " << k;
      std::printf("  multibody 1000rev a=%.0e rev=%6.1f residual=%.4g J cerr=%.2g omega=%.9g\n", acc,
                  r.revolutions[k], r.residual[k], r.constraint_error[k], r.omega[k]);
      EXPECT_LE(r.constraint_error[k], kConstraintFactor * acc) << "a = " << acc << " after " << r.revolutions[k] << " rev";
    }
    // Energy: within the argued bound at the end (HardCaseSupport.h), and no drift beyond the
    // integration error: the residual grows by no more per 100 revolutions in any block than
    // 3x its growth over the first block, plus 10·a of the energy that block carried (the
    // motor work of 100 revolutions).
    const double E = std::max(std::abs(r.motor_work), E_ref);
    EXPECT_LE(std::abs(r.residual.back()), energyTolerance(acc, E, r.steps, r.revolutions.back()))
        << "a = " << acc << ": residual " << r.residual.back() << " J after " << r.revolutions.back() << " rev";
    const double per_block_energy = std::abs(r.motor_work) / 10.0;
    for (size_t k = 1; k < r.residual.size(); ++k)
      EXPECT_LE(std::abs(r.residual[k] - r.residual[k - 1]),
                3.0 * std::abs(r.residual[0]) + 10.0 * acc * per_block_energy)
          << "a = " << acc << ": energy residual grows faster in block " << k + 1 << " than in block 1";
    // Constraint error: projected every step, so no growth from the first block to the last.
    EXPECT_LE(r.constraint_error.back(), std::max(10.0 * r.constraint_error.front(), kConstraintFactor * acc));
  }
  // Tenfold tighter: final crank speed and the largest sampled coupling torque move by less
  // than claimed (HardCaseSupport.h), after 1000 revolutions.
  const double w_scale = std::max(syncCrankSpeed(s), *std::max_element(run[1].omega.begin(), run[1].omega.end()));
  EXPECT_LE(std::abs(run[0].omega.back() - run[1].omega.back()), kSpeedClaim * a * w_scale);
  auto maxAbsOf = [](const std::vector<double>& v) {
    double m = 0;
    for (double x : v) m = std::max(m, std::abs(x));
    return m;
  };
  EXPECT_LE(std::abs(maxAbsOf(run[0].coupling_torque) - maxAbsOf(run[1].coupling_torque)),
            kTorqueClaim * a * maxAbsOf(run[1].coupling_torque));
  checkCase(Model::Reduced, s, 1e-6);
}

// Cart velocity reversal under both readings of the roller-force direction. As printed, the
// roller forces keep their direction through the reversal (a position-like load); opposing the
// velocity, they flip with sign(v) smoothed as tanh(v/v_s), v_s = 1 mm/s: a jump of 2·(F1 + F2)
// over ~1 ms at every dead centre. Roller forces 3000 N per roller (not 7962) so that the motor
// can carry the opposing-velocity reading (≈ 3.1 kN·m mean against ≈ 4.6 kN·m at breakdown);
// started at nominal speed so the run is all reversals, no start-up.
TEST(HardCases, CartVelocityReversalUnderBothForceReadings) {
  for (RollerForceDirection d : {RollerForceDirection::AsPrinted, RollerForceDirection::OpposesVelocity}) {
    Scene s = seed(std::string("reversal-") + toString(d), 1.0);
    s.loads.roller_force_direction = d;
    s.loads.roller_force_front = s.loads.roller_force_rear = 3000.0;
    s.initial.crank_speed = 10.4;
    for (Model m : {Model::Multibody, Model::Reduced}) {
      const RunResult r = checkCase(m, s, 1e-6);
      const Table& t = r.timeseries;
      bool pos = false, neg = false;  // cart 1 moves both ways: at least one reversal
      for (const auto& row : t.rows) {
        pos |= row[t.index("v_cart_1")] > 0.1;
        neg |= row[t.index("v_cart_1")] < -0.1;
      }
      EXPECT_TRUE(pos && neg) << name(m) << " " << toString(d);
      if (d == RollerForceDirection::OpposesVelocity) {
        EXPECT_GT(r.energy.load_work, 0.0) << name(m) << ": a resistance must absorb work";
      }
    }
  }
}

// 32 carts, cranks 11.25° apart, all on one side: 32 loop closures (64 constraint equations in
// the multibody model) on one crankshaft; the motor is scaled 8x with the machine. One
// multibody right-hand side costs ~30x that of four carts (benchmarks/bench_rhs.cpp), so the
// run is 0.25 s at a = 1e-5 (and 1e-6).
TEST(HardCases, ThirtyTwoCarts) {
  Scene s = seed("32-carts", 0.25);
  s.carts.count = 32;
  s.carts.side.assign(32, 1);
  s.crank.offset = 2.0 * M_PI / 32;
  s.motor.breakdown_torque *= 8.0;
  s.initial.crank_speed = 10.4;
  for (Model m : {Model::Multibody, Model::Reduced}) checkCase(m, s, 1e-5);
}

}  // namespace
}  // namespace rollerdyn::hardcases
