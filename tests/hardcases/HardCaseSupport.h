// Shared checks of the hard-case tests. Every case runs BOTH models twice, at an accuracy a and
// at a/10, and asserts per model:
//
//   1. no exception and no NaN/inf anywhere in the output tables;
//   2. constraint error (multibody only): within kConstraintFactor·a [m]. Simbody projects the
//      position constraints to the constraint tolerance (= a) after every step, in a weighted
//      norm whose length scale is 1 m (our links are 0.2 ... 1 m long), so the error left in
//      metres is of order a; the factor 10 covers the weighting and the interpolated output
//      states. The reduced model has no constraints (one generalized coordinate per shaft, the
//      carts placed by the closed-form kinematics), so its error is identically 0 and the check
//      is not run for it (each reduced run prints "constraint check: not applicable");
//   3. the energy audit closes within the error model of that integrator on that case (below);
//   4. convergence: tightening the accuracy tenfold moves the whole time series of crank speed
//      and coupling torque (max over the common output grid) by less than the error model of
//      that integrator on that case says the run at a carries.
//
// Error model. An adaptive integrator asked for accuracy a delivers a global error C·a, with a
// constant C that depends on the method and on the problem (how stiff, how many revolutions,
// how often the smoothed sign laws flip), not on a. So each case states C per model and per
// quantity, MEASURED on this build (the numbers are in the comment beside each claim, printed
// by every run as "residual/(a*E)", "dw/(a*W)" and "dM/(a*M)"), and claims 3·C: the factor 3
// covers a different compiler or libm (measured: the constants reproduce to a few per cent
// between a and a/10 where the run converges), and leaves a tenfold regression of any one
// quantity outside the claim. Where the measured C is at round-off level the claim is the
// round-off floor instead (kRoundoffFloor), stated in the case.
//   energy:   |residual| <= C_E·acc·E + kRoundoffFloor·E   (E: energyScale below; checked at a
//             and at a/10, each against its own accuracy);
//   speed:    max_t |ω_a(t) − ω_{a/10}(t)| <= C_ω·a·W      (W = max(max|ω|, ω0/u): both integrators
//             control the speed against a floor of that order, so a creeping or stalled machine
//             is not held to a relative error of its creep speed);
//   torque:   max_t |M_a(t) − M_{a/10}(t)| <= C_M·a·M      (M = max|coupling torque| at a/10).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "multibody/MultibodySimulation.h"
#include "reduced/ReducedModel.h"
#include "scene/Scene.h"
#include "support/Loveikin2018Scene.h"

namespace rollerdyn::hardcases {

constexpr double kConstraintFactor = 10.0;

// Round-off floor of the energy audit, relative to the energy scale E: the audit is a sum of
// five or six terms of size ~E computed in double precision, and the work integrals
// accumulate one rounding per step; 1e-12 ≈ 4500 ε covers ~1e4 steps of that with margin.
constexpr double kRoundoffFloor = 1e-12;

// The error constants a case claims for one model (see the file comment); 0 = not measured,
// the check then fails and says so, so a case cannot silently go unchecked.
struct Claims {
  double energy = 0;  // C_E: |energy residual| <= C_E·acc·E + kRoundoffFloor·E
  double speed = 0;   // C_ω: max_t |ω_a − ω_{a/10}| <= C_ω·a·W
  double torque = 0;  // C_M: max_t |M_a − M_{a/10}| <= C_M·a·M
};

// ROLLERDYN_HARDCASE_ACCURACY_SCALE (default 1) multiplies every case's accuracy a: the way the
// constants are measured over several step sequences (see the file comment). Not for CI.
inline double accuracyScale() {
  const char* v = std::getenv("ROLLERDYN_HARDCASE_ACCURACY_SCALE");
  if (!v || !*v) return 1.0;
  char* end = nullptr;
  const double x = std::strtod(v, &end);
  if (*end != '\0' || !(x > 0.0))
    throw std::invalid_argument(std::string("ROLLERDYN_HARDCASE_ACCURACY_SCALE: expected a positive number, got '") + v + "'");
  return x;
}

// ROLLERDYN_HARDCASE_MODEL = multibody | reduced (default: both) runs only that model's checks
// and skips the models' agreement: the measurement script (scripts/hardcase-constants.py) uses it
// to re-measure one model's constants. Not for CI.
inline bool modelSelected(const char* model) {
  const char* v = std::getenv("ROLLERDYN_HARDCASE_MODEL");
  if (!v || !*v) return true;
  if (std::string(v) != "multibody" && std::string(v) != "reduced")
    throw std::invalid_argument(std::string("ROLLERDYN_HARDCASE_MODEL: expected multibody or reduced, got '") + v + "'");
  return std::string(v) == model;
}

inline double energyTolerance(double accuracy, double energy_scale, double claim) {
  return (claim * accuracy + kRoundoffFloor) * energy_scale;
}

// The hard cases' machine (Loveikin2018Scene.h) in the equations their constants were measured in: the
// multibody model's constrained formulation (ctest runs every case once more in the minimal one,
// multibodyFormulation below) with the lagged normal force of its guide friction, and the reduced
// model's quasi-static guide normals (the papers' cart statics). A Scene built in code has a scene
// file's defaults (minimal, algebraic, kinetostatic), so the cases say theirs here.
inline Scene hardCaseMachine() {
  Scene s = test_scenes::loveikin2018Scene();
  s.simulation.formulation = Formulation::Constrained;
  s.loads.guide_normal_force = GuideNormalForce::Lagged;
  s.reduced.guide_normals = ReducedGuideNormals::QuasiStatic;
  return s;
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

// The formulation the multibody model runs in: the one named by ROLLERDYN_MULTIBODY_FORMULATION
// (constrained | minimal; tests/CMakeLists.txt runs this suite once more with minimal), else the
// scene's own. The one place that decides it: inFormulation() sets it on the run and
// Expect::of() picks the claims measured for it.
inline Formulation multibodyFormulation(const Scene& s) {
  const char* f = std::getenv("ROLLERDYN_MULTIBODY_FORMULATION");
  if (f && std::string(f) == "minimal") return Formulation::Minimal;
  if (f && std::string(f) == "constrained") return Formulation::Constrained;
  return s.simulation.formulation;
}

inline Scene inFormulation(Scene s) {
  s.simulation.formulation = multibodyFormulation(s);
  return s;
}

inline RunResult run(Model m, const Scene& s) {
  return m == Model::Multibody ? runMultibodyModel(inFormulation(s)) : runReducedModel(s);
}

// What a case expects of how the run ends, and the error constants it claims per model. The
// multibody model has its own constants per formulation (different integrators: Simbody's on
// the constrained equations, CVODE Adams on the independent coordinates, MinimalSimulation.h);
// of() picks those of the formulation the multibody run uses (multibodyFormulation, as run()).
struct Expect {
  bool complete = true;        // false: the run must end early (and say why in status)
  std::string status_prefix;   // e.g. "motor stalled at t = "; empty: not checked
  Claims multibody;            // multibody, constrained formulation (file comment)
  Claims multibody_minimal;    // multibody, minimal formulation; 0 = not measured, fails
  Claims reduced;              // reduced model
  // Agreement of the two models at accuracy a/10, max_t |x_multibody − x_reduced| relative to
  // W (crank speed) and M (coupling torque) as in the file comment; 0: not compared. The models
  // differ in physics only by the guide friction (dynamic vs quasi-static reactions), so the
  // measured agreement is that difference, and the claim is 3x it. At a/10 both formulations
  // are close enough to the exact solution that one claim serves both (measured per case).
  double models_speed = 0, models_torque = 0;
  const Claims& of(Model m, const Scene& s) const {
    if (m == Model::Reduced) return reduced;
    return multibodyFormulation(s) == Formulation::Minimal ? multibody_minimal : multibody;
  }
};

// Largest |a(t) − b(t)| of one column over the output rows the two tables share. Both runs
// sample the same grid (analysis/OutputGrid.h: 0, h, 2h, ...), so row i is the same t in both;
// a run that ended early (stall) is compared over the rows it has. Asserts the grids match.
inline double seriesDifference(const Table& a, const Table& b, const std::string& column) {
  const std::size_t n = std::min(a.rows.size(), b.rows.size());
  const int ta = a.index("t"), tb = b.index("t"), ca = a.index(column), cb = b.index(column);
  double d = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_NEAR(a.rows[i][ta], b.rows[i][tb], 1e-9) << "output grids differ at row " << i;
    d = std::max(d, std::abs(a.rows[i][ca] - b.rows[i][cb]));
  }
  return d;
}

// The runs of one model at a and a/10, for case-specific checks.
struct CasePair {
  RunResult at_a, at_a10;
};

// The checks of the file comment on a pair of runs (a and a/10) of one model. Returns both runs
// for case-specific checks.
inline CasePair checkCase(Model model, const Scene& scene, double a, const Expect& expect) {
  if (!modelSelected(name(model))) return {};
  const std::string who = std::string(name(model)) +
                          (model == Model::Multibody ? std::string(" (") + toString(multibodyFormulation(scene)) + ")" : "") +
                          " on " + scene.name;
  const Claims& claim = expect.of(model, scene);
  EXPECT_GT(claim.energy, 0.0) << who << ": no energy error constant claimed";
  EXPECT_GT(claim.speed, 0.0) << who << ": no speed error constant claimed";
  EXPECT_GT(claim.torque, 0.0) << who << ": no coupling-torque error constant claimed";
  a *= accuracyScale();
  CasePair p;
  RunResult &r1 = p.at_a, &r2 = p.at_a10;
  const Scene s1 = withAccuracy(scene, a), s2 = withAccuracy(scene, a / 10.0);
  EXPECT_NO_THROW(r1 = run(model, s1)) << who;
  EXPECT_NO_THROW(r2 = run(model, s2)) << who << " at a/10";
  for (const RunResult* r : {&r1, &r2}) {
    const std::string at = who + (r == &r1 ? " at a" : " at a/10");
    EXPECT_FALSE(r->timeseries.rows.empty()) << at;
    if (r->timeseries.rows.empty()) return p;
    EXPECT_TRUE(allFinite(r->timeseries)) << at << ": non-finite value in timeseries";
    EXPECT_TRUE(allFinite(r->reactions)) << at << ": non-finite value in reactions";
    EXPECT_EQ(r->stats.complete, expect.complete) << at << ": status " << r->stats.status;
    if (!expect.status_prefix.empty()) {
      EXPECT_EQ(r->stats.status.rfind(expect.status_prefix, 0), 0u)
          << at << ": status '" << r->stats.status << "' should start with '" << expect.status_prefix << "'";
    }
    const double acc = r == &r1 ? a : a / 10.0;
    if (model == Model::Multibody) {
      EXPECT_LE(r->stats.constraint_error_max, kConstraintFactor * acc) << at;
    }
    const Scene& s = r == &r1 ? s1 : s2;
    const double E = energyScale(s, *r), N = revolutions(*r);
    char cerr[64] = "constraint check: not applicable";
    if (model == Model::Multibody) std::snprintf(cerr, sizeof cerr, "cerr=%.2g", r->stats.constraint_error_max);
    std::printf("  %-9s %-20s a=%.0e steps=%-6ld revs=%-6.2f residual=%-10.3g J E=%-9.3g J residual/(a*E)=%-9.3g %s %s\n",
                name(model), scene.name.c_str(), acc, r->stats.steps, N, r->energy.residual(), E,
                r->energy.residual() / (acc * E), cerr, r->stats.status.c_str());
    EXPECT_LE(std::abs(r->energy.residual()), energyTolerance(acc, E, claim.energy))
        << at << ": energy residual " << r->energy.residual() << " J = " << r->energy.residual() / (acc * E)
        << "·a·E, claimed " << claim.energy << "·a·E (E = " << E << " J)";
  }
  // 4. tenfold tighter accuracy moves the time series by less than claimed.
  const double W = std::max(maxAbs(r2.timeseries, "omega_crank"), syncCrankSpeed(scene));
  const double M = maxAbs(r2.timeseries, "coupling_torque");
  const double dw = seriesDifference(r1.timeseries, r2.timeseries, "omega_crank");
  const double dM = seriesDifference(r1.timeseries, r2.timeseries, "coupling_torque");
  std::printf("  %-9s %-20s convergence a=%.0e: dw/(a*W)=%.3g (W=%.4g rad/s)  dM/(a*M)=%.3g (M=%.5g N*m)\n",
              name(model), scene.name.c_str(), a, dw / (a * W), W, dM / (a * M), M);
  EXPECT_LE(dw, claim.speed * a * W) << who << ": crank speed series moves by " << dw << " rad/s = "
                                     << dw / (a * W) << "·a·W at a/10, claimed " << claim.speed << "·a·W";
  EXPECT_LE(dM, claim.torque * a * M) << who << ": coupling torque series moves by " << dM << " N·m = "
                                      << dM / (a * M) << "·a·M at a/10, claimed " << claim.torque << "·a·M";
  return p;
}

// Both models through checkCase, then their agreement (Expect::models_speed/_torque) compared
// over the common output grid of the runs at a/10.
struct BothModels {
  CasePair multibody, reduced;
};
inline BothModels checkBothModels(const Scene& scene, double a, const Expect& expect) {
  BothModels b;
  b.multibody = checkCase(Model::Multibody, scene, a, expect);
  b.reduced = checkCase(Model::Reduced, scene, a, expect);
  const Table &m = b.multibody.at_a10.timeseries, &r = b.reduced.at_a10.timeseries;
  if (m.rows.empty() || r.rows.empty()) return b;
  const double W = std::max(maxAbs(m, "omega_crank"), syncCrankSpeed(scene));
  const double M = maxAbs(m, "coupling_torque");
  const double dw = seriesDifference(m, r, "omega_crank") / W, dM = seriesDifference(m, r, "coupling_torque") / M;
  const char* f = toString(multibodyFormulation(scene));
  std::printf("  models    %-20s agree at a/10 (multibody %s): max|dw|/W=%.3g  max|dM|/M=%.3g\n", scene.name.c_str(), f,
              dw, dM);
  if (expect.models_speed > 0)
    EXPECT_LE(dw, expect.models_speed) << scene.name << ": multibody (" << f << ") and reduced crank speeds differ by "
                                       << dw << " of W, claimed " << expect.models_speed;
  if (expect.models_torque > 0)
    EXPECT_LE(dM, expect.models_torque) << scene.name << ": multibody (" << f << ") and reduced coupling torques differ by "
                                        << dM << " of M, claimed " << expect.models_torque;
  return b;
}

}  // namespace rollerdyn::hardcases
