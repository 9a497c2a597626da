// Hard cases: one test per case, each running both models at an accuracy a and at a/10 and
// asserting no exception/NaN, constraint error (multibody), energy audit, convergence of the
// crank-speed and coupling-torque time series, and the agreement of the two models
// (HardCaseSupport.h explains the error model behind every bound; each case gives its measured
// constants). Machine: Loveikin, Pochka, Romasevych (2018) (tests/support/Loveikin2018Scene.h:
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
#include "multibody/MultibodyModel.h"
#include "physics/KlossMotor.h"

namespace rollerdyn::hardcases {
namespace {

// A case's claims (HardCaseSupport.h): error constants per model (the multibody model per
// formulation: constrained, then minimal) and the models' agreement. The constants scatter with
// the integrator's step sequence: round-off-level changes of the right-hand side (a different
// summation order) moved single values of CVODE Adams (minimal formulation, reduced model) by up
// to 20x, and the reduced model's at neighbouring accuracies by up to 10⁴x (StiffCoupling1e9WithDamping);
// Runge-Kutta-Merson's (constrained formulation) by up to 3x. So every constant of every model is
// the largest over five accuracies a·{0.7, 0.85, 1, 1.2, 1.4} (five step sequences;
// ROLLERDYN_HARDCASE_ACCURACY_SCALE in HardCaseSupport.h), and the claim is 3x that (rounded up to
// two digits), measured on this build (Release, g++ 12) by
//   /usr/bin/python3 scripts/hardcase-constants.py
// which prints the constants beside the claims and flags a claim below its measurement. Given
// beside each claim as "largest over the five accuracies": residual/(a·E) (the larger of a and
// a/10), dw/(a·W), dM/(a·M); the earlier single measurements at a ("measured ...") are kept for
// the history of each case. The models' agreement at a/10 (max|dw|/W, max|dM|/M) follows the
// same rule, its largest over the five accuracies taken over both multibody formulations (one
// agreement claim serves both); largest values, constrained and minimal alike: stiff-1e9-damped
// 4.8e-5, 7.5e-3; stiff-1e9-undamped 1.1e-4, 0.034; free-100rev 1.6e-4, 0.027; in-phase 5.1e-6,
// 2.9e-5; overload 1.7e-7, 1.4e-5; from-rest 5.8e-4, 4.2e-3; synchronous 1.1e-7, 2.6e-5;
// reversal 1.1e-4, 8.6e-3; 32 carts 2.9e-5, 2.5e-3.
Expect claims(Claims multibody, Claims multibody_minimal, Claims reduced, double models_speed, double models_torque) {
  Expect e;
  e.multibody = multibody;
  e.multibody_minimal = multibody_minimal;
  e.reduced = reduced;
  e.models_speed = models_speed;
  e.models_torque = models_torque;
  return e;
}

Scene seed(const std::string& name, double t_end) {
  Scene s = hardCaseMachine();
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
//
// Started at the nominal crank speed 10.42 rad/s and run for 1.8 s, three crank revolutions, so
// the stiff mode is crossed by every cart reversal of a full cycle (from rest the drive covers
// only 0.14 revolutions in 0.5 s). The start without twist excites the stiff mode once; the
// damper (decay rate k·p0²/(2c) ≈ 80 1/s) removes it within ~0.05 s.
TEST(HardCases, StiffCoupling1e9WithDamping) {
  Scene s = seed("stiff-1e9-damped", 1.8);
  s.coupling.stiffness = 1e9;
  s.initial.crank_speed = 10.42;
  // measured: multibody 1.9e-6, 0.022, 79; reduced 0.015, 0.22, 2.1e3; models 4.8e-5, 7.5e-3.
  // (The multibody energy residual is 2e-12·E, at the round-off floor.)
  // Minimal formulation measured: 7.0e-5 (at a) and 2.4e-4 (at a/10), 1.8e-3, 15. Its energy
  // residual does NOT converge: 5.1e-6, 6.5e-7, 2.2e-7, 4.8e-6, 2.9e-10 J at a = 1e-5 ... 1e-9
  // (3x from a to a/10, and back up at 1e-8), at most 5e-10·E: likely CVODE Adams's step is set
  // by the stability of the 4.5e3 rad/s mode here, not by its error control, so the audit
  // integrals' errors do not follow the tolerance. The claim is the measurement at a and a/10.
  // With the structured Newton Jacobian (MinimalSimulation.cpp): 5.9e-4 (a), 7.2e-4 (a/10). Over
  // 30 accuracies from 1e-5 to 1e-7 |C_E| has median 1.7e-4, 90 % 1.1e-3, max 3.9e-3 (full
  // Jacobian: 1.0e-4, 5.7e-4, 8.2e-3); at a = 2e-6 and 1.5e-6 single stretches where the step
  // outgrows the 4.5e3 rad/s mode leave 0.64 and 0.68 (not seen with the full Jacobian).
  // Minimal formulation, largest over a·{0.7, 0.85, 1, 1.2, 1.4} (see the top of this file): 0.013, 0.0022, 22.
  // Constrained formulation, largest over the five accuracies: 6.2e-6, 0.024, 88. Reduced model
  // (Adams order capped at 6, ReducedIntegrators.cpp): 0.0065, 0.22, 2.1e3 over the five, but over
  // 19 accuracies a·{0.6, 0.65, ..., 1.5} 0.001 ... 0.019·a·E except 30.8 at 1.15·a and 12.9 at
  // 0.6·a (speed 13.3 and 1.6 there): an error CVODE's test accepts within the first 5 ms of the
  // stiff mode's start transient (same with order 12, where 0.85·a gave 46.5). The claim covers
  // every accuracy measured: 3x 30.8, 13.3, 2.1e3.
  const BothModels b = checkBothModels(s, 1e-6, claims({1.9e-5, 0.072, 270}, {0.041, 0.0066, 67}, {93, 40, 6300}, 1.5e-4, 0.023));
  if (modelSelected("multibody")) EXPECT_GE(revolutions(b.multibody.at_a), 2.9);
  if (modelSelected("reduced")) EXPECT_GE(revolutions(b.reduced.at_a), 2.9);
}

// Same, undamped (k = 0): the 4.5e3 rad/s mode is excited at every cart reversal, where the
// guide friction flips sign within ~v_s/a_cart (tanh, v_s = 1 mm/s), and never decays. Its
// amplitude depends on how exactly each flip is traversed and converges slowly, which is why
// this case's torque constants (measured below: 6.5e3 multibody, 1.9e4 reduced, i.e. 0.65 % and
// 1.9 % of the largest coupling torque at a = 1e-6) are the largest of the short cases. (Before
// commit 21ac486 the multibody model failed this case, 16 % at a = 1e-6, for the reason given
// above StiffCoupling1e9WithDamping.) Kept at 0.5 s from rest: the undamped stiff mode makes
// this the costliest short case per simulated second (~10^4 steps per model and accuracy).
TEST(HardCases, StiffCoupling1e9WithoutDamping) {
  Scene s = seed("stiff-1e9-undamped", 0.5);
  s.coupling.stiffness = 1e9;
  s.coupling.damping = 0.0;
  // measured: multibody 4.3e-6, 2.2, 6.5e3; reduced 3.1e-3, 6.1, 1.9e4; models 1.0e-4, 0.016.
  // Minimal formulation: 6.5e-5 (a; 3.1e-5 at a/10, residual 21x smaller), 0.23, 691.
  // Minimal formulation, largest over a·{0.7, 0.85, 1, 1.2, 1.4} (see the top of this file): 0.00014, 0.18, 6e+02.
  // Constrained formulation, largest over the five accuracies: 6.0e-6, 2.8, 8.4e3; reduced model:
  // 3.3e-3, 19.8, 6.6e4.
  checkBothModels(s, 1e-6, claims({1.8e-5, 8.4, 2.6e4}, {0.00041, 0.55, 1900}, {0.0099, 60, 2e5}, 3.3e-4, 0.11));
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
  // The undamped coupling mode (p0 ≈ 88 rad/s, Dyomin (two rotors) eq. (10)) runs through ~880
  // periods and its phase error grows with every one of them, so this case's constants are the
  // largest of all (the time series differ most late in the run). measured: multibody 0.097, 114, 2.0e4; reduced 0.14, 478, 8.3e4; models 1.2e-4, 0.021.
  // Minimal formulation: 0.064 (a) and 0.105 (a/10; residual 6x smaller), 5.6, 961 (CVODE at
  // 0.01·a, MinimalSimulation.cpp, keeps the coupling mode's phase 20x closer than Simbody at a).
  // Minimal formulation, largest over a·{0.7, 0.85, 1, 1.2, 1.4} (see the top of this file): 0.11, 6, 1e+03.
  // Constrained formulation, largest over the five accuracies: 0.32, 125, 2.2e4; reduced model:
  // 3.9, 641, 1.1e5 (its energy constant is 3.9 at a·0.85 ... 1.4 alike; the earlier claim 0.43
  // was one low draw).
  const BothModels b = checkBothModels(s, 1e-6, claims({0.96, 380, 6.5e4}, {0.34, 19, 3100}, {12, 2000, 3.4e5}, 4.7e-4, 0.081));
  for (Model m : {Model::Multibody, Model::Reduced}) {
    if (!modelSelected(name(m))) continue;  // measurement runs of one model (HardCaseSupport.h)
    const RunResult& r = (m == Model::Multibody ? b.multibody : b.reduced).at_a;
    EXPECT_GE(revolutions(r), 95.0) << name(m);
    // Conservation itself: no motor, no dissipation, no load work; the audit's residual is
    // then ΔT + ΔV, checked above against the claimed C_E·a·E.
    EXPECT_EQ(r.energy.motor_work, 0.0) << name(m);
    EXPECT_EQ(r.energy.load_work, 0.0) << name(m);
    EXPECT_EQ(r.energy.friction_dissipation, 0.0) << name(m);
  }
}

// Δφ = 0: all four carts in phase. Their dead centres coincide (x_B' = 0 for all at once, so
// J_n2(φ) dips to the rods' share alone) and the as-printed roller-force torques add up to
// ≈ 12.8 kN·m peaks, nearly three times the motor's ≈ 4.6 kN·m at breakdown: from rest the
// drive cannot push the carts over and the crank rocks back and forth. Asserted: in both models
// the crank speed takes both signs (it rocks) and the crank never completes a revolution; the
// two models' crank-speed and coupling-torque series agree to the stated tolerance.
TEST(HardCases, AllCartsInPhase) {
  Scene s = seed("in-phase", 1.0);
  s.crank.offset = 0.0;
  // measured: multibody 5.1e-4, 0.022, 0.98; reduced 4.3, 9.9, 140; models 4.9e-6, 2.5e-5
  // (no rotation, so the guide friction, the models' one physical difference, hardly differs).
  // Minimal formulation: 0.104 (a; 0.025 at a/10, residual 41x smaller), 0.66, 4.4: energy 70x,
  // speed 10x the constrained formulation's. Likely reason: CVODE Adams controls the local
  // error of the energy-audit integrals only against atol = 0.01·a·E_ref per step (RMS norm
  // over all states), where Simbody's Merson keeps the states at a; the crank rocking through
  // near-zero speed is where Adams changes order and step most. It converges.
  // Minimal formulation, largest over a·{0.7, 0.85, 1, 1.2, 1.4} (see the top of this file): 0.16, 0.35, 3.2.
  // Constrained formulation, largest over the five accuracies: 7.0e-4, 0.027, 1.3; reduced model:
  // 9.3, 14, 285.
  const BothModels b = checkBothModels(s, 1e-6, claims({2.1e-3, 0.081, 3.9}, {0.48, 1.1, 9.7}, {28, 43, 860}, 1.6e-5, 8.6e-5));
  for (Model m : {Model::Multibody, Model::Reduced}) {
    if (!modelSelected(name(m))) continue;  // measurement runs of one model (HardCaseSupport.h)
    const Table& t = (m == Model::Multibody ? b.multibody : b.reduced).at_a.timeseries;
    double lo = 0, hi = 0;
    for (const auto& row : t.rows) {
      lo = std::min(lo, row[t.index("omega_crank")]);
      hi = std::max(hi, row[t.index("omega_crank")]);
    }
    std::printf("  %-9s in-phase: omega_crank in [%.4g, %.4g] rad/s, %.3g revolutions\n", name(m), lo, hi,
                revolutions((m == Model::Multibody ? b.multibody : b.reduced).at_a));
    EXPECT_LT(lo, -0.1) << name(m) << ": the crank never turns backwards";
    EXPECT_GT(hi, 0.1) << name(m) << ": the crank never turns forwards";
    EXPECT_LT(revolutions((m == Model::Multibody ? b.multibody : b.reduced).at_a), 1.0) << name(m);
  }
}

// Overload beyond the breakdown torque: the roller forces oppose the velocity (the other
// reading of Loveikin, Pochka, Romasevych (2018)), four carts need ≈ 8.1 kN·m mean crank torque against ≈ 4.6 kN·m at
// breakdown. The run must end early with "motor stalled at t = ..." and complete = false, not
// blow up or hang.
TEST(HardCases, OverloadStallsWithClearStatus) {
  Scene s = seed("overload", 3.0);
  s.loads.roller_force_direction = RollerForceDirection::OpposesVelocity;
  // measured: multibody 1.6e-6, 0.038, 2.8; reduced 0.082, 0.96, 754; models 8.2e-8, 7.7e-6.
  // Minimal formulation: 3.5e-4 (a) and 1.2e-3 (a/10), 7.8e-3, 0.77. Energy residual only 3x
  // smaller at a/10 (3.3e-6 -> 1.1e-6 J; 4.1e-6, 2.3e-8, 4.2e-8 J at a = 1e-5, 1e-8, 1e-9): it
  // converges over the ladder, not tenfold per decade (CVODE Adams's variable order).
  // Minimal formulation, largest over a·{0.7, 0.85, 1, 1.2, 1.4} (see the top of this file): 0.0014, 0.0097, 0.95.
  // Constrained formulation, largest over the five accuracies: 2.5e-6, 0.040, 2.9; reduced model:
  // 0.090, 0.99, 754.
  Expect stalled = claims({7.5e-6, 0.12, 8.8}, {0.0042, 0.03, 2.9}, {0.28, 3, 2300}, 5.2e-7, 4.3e-5);
  stalled.complete = false;
  stalled.status_prefix = "motor stalled at t = ";
  const BothModels b = checkBothModels(s, 1e-6, stalled);
  for (Model m : {Model::Multibody, Model::Reduced}) {
    if (!modelSelected(name(m))) continue;  // measurement runs of one model (HardCaseSupport.h)
    const RunResult& r = (m == Model::Multibody ? b.multibody : b.reduced).at_a;
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
  // measured: multibody 4.5e-3, 0.16, 3.4; reduced 14, 7.0, 103. The models are NOT compared
  // here: they differ by 4 % in crank speed and 54 % of the largest coupling torque at a/10.
  // Their one physical difference, guide friction from dynamic (multibody) or quasi-static
  // (reduced) normal forces, is largest near lock-up, where the rod at β = 72° presses the cart
  // into its guide with a large vertical force; a modelling difference, not an error bound.
  // Minimal formulation: 2.0e-3 (a) and 6.1e-3 (a/10), 0.034, 0.50; models 0.041, 0.54 (same
  // difference). Energy residual 3x smaller at a/10 (2.2e-5 -> 6.8e-6 J; 5.4e-4, 7.2e-6,
  // 5.0e-7 J at a = 1e-5, 1e-8, 1e-9): plateau between 1e-7 and 1e-8, converges beyond.
  // With the structured Newton Jacobian: 7.6e-3 (a), 0.076 (a/10). The constant scatters with the
  // accuracy: over 30 accuracies from 1e-5 to 1e-7 |C_E| has median 0.032, 90 % 0.066, max 0.076
  // (full Jacobian: 0.040, 0.094, 0.13), so the earlier 6.1e-3 was a low draw.
  // Minimal formulation, largest over a·{0.7, 0.85, 1, 1.2, 1.4} (see the top of this file): 0.12, 0.43, 5.9.
  // Constrained formulation, largest over the five accuracies: 5.1e-3, 0.16, 3.4; reduced model:
  // 26, 13, 173.
  checkBothModels(s, 1e-6, claims({0.016, 0.5, 11}, {0.36, 1.4, 18}, {78, 38, 520}, 0, 0));
}

// Start from rest: slip s = 1, motor at its starting torque, every cart velocity 0 (the
// smoothed sign laws at their steepest), coupling twist building from 0.
TEST(HardCases, StartFromRest) {
  Scene s = seed("from-rest", 1.0);
  ASSERT_EQ(s.initial.crank_speed, 0.0);
  // measured: multibody 1.5e-3, 0.022, 0.40; reduced 23, 6.2, 110; models 5.8e-4, 4.2e-3.
  // Minimal formulation: 5.4e-5 (a) and 0.019 (a/10), 0.12, 1.2. The residual at a is a sign
  // change passing near 0 (8.7e-3, -5.2e-7, 1.8e-5, -1.8e-6, -6.9e-7 J at a = 1e-5 ... 1e-9):
  // larger at a/10 than at a, decreasing over the ladder as a whole; the claim is a/10's.
  // With the structured Newton Jacobian: 0.36 (a), 0.048 (a/10). Over 30 accuracies from 1e-5 to
  // 1e-7 |C_E| has median 0.058, 90 % 0.24, max 0.58 (full Jacobian: 0.057, 0.27, 0.53): the
  // near-zero value at a was a sign change, the claim is now a's.
  // Minimal formulation, largest over a·{0.7, 0.85, 1, 1.2, 1.4} (see the top of this file): 0.39, 0.51, 3.1.
  // Constrained formulation, largest over the five accuracies: 1.7e-3, 0.023, 0.72; reduced model:
  // 41, 6.5, 110.
  const BothModels b = checkBothModels(s, 1e-6, claims({5e-3, 0.069, 2.2}, {1.2, 1.6, 9.4}, {130, 20, 330}, 1.8e-3, 0.013));
  for (Model m : {Model::Multibody, Model::Reduced}) {
    if (!modelSelected(name(m))) continue;  // measurement runs of one model (HardCaseSupport.h)
    const RunResult& r = (m == Model::Multibody ? b.multibody : b.reduced).at_a;
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
  // measured: multibody 4.6e-4, 2.0e-3, 0.94; reduced 1.1, 0.37, 180; models 9.8e-8, 1.7e-5
  // (no loads, no friction: identical physics in both models).
  // Minimal formulation: 0.019 (a; 5.6e-3 at a/10, residual 33x smaller), 8.6e-3, 2.7.
  // Minimal formulation, largest over a·{0.7, 0.85, 1, 1.2, 1.4} (see the top of this file): 0.033, 0.017, 2.8.
  // Constrained formulation, largest over the five accuracies: 4.6e-4, 2.6e-3, 0.94; reduced model:
  // 2.1, 0.72, 289.
  const BothModels b = checkBothModels(s, 1e-6, claims({1.4e-3, 7.7e-3, 2.9}, {0.098, 0.051, 8.6}, {6.3, 2.2, 870}, 3.5e-7, 8e-5));
  for (Model m : {Model::Multibody, Model::Reduced}) {
    if (!modelSelected(name(m))) continue;  // measurement runs of one model (HardCaseSupport.h)
    const RunResult& r = (m == Model::Multibody ? b.multibody : b.reduced).at_a;
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
// Multibody claims of the 1000-revolution case, measured at a = 1e-5 (energy: the larger of a
// and a/10): residual/(a·E) 945 and 982 (E = motor work, 6.7 kJ: the error grows with the
// revolutions, ~1·a·E per revolution, and scales with a), dw/(a·W) 1.7, dM/(a·M) 19 over the
// ten samples. Largest over a·{0.7, 0.85, 1, 1.2, 1.4}: 1.07e3, 1.8, 20. Claims 3x that. These
// runs call Simbody's integrator directly (sampleMultibody), i.e.
// the constrained formulation also under ROLLERDYN_MULTIBODY_FORMULATION=minimal.
constexpr Claims kThousandRev{3300, 5.4, 60};
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

  const double a = 1e-5 * accuracyScale();  // the measurement hook, as in checkCase
  Samples run[2];
  for (int i = 0; i < 2 && modelSelected("multibody"); ++i) {
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
    // Energy: within the error model at the end (HardCaseSupport.h, constant kThousandRev.energy),
    // and no drift beyond the integration error: the residual grows by no more per 100
    // revolutions in any block than 3x its growth over the first block, plus the claim's share
    // of the energy that block carried (the motor work of 100 revolutions).
    const double E = std::max(std::abs(r.motor_work), E_ref);
    std::printf("  multibody 1000rev a=%.0e steps=%ld residual/(a*E)=%.3g (E=%.4g J)\n", acc, r.steps,
                r.residual.back() / (acc * E), E);
    EXPECT_LE(std::abs(r.residual.back()), energyTolerance(acc, E, kThousandRev.energy))
        << "a = " << acc << ": residual " << r.residual.back() << " J = " << r.residual.back() / (acc * E)
        << "·a·E after " << r.revolutions.back() << " rev, claimed " << kThousandRev.energy << "·a·E";
    const double per_block_energy = std::abs(r.motor_work) / 10.0;
    for (size_t k = 1; k < r.residual.size(); ++k)
      EXPECT_LE(std::abs(r.residual[k] - r.residual[k - 1]),
                3.0 * std::abs(r.residual[0]) + energyTolerance(acc, per_block_energy, kThousandRev.energy))
          << "a = " << acc << ": energy residual grows faster in block " << k + 1 << " than in block 1";
    // Constraint error: projected every step, so no growth from the first block to the last.
    EXPECT_LE(r.constraint_error.back(), std::max(10.0 * r.constraint_error.front(), kConstraintFactor * acc));
  }
  // Tenfold tighter: the sampled series of crank speed and coupling torque (every 100
  // revolutions) move by less than the error model claims.
  auto maxAbsOf = [](const std::vector<double>& v) {
    double m = 0;
    for (double x : v) m = std::max(m, std::abs(x));
    return m;
  };
  double dw = 0, dM = 0;
  for (size_t k = 0; k < run[0].omega.size() && k < run[1].omega.size(); ++k) {
    dw = std::max(dw, std::abs(run[0].omega[k] - run[1].omega[k]));
    dM = std::max(dM, std::abs(run[0].coupling_torque[k] - run[1].coupling_torque[k]));
  }
  const double W = std::max(syncCrankSpeed(s), maxAbsOf(run[1].omega)), M = maxAbsOf(run[1].coupling_torque);
  std::printf("  multibody 1000rev convergence a=%.0e: dw/(a*W)=%.3g dM/(a*M)=%.3g\n", a, dw / (a * W), dM / (a * M));
  EXPECT_LE(dw, kThousandRev.speed * a * W) << "crank speed samples move by " << dw / (a * W) << "·a·W";
  EXPECT_LE(dM, kThousandRev.torque * a * M) << "coupling torque samples move by " << dM / (a * M) << "·a·M";
  // Reduced, measured at a = 1e-6: residual/(a·E) 5.9e3 and 7.8e3 (at a/10), dw/(a·W) 55,
  // dM/(a·M) 493 over the whole time series (1000 revolutions). Largest over a·{0.7, 0.85, 1, 1.2,
  // 1.4} (Adams order capped at 6): 7.2e3, 127, 999. Claims 3x that.
  Expect reduced = claims({}, {}, {2.2e4, 390, 3000}, 0, 0);
  checkCase(Model::Reduced, s, 1e-6, reduced);
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
    // measured, as printed: multibody 2.6e-4, 0.011, 1.2; reduced 5.3, 0.85, 122; models 1.1e-4,
    // 8.6e-3. Opposing the velocity: multibody 1.4e-3, 9.9e-3, 0.63; reduced 3.8, 3.0, 54;
    // models 6.6e-5, 8.2e-4. One claim for both readings: the larger of each pair.
    // Minimal formulation, as printed: 0.064 (a) and 0.087 (a/10; residual 7x smaller), 0.039,
    // 4.0; opposing the velocity: 0.049 (a) and 0.041 (a/10; 12x smaller), 0.014, 0.14.
    // Minimal formulation, largest over a·{0.7, 0.85, 1, 1.2, 1.4} (see the top of this file), as printed: 0.19, 0.055, 5.6; opposing the velocity: 0.048, 0.023, 0.47.
    // Constrained formulation, largest over the five accuracies and both readings: 1.6e-3, 0.024,
    // 3.9; reduced model: 15, 6.4, 149.
    const BothModels b = checkBothModels(s, 1e-6, claims({4.8e-3, 0.071, 12}, {0.57, 0.17, 17}, {45, 20, 450}, 3.3e-4, 0.026));
    for (Model m : {Model::Multibody, Model::Reduced}) {
      if (!modelSelected(name(m))) continue;  // measurement runs of one model (HardCaseSupport.h)
      const RunResult& r = (m == Model::Multibody ? b.multibody : b.reduced).at_a;
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
  // measured: multibody 3.6e-4, 2.4e-3, 1.7; reduced 1.5, 1.2, 169; models 2.9e-5, 2.5e-3.
  // Minimal formulation: 1.9e-3 (a; 1.4e-3 at a/10, residual 13x smaller), 1.4e-3, 0.37.
  // Minimal formulation, largest over a·{0.7, 0.85, 1, 1.2, 1.4} (see the top of this file): 0.033, 0.017, 10.
  // Constrained formulation, largest over the five accuracies: 3.8e-4, 4.5e-3, 1.7; reduced model:
  // 2.3, 1.2, 307.
  checkBothModels(s, 1e-5, claims({1.2e-3, 0.014, 5.1}, {0.099, 0.052, 31}, {6.9, 3.7, 930}, 8.8e-5, 7.5e-3));
}

}  // namespace
}  // namespace rollerdyn::hardcases
