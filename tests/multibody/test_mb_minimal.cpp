// The minimal formulation of the multibody model (simulation.formulation = minimal) against the
// constrained one: the same Simbody model integrated two different ways must give the same
// motion and reactions. The expected values come from the OTHER formulation (Simbody's
// constrained solve with its own Runge-Kutta-Merson integration), never from the code under
// test. Plus unit tests of the two building blocks: MinimalCoordinates (the closed-form map
// satisfies Simbody's position, velocity and acceleration constraints) and MinimalDynamics (its
// accelerations and guide normal forces equal Simbody's constrained solve at arbitrary states).
//
// Time span: 1 s of each scene instead of its 5-10 s. From rest the first second holds the
// whole start-up (the motor's breakdown region, the crank passing every dead centre at changing
// speed, each cart reversing 2-3 times, guide-friction normal forces switching sign, the
// coupling's torsional transient at its largest), i.e. every term of the equations at its
// largest; the later steady revolutions repeat the same states. The constrained formulation at
// accuracy 1e-10 costs ~1.3 s of CPU per simulated second, so 1 s keeps this file near a minute.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "multibody/MinimalCoordinates.h"
#include "multibody/MinimalDynamics.h"
#include "multibody/MultibodyModel.h"
#include "multibody/MultibodySimulation.h"
#include "scene/SceneParser.h"

namespace rollerdyn {
namespace {

std::string scenePath(const std::string& name) { return std::string(ROLLERDYN_SOURCE_DIR) + "/model/" + name; }

// The lagged guide-friction law: the one both formulations can run (the algebraic law needs the
// minimal formulation; its own tests are in test_mb_algebraic_friction.cpp). Later overrides win.
Scene shortScene(const std::string& file, std::vector<std::string> overrides = {}) {
  overrides.insert(overrides.begin(), "loads.guide_friction.normal_force=lagged");
  overrides.push_back("simulation.t_end=1.0");
  overrides.push_back("simulation.accuracy=1e-10");
  return parseSceneFile(scenePath(file), overrides);
}

// max_i |a_i - b_i| / max_i |a_i| over the rows both tables share.
double relDiff(const Table& a, const Table& b, const std::string& column) {
  const int ia = a.index(column), ib = b.index(column);
  const size_t n = std::min(a.rows.size(), b.rows.size());
  double d = 0, scale = 0;
  for (size_t k = 0; k < n; ++k) {
    d = std::max(d, std::abs(a.rows[k][ia] - b.rows[k][ib]));
    scale = std::max(scale, std::abs(a.rows[k][ia]));
  }
  return scale > 0 ? d / scale : d;
}

struct Pair {
  RunResult constrained, minimal;
};

// constrained_accuracy: accuracy of the constrained run when it must be tighter than the
// scene's (0: the scene's).
Pair runBoth(Scene sc, const MultibodyOptions& options = {}, double constrained_accuracy = 0) {
  Pair p;
  Scene sc_constrained = sc;
  if (constrained_accuracy > 0) sc_constrained.simulation.accuracy = constrained_accuracy;
  sc_constrained.simulation.formulation = Formulation::Constrained;
  {
    const MultibodyModel m(sc_constrained, options);
    p.constrained = simulateMultibody(m);
  }
  sc.simulation.formulation = Formulation::Minimal;
  {
    const MultibodyModel m(sc, options);
    p.minimal = simulateMultibody(m);
  }
  return p;
}

void expectAgreement(const Pair& p, const std::string& what) {
  SCOPED_TRACE(what);
  ASSERT_TRUE(p.constrained.stats.complete) << p.constrained.stats.status;
  ASSERT_TRUE(p.minimal.stats.complete) << p.minimal.stats.status;
  ASSERT_EQ(p.constrained.timeseries.rows.size(), p.minimal.timeseries.rows.size());
  ASSERT_EQ(p.constrained.reactions.columns, p.minimal.reactions.columns);
  EXPECT_LE(relDiff(p.constrained.timeseries, p.minimal.timeseries, "omega_crank"), 1e-8);
  EXPECT_LE(relDiff(p.constrained.timeseries, p.minimal.timeseries, "coupling_torque"), 1e-8);
  for (const std::string& c : p.constrained.reactions.columns) {
    if (c == "t") continue;
    EXPECT_LE(relDiff(p.constrained.reactions, p.minimal.reactions, c), 1e-7) << c;
  }
  // Each cart stays on its side of the shaft: σ·x_B > 0 in every row.
  const Table& ts = p.minimal.timeseries;
  for (int j = 1; ts.has("x_cart_" + std::to_string(j)); ++j) {
    const int c = ts.index("x_cart_" + std::to_string(j));
    const double sign = p.constrained.timeseries.rows.front()[c] > 0 ? 1.0 : -1.0;
    for (const auto& row : ts.rows) ASSERT_GT(sign * row[c], 0.0) << "cart " << j;
  }
  // The built-in self-check: the projected accelerations and guide normal forces equal
  // Simbody's constrained solve at every output row to round-off.
  EXPECT_GE(p.minimal.stats.formulation_self_check, 0.0);
  EXPECT_LT(p.minimal.stats.formulation_self_check, 1e-11);
  EXPECT_LT(p.constrained.stats.formulation_self_check, 0.0);  // not run: "not measured"
}

TEST(MultibodyMinimal, AgreesOnShippedScenes) {
  for (const char* file : {"balanced-4cart.yaml", "recuperative-2cart.yaml", "energy-balanced-3cart.yaml",
                           "cam-drive.yaml"})
    expectAgreement(runBoth(shortScene(file)), file);
}

TEST(MultibodyMinimal, AgreesForEveryRodModelAndCoupling) {
  expectAgreement(runBoth(shortScene("balanced-4cart.yaml", {"rods.model=split"})), "split rods");
  // Massless rods leave the crankshaft without inertia of its own: give it some.
  expectAgreement(runBoth(shortScene("balanced-4cart.yaml", {"rods.model=massless", "crank.shaft_inertia=2"})),
                  "massless rods");
  expectAgreement(runBoth(shortScene("balanced-4cart.yaml", {"coupling.type=rigid"})), "rigid coupling");
  // Without gravity the constrained formulation at 1e-10 is itself 1.9e-8 off in coupling torque
  // (against its own run at 1e-11; the minimal run at 1e-10 is 2.4e-9 off that run), so the
  // reference runs at 1e-11 here.
  expectAgreement(runBoth(shortScene("recuperative-2cart.yaml", {"loads.gravity=0"}), {}, 1e-11), "no gravity");
  expectAgreement(runBoth(shortScene("recuperative-2cart.yaml",
                                     {"loads.roller_force_direction=opposes_velocity"})),
                  "roller forces opposing the velocity");
}

TEST(MultibodyMinimal, AgreesWithFlywheelOnEitherShaft) {
  for (const char* where : {"crankshaft", "motor_shaft"})
    expectAgreement(runBoth(shortScene("balanced-4cart.yaml",
                                       {"flywheel.inertia=20", std::string("flywheel.location=") + where})),
                    where);
}

TEST(MultibodyMinimal, AgreesWithMotorOffAndPrescribedSpeed) {
  // Motor off: a free-running machine from 8 rad/s (the carts slow it down).
  expectAgreement(runBoth(shortScene("balanced-4cart.yaml", {"motor.enabled=false", "initial.crank_speed=8"})),
                  "motor off");
  // Prescribed crank speed (rigid: nothing left to integrate but the auxiliary states; elastic:
  // the motor side still twists).
  MultibodyOptions prescribed;
  prescribed.prescribe_crank_speed = true;
  prescribed.crank_speed = 10.0;
  expectAgreement(runBoth(shortScene("recuperative-2cart.yaml", {"motor.enabled=false", "initial.crank_speed=10"}),
                          prescribed),
                  "prescribed speed, rigid");
  expectAgreement(runBoth(shortScene("balanced-4cart.yaml", {"initial.crank_speed=10"}), prescribed),
                  "prescribed speed, elastic");
}

// The closed-form map satisfies Simbody's own constraints at every level, for both sides and
// all loop types, at arbitrary (non-physical) states.
TEST(MinimalCoordinates, SatisfiesSimbodyConstraints) {
  for (const char* rods : {"distributed", "split", "massless", "cam"}) {
    {
      const char* drive = std::string(rods) == "cam" ? "cam" : "crank";
      const Scene sc = std::string(rods) == "cam"
                           ? shortScene("cam-drive.yaml")
                           : shortScene("balanced-4cart.yaml", {std::string("rods.model=") + rods, "crank.shaft_inertia=2"});
      const MultibodyModel model(sc);
      SimTK::State s = model.initialState();
      MinimalCoordinates coords(model, s);
      for (double phi : {0.3, 1.7, 4.0, -2.2}) {
        IndependentState x;
        x.crank_angle = phi;
        x.crank_speed = 9.0 - phi;
        x.twist = 1e-4;
        x.twist_rate = -2e-3;
        coords.apply(0.0, x, s);
        // udot = N·ν̈ + Ṅ·ν̇ with an arbitrary ν̈: must satisfy the acceleration constraints.
        SimTK::Vector udot = coords.bias();
        for (int c = 0; c < coords.freeSpeeds(); ++c) udot += (3.0 + c) * coords.column(c);
        model.system().realize(s, SimTK::Stage::Velocity);
        SimTK::Vector aerr;
        model.matter().calcConstraintAccelerationErrors(s, udot, aerr);
        const std::string at = std::string(rods) + " " + drive + " phi=" + std::to_string(phi);
        EXPECT_LT(SimTK::max(SimTK::abs(s.getQErr())), 1e-13) << at;
        EXPECT_LT(SimTK::max(SimTK::abs(s.getUErr())), 1e-12) << at;
        EXPECT_LT(SimTK::max(SimTK::abs(aerr)), 1e-10) << at;
        const IndependentState back = coords.extract(s);
        EXPECT_EQ(back.crank_angle, phi);
        EXPECT_EQ(back.crank_speed, x.crank_speed);
      }
    }
  }
}

// MinimalDynamics' accelerations and guide normal forces equal Simbody's constrained solve
// (realize Acceleration, calcMobilizerReactionForces) at arbitrary states, with friction on.
// The applied forces MinimalDynamics sums without realizing Dynamics are Simbody's own sums at
// Dynamics stage, term for term (same elements, same order): equal to the last bit. Motor,
// elastic coupling with damping, gravity, roller loads and guide friction (non-zero lagged normal
// forces) all act.
TEST(MultibodyModel, AppliedForcesEqualSimbodysDynamicsStageSums) {
  const Scene sc = shortScene("balanced-4cart.yaml", {"loads.guide_friction.coefficient=0.1"});
  const MultibodyModel model(sc);
  ASSERT_TRUE(model.hasGuideFriction());
  SimTK::State s = model.assembledState(2.5, 7.0, 2e-4);
  SimTK::Vector& z = model.forces().updZ(s);
  for (int i = 0; i < z.size(); ++i) z[i] = 1000.0 * (i + 1) * (i % 2 ? -1 : 1);
  model.system().realize(s, SimTK::Stage::Dynamics);
  const SimTK::SimbodyMatterSubsystem& matter = model.matter();
  SimTK::Vector_<SimTK::SpatialVec> body(matter.getNumBodies(), SimTK::SpatialVec(SimTK::Vec3(0), SimTK::Vec3(0)));
  SimTK::Vector_<SimTK::Vec3> particle(matter.getNumParticles(), SimTK::Vec3(0));
  SimTK::Vector mobility(s.getNU(), 0.0);
  model.addAppliedForces(s, body, particle, mobility);
  const SimTK::Vector_<SimTK::SpatialVec>& body_ref = model.system().getRigidBodyForces(s, SimTK::Stage::Dynamics);
  const SimTK::Vector& mobility_ref = model.system().getMobilityForces(s, SimTK::Stage::Dynamics);
  double largest = 0;
  for (int b = 0; b < body.size(); ++b)
    for (int k = 0; k < 2; ++k)
      for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(body[b][k][c], body_ref[b][k][c]) << "body " << b << " part " << k << " axis " << c;
        largest = std::max(largest, std::abs(body_ref[b][k][c]));
      }
  for (int i = 0; i < mobility.size(); ++i) {
    EXPECT_EQ(mobility[i], mobility_ref[i]) << "mobility " << i;
    largest = std::max(largest, std::abs(mobility_ref[i]));
  }
  EXPECT_GT(largest, 1000.0);  // the comparison is not between zeros
}

// Both guide-friction laws: with the algebraic one, Simbody's constrained solve sees the friction
// of the loop's normal forces, so its reactions must return those normal forces (the loop's
// fixed point, checked by Simbody's own solve).
TEST(MinimalDynamics, MatchesSimbodyConstrainedSolve) {
  for (const char* law : {"lagged", "algebraic"})
  for (const char* rods : {"distributed", "split", "massless", "cam"}) {
    const std::string normal_force = std::string("loads.guide_friction.normal_force=") + law;
    const Scene sc = std::string(rods) == "cam"
                         ? shortScene("cam-drive.yaml", {"loads.guide_friction.coefficient=0.1", normal_force})
                         : shortScene("balanced-4cart.yaml", {std::string("rods.model=") + rods, "crank.shaft_inertia=2",
                                                              "loads.guide_friction.coefficient=0.1", normal_force});
    SCOPED_TRACE(law);
    const MultibodyModel model(sc);
    SimTK::State s = model.initialState();
    MinimalCoordinates coords(model, s);
    MinimalDynamics dyn(model, s);
    for (double phi : {0.2, 2.5, 5.1}) {
      IndependentState x;
      x.crank_angle = phi;
      x.crank_speed = 7.0;
      x.twist = 2e-4;
      x.twist_rate = 1e-3;
      coords.apply(0.0, x, s);
      ASSERT_TRUE(dyn.evaluate(s, coords));
      const SimTK::Vector udot = dyn.udot();
      const SimTK::Vector normals = dyn.guideNormals(s);
      model.system().realize(s, SimTK::Stage::Acceleration);
      const SimTK::Vector& udot_ref = s.getUDot();
      const double scale = SimTK::max(SimTK::abs(udot_ref));
      EXPECT_LT(SimTK::max(SimTK::abs(udot - udot_ref)) / scale, 1e-12) << rods << " phi=" << phi;
      std::vector<double> ts, re;
      model.observe(s, ts, re);
      for (int j = 0; j < sc.carts.count; ++j) {
        EXPECT_NEAR(normals[2 * j], re[1 + 6 * j], 1e-9 * std::abs(re[1 + 6 * j]) + 1e-6) << rods << " cart " << j;
        EXPECT_NEAR(normals[2 * j + 1], re[2 + 6 * j], 1e-9 * std::abs(re[2 + 6 * j]) + 1e-6) << rods << " cart " << j;
      }
    }
  }
}

}  // namespace
}  // namespace rollerdyn
