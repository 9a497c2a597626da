// Shared checks of the hard-case tests (issue #4). Every case runs BOTH models twice, at an
// accuracy a and at a/10, and asserts four things per model:
//
//   1. no exception and no NaN/inf anywhere in the output tables;
//   2. constraint error (multibody) within kConstraintFactor·a [m]: Simbody projects the
//      position constraints to the constraint tolerance (= a, the scene default) after every
//      step, in a weighted norm whose length scale is 1 m (our links are 0.2 ... 1 m long), so
//      the error left in metres is of order a; the factor 10 covers the weighting and the
//      interpolated output states (which are projected too, to the same tolerance);
//   3. the energy audit closes: |residual| <= energyTolerance(a, E, N) below;
//   4. tightening the accuracy tenfold changes the results by less than the error we claim for
//      the run at a: the final crank speed by at most kSpeedClaim·a·max|ω| and the largest
//      coupling torque by at most kTorqueClaim·a·max|M_c| (see the constants).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cmath>
#include <string>
#include <vector>

#include "multibody/MultibodySimulation.h"
#include "reduced/ReducedModel.h"
#include "scene/Scene.h"
#include "support/Seed000Scene.h"

namespace rollerdyn::hardcases {

// Claimed relative error of a run at integrator accuracy a (factor × a), in the bench's measure
// (src/bench/BenchRun.h: deviation over the run relative to the signal's largest magnitude).
// `rollerdyn bench model/balanced-4cart.yaml` measures, at a = 1e-6, error_omega ≈ 9·a
// (multibody RungeKuttaMerson) and ≈ 21·a (reduced CVODE), error_coupling ≈ 60·a and ≈ 160·a.
// The claims keep a factor ~5 of margin above those measurements.
constexpr double kSpeedClaim = 100.0;    // crank speed
constexpr double kTorqueClaim = 1000.0;  // coupling torque
constexpr double kConstraintFactor = 10.0;

// Energy-audit tolerance [J]. The work integrals (motor, damper, friction, loads) are extra
// states under the same error control as the motion: each accepted step leaves a local error of
// at most about a·E in them (E = the run's energy scale below; CVODE's absolute tolerance on the
// work states is a·E_ref, Simbody's relative control is against the same magnitudes). They are
// quadratures, so nothing damps their errors: the global error is the sum of the local errors.
// Two ways that sum grows, and the bound takes the larger:
//   - local errors of successive steps of an adaptive method vary in sign like a random walk:
//     ~ a·E·√n_steps;
//   - a systematic error per forcing period (one crank revolution: J(φ), loads and motor torque
//     are periodic in φ) grows linearly: ~ a·E·N_rev.
//   |residual| <= 10·a·E·max(1, √n_steps, N_rev),
// the factor 10 being the usual gap between the local tolerance an RK/Adams method is asked for
// and the error it delivers. E = the largest of the motor work, the initial and final kinetic
// energies and the kinetic energy at synchronous crank speed (or at the initial speed when the
// motor is off), so a stalled or free-running machine still has a meaningful scale.
// (Measured on these cases: multibody residuals are 1e-5 ... 1e-2·a·E, reduced CVODE/Adams
// 1 ... 31·a·E with 130 ... 430 steps.)
inline double energyTolerance(double accuracy, double energy_scale, long steps, double revolutions) {
  return 10.0 * accuracy * energy_scale * std::max({1.0, std::sqrt(double(steps)), revolutions});
}

inline Scene withAccuracy(Scene s, double a) {
  s.simulation.accuracy = a;
  s.simulation.constraint_tolerance = a;
  return s;
}

inline double syncCrankSpeed(const Scene& s) { return s.motor.omega_sync / s.reducer.ratio; }

// Kinetic energy of the whole machine at the reference speed (synchronous, or the initial speed
// with the motor off), with the reduced inertia at the initial crank angle [J].
inline double referenceKineticEnergy(const Scene& s) {
  const ReducedModel m(s);
  const double w = s.motor.enabled ? syncCrankSpeed(s) : std::abs(s.initial.crank_speed);
  const double J = m.reducedInertia(s.initial.crank_angle) + (m.rigid() ? 0.0 : m.motorSideInertia());
  return 0.5 * J * w * w;
}

inline double energyScale(const Scene& s, const RunResult& r) {
  const EnergyAudit& e = r.energy;
  return std::max({std::abs(e.motor_work), std::abs(e.kinetic_initial), std::abs(e.kinetic_final),
                   referenceKineticEnergy(s)});
}

inline bool allFinite(const Table& t) {
  for (const auto& row : t.rows)
    for (double v : row)
      if (!std::isfinite(v)) return false;
  return true;
}

inline double maxAbs(const Table& t, const std::string& column) {
  double m = 0.0;
  const int c = t.index(column);
  for (const auto& row : t.rows) m = std::max(m, std::abs(row[c]));
  return m;
}

inline double last(const Table& t, const std::string& column) {
  return t.rows.empty() ? NAN : t.rows.back()[t.index(column)];
}

// Crank revolutions covered by a run (|φ_end − φ_0| / 2π).
inline double revolutions(const RunResult& r) {
  const Table& t = r.timeseries;
  if (t.rows.size() < 2) return 0.0;
  const int c = t.index("phi_crank");
  return std::abs(t.rows.back()[c] - t.rows.front()[c]) / (2.0 * M_PI);
}

enum class Model { Multibody, Reduced };
inline const char* name(Model m) { return m == Model::Multibody ? "multibody" : "reduced"; }

// The multibody model runs in the formulation named by ROLLERDYN_MULTIBODY_FORMULATION
// (constrained | minimal; tests/CMakeLists.txt runs this suite once more with minimal), else in
// the scene's own.
inline Scene inFormulation(Scene s) {
  const char* f = std::getenv("ROLLERDYN_MULTIBODY_FORMULATION");
  if (f && std::string(f) == "minimal") s.simulation.formulation = Formulation::Minimal;
  if (f && std::string(f) == "constrained") s.simulation.formulation = Formulation::Constrained;
  return s;
}

inline RunResult run(Model m, const Scene& s) {
  return m == Model::Multibody ? runMultibodyModel(inFormulation(s)) : runReducedModel(s);
}

// What a case expects of how the run ends, and the errors it claims.
struct Expect {
  bool complete = true;        // false: the run must end early (and say why in status)
  std::string status_prefix;   // e.g. "motor stalled at t = "; empty: not checked
  double speed_claim = kSpeedClaim;    // claimed error of the final crank speed, × a
  double torque_claim = kTorqueClaim;  // claimed error of the largest coupling torque, × a
};

// The four checks of the file comment on a pair of runs (a and a/10) of one model. Returns the
// run at accuracy a for case-specific checks.
inline RunResult checkCase(Model model, const Scene& scene, double a, const Expect& expect = {}) {
  const std::string who = std::string(name(model)) + " on " + scene.name;
  RunResult r1, r2;
  const Scene s1 = withAccuracy(scene, a), s2 = withAccuracy(scene, a / 10.0);
  EXPECT_NO_THROW(r1 = run(model, s1)) << who;
  EXPECT_NO_THROW(r2 = run(model, s2)) << who << " at a/10";
  for (const RunResult* r : {&r1, &r2}) {
    const std::string at = who + (r == &r1 ? " at a" : " at a/10");
    EXPECT_FALSE(r->timeseries.rows.empty()) << at;
    if (r->timeseries.rows.empty()) return r1;
    EXPECT_TRUE(allFinite(r->timeseries)) << at << ": non-finite value in timeseries";
    EXPECT_TRUE(allFinite(r->reactions)) << at << ": non-finite value in reactions";
    EXPECT_EQ(r->stats.complete, expect.complete) << at << ": status " << r->stats.status;
    if (!expect.status_prefix.empty()) {
      EXPECT_EQ(r->stats.status.rfind(expect.status_prefix, 0), 0u)
          << at << ": status '" << r->stats.status << "' should start with '" << expect.status_prefix << "'";
    }
    const double acc = r == &r1 ? a : a / 10.0;
    EXPECT_LE(r->stats.constraint_error_max, kConstraintFactor * acc) << at;
    const Scene& s = r == &r1 ? s1 : s2;
    const double E = energyScale(s, *r), N = revolutions(*r);
    std::printf("  %-9s %-24s a=%.0e steps=%ld revs=%.2f residual=%.3g J E=%.3g J residual/(a*E)=%.3g cerr=%.2g %s\n",
                name(model), scene.name.c_str(), acc, r->stats.steps, N, r->energy.residual(), E,
                r->energy.residual() / (acc * E), r->stats.constraint_error_max, r->stats.status.c_str());
    EXPECT_LE(std::abs(r->energy.residual()), energyTolerance(acc, E, r->stats.steps, N))
        << at << ": energy residual " << r->energy.residual() << " J, energy scale " << E << " J, "
        << N << " revolutions";
  }
  // 4. tenfold tighter accuracy moves the results by less than claimed. Speed errors are
  // claimed against max(max|ω|, ω0/u): both integrators control the speed against a floor of
  // that order (CVODE: atol_ω = a·ω0/u; Simbody: unit weights, i.e. a floor of ~1 rad/s), so a
  // creeping or stalled machine is not held to a relative error of its creep speed.
  const double w_scale = std::max(maxAbs(r2.timeseries, "omega_crank"), syncCrankSpeed(scene));
  EXPECT_LE(std::abs(last(r1.timeseries, "omega_crank") - last(r2.timeseries, "omega_crank")),
            expect.speed_claim * a * w_scale)
      << who << ": final crank speed " << last(r1.timeseries, "omega_crank") << " vs "
      << last(r2.timeseries, "omega_crank") << " rad/s at a/10";
  const double m1 = maxAbs(r1.timeseries, "coupling_torque"), m2 = maxAbs(r2.timeseries, "coupling_torque");
  EXPECT_LE(std::abs(m1 - m2), expect.torque_claim * a * m2)
      << who << ": max |coupling torque| " << m1 << " vs " << m2 << " N·m at a/10";
  return r1;
}

}  // namespace rollerdyn::hardcases
