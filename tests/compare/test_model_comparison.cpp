// Tests of the comparison arithmetic (src/compare/ModelComparison.h) on hand-made tables whose
// differences are known exactly, and of the scene-derived list of modelling differences
// (src/compare/ModelDifferences.h). No simulation runs here (see tests/validation for those).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "compare/ModelComparison.h"
#include "compare/ModelDifferences.h"
#include "support/Loveikin2018Scene.h"

using namespace rollerdyn;

namespace {

bool hasTopic(const std::vector<ModelDifference>& d, const std::string& topic) {
  return std::any_of(d.begin(), d.end(), [&](const ModelDifference& x) { return x.topic == topic; });
}
const ModelDifference* topic(const std::vector<ModelDifference>& d, const std::string& t) {
  for (const auto& x : d)
    if (x.topic == t) return &x;
  return nullptr;
}

// A run on the grid t = 0, h, ..., t_end whose every column is a known function of t.
RunResult syntheticRun(const std::string& model, double h, double t_end, int carts, double omega_offset,
                       double torque_scale, double reaction_offset) {
  RunResult r;
  r.model = model;
  r.timeseries.columns = {"t", "phi_crank", "omega_crank", "eps_crank", "coupling_torque"};
  r.reactions.columns = {"t"};
  for (int j = 1; j <= carts; ++j)
    for (const char* n : {"N_front_", "N_rear_", "F_rod_"}) r.reactions.columns.push_back(n + std::to_string(j));
  const int n = int(std::round(t_end / h));
  for (int i = 0; i <= n; ++i) {
    const double t = i * h;
    // omega linear in t, so linear interpolation between rows is exact
    r.timeseries.rows.push_back({t, 10 * t + 0.5 * t * t, 10 + t + omega_offset, 1.0, torque_scale * (100 + 50 * t)});
    std::vector<double> row = {t};
    for (int j = 1; j <= carts; ++j) {
      row.push_back(1000 * j + 100 * t + reaction_offset);
      row.push_back(-500 * j + reaction_offset);
      row.push_back(2000 + reaction_offset);
    }
    r.reactions.rows.push_back(row);
  }
  r.stats.cpu_seconds = model == "multibody" ? 2.0 : 0.01;
  return r;
}

}  // namespace

TEST(DifferenceStats, HandComputedValues) {
  // d = a - b = (0, -0.5, 0, 0, 0) on t = 0, 0.25, ..., 1:
  //   max|d| = 0.5 at t = 0.25; max|a| = 2 -> max_rel = 0.25;
  //   ∫d² dt (trapezoids) = 2 · ½·(0 + 0.25)·0.25 = 0.0625 over T = 1 -> rms = 0.25.
  const std::vector<double> t = {0, 0.25, 0.5, 0.75, 1.0};
  const std::vector<double> a = {0, 1, 2, 1, 0};
  const std::vector<double> b = {0, 1.5, 2, 1, 0};
  const DifferenceStats s = differenceStats(t, a, b);
  EXPECT_DOUBLE_EQ(s.max_abs_diff, 0.5);
  EXPECT_DOUBLE_EQ(s.t_at_max, 0.25);
  EXPECT_DOUBLE_EQ(s.max_abs_a, 2.0);
  EXPECT_DOUBLE_EQ(s.max_rel_diff, 0.25);
  EXPECT_DOUBLE_EQ(s.rms_diff, 0.25);
  EXPECT_EQ(s.samples, 5u);
}

TEST(DifferenceStats, ZeroReferenceAndNonFinite) {
  const std::vector<double> t = {0, 1}, zero = {0, 0}, one = {0, 1};
  EXPECT_EQ(differenceStats(t, zero, zero).max_rel_diff, 0.0);  // both identically zero: no difference
  EXPECT_TRUE(std::isnan(differenceStats(t, zero, one).max_rel_diff));  // no scale to divide by
  EXPECT_TRUE(std::isnan(differenceStats(t, one, {0, NAN}).max_abs_diff));  // a NaN never looks clean
}

TEST(ResampleLinear, ExactAtNodesLinearBetweenNaNOutside) {
  const std::vector<double> ts = {0, 1, 2}, ys = {0, 10, 40};
  const std::vector<double> out = resampleLinear(ts, ys, {0, 0.5, 1, 1.5, 2, 2.5, -1});
  EXPECT_EQ(out[0], 0);
  EXPECT_DOUBLE_EQ(out[1], 5);
  EXPECT_EQ(out[2], 10);
  EXPECT_DOUBLE_EQ(out[3], 25);
  EXPECT_EQ(out[4], 40);
  EXPECT_TRUE(std::isnan(out[5]));
  EXPECT_TRUE(std::isnan(out[6]));
}

TEST(CompareRuns, KnownOffsetsOnDifferentGrids) {
  const Scene sc = test_scenes::loveikin2018Scene();
  // Multibody on a 0.1 s grid, reduced on a 0.05 s grid (a superset): ω differs by 0.01 rad/s,
  // the coupling torque by 2 %, every reaction by 5 N.
  const RunResult mb = syntheticRun("multibody", 0.1, 1.0, 4, 0.0, 1.0, 0.0);
  const RunResult red = syntheticRun("reduced", 0.05, 1.0, 4, 0.01, 0.98, 5.0);
  const ModelComparison c = compareRuns(sc, mb, red);
  EXPECT_EQ(c.rows, 11u);
  EXPECT_LT(c.grid_max_time_offset, 1e-12);
  const QuantityComparison* w = c.find("omega_crank");
  ASSERT_NE(w, nullptr);
  EXPECT_NEAR(w->stats.max_abs_diff, 0.01, 1e-12);
  EXPECT_NEAR(w->stats.rms_diff, 0.01, 1e-12);
  EXPECT_NEAR(w->stats.max_rel_diff, 0.01 / 11.0, 1e-12);  // max|ω_mb| = 11 at t = 1
  const QuantityComparison* m = c.find("coupling_torque");
  ASSERT_NE(m, nullptr);
  EXPECT_NEAR(m->stats.max_rel_diff, 0.02, 1e-12);  // 2 % everywhere, largest |a - b| where |a| is largest
  for (int j = 1; j <= 4; ++j)
    for (const char* n : {"N_front_", "N_rear_", "F_rod_"}) {
      const QuantityComparison* q = c.find(n + std::to_string(j));
      ASSERT_NE(q, nullptr) << n << j;
      EXPECT_NEAR(q->stats.max_abs_diff, 5.0, 1e-9);
      ASSERT_NE(c.findKinetostatic(n + std::to_string(j)), nullptr);
    }
  // comparison.csv columns: t, then <q>_multibody, <q>_reduced (+ _reduced_kinetostatic for reactions)
  ASSERT_GE(c.table.columns.size(), 5u);
  EXPECT_EQ(c.table.columns[0], "t");
  EXPECT_EQ(c.table.columns[1], "omega_crank_multibody");
  EXPECT_EQ(c.table.columns[2], "omega_crank_reduced");
  EXPECT_TRUE(c.table.has("F_rod_4_reduced_kinetostatic"));
  EXPECT_EQ(c.table.columns.size(), 1u + 2u * 2u + 12u * 3u);
  EXPECT_EQ(c.table.rows.size(), 11u);
}

TEST(CompareRuns, WithoutReactionsOnlyCrankSpeedAndCouplingTorque) {
  // simulation.reactions: false: the runs have no reactions table; the motion is compared alone.
  Scene sc = test_scenes::loveikin2018Scene();
  sc.simulation.reactions = false;
  RunResult mb = syntheticRun("multibody", 0.1, 1.0, 4, 0.0, 1.0, 0.0);
  RunResult red = syntheticRun("reduced", 0.05, 1.0, 4, 0.01, 0.98, 5.0);
  mb.reactions = red.reactions = Table{};
  const ModelComparison c = compareRuns(sc, mb, red);
  ASSERT_EQ(c.quantities.size(), 2u);
  EXPECT_NEAR(c.find("omega_crank")->stats.max_abs_diff, 0.01, 1e-12);
  EXPECT_NEAR(c.find("coupling_torque")->stats.max_rel_diff, 0.02, 1e-12);
  EXPECT_TRUE(c.kinetostatic.empty());
  EXPECT_EQ(c.table.columns.size(), 1u + 2u * 2u);
  EXPECT_NE(comparisonText(c).find("reactions      not computed"), std::string::npos);
}

TEST(CompareRuns, OnlyTheCommonSpanIsCompared) {
  // A multibody run that ended early (e.g. stalled) at t = 0.5: only t <= 0.5 is compared.
  const Scene sc = test_scenes::loveikin2018Scene();
  const RunResult mb = syntheticRun("multibody", 0.1, 0.5, 4, 0.0, 1.0, 0.0);
  const RunResult red = syntheticRun("reduced", 0.1, 1.0, 4, 0.0, 1.0, 0.0);
  const ModelComparison c = compareRuns(sc, mb, red);
  EXPECT_EQ(c.rows, 6u);
  EXPECT_NEAR(c.t_end, 0.5, 1e-12);
  EXPECT_EQ(c.find("omega_crank")->stats.max_abs_diff, 0.0);
}

TEST(ComparisonJson, ContractKeys) {
  const Scene sc = test_scenes::loveikin2018Scene();
  const ModelComparison c = compareRuns(sc, syntheticRun("multibody", 0.1, 1.0, 4, 0.0, 1.0, 0.0),
                                        syntheticRun("reduced", 0.1, 1.0, 4, 0.01, 1.0, 0.0));
  const nlohmann::json j = comparisonJson(c);
  for (const char* q : {"omega_crank", "coupling_torque", "N_front_1", "N_rear_4", "F_rod_2"})
    for (const char* k : {"max_abs_diff", "rms_diff", "max_rel_diff"}) {
      ASSERT_TRUE(j["quantities"].contains(q)) << q;
      EXPECT_TRUE(j["quantities"][q].contains(k)) << q << "." << k;
    }
  ASSERT_TRUE(j["differences"].is_array());
  EXPECT_FALSE(j["differences"].empty());
  EXPECT_TRUE(j["differences"][0].is_string());
  EXPECT_DOUBLE_EQ(j["speed"]["cpu_seconds_multibody"].get<double>(), 2.0);
  EXPECT_DOUBLE_EQ(j["speed"]["cpu_seconds_reduced"].get<double>(), 0.01);
  EXPECT_DOUBLE_EQ(j["speed"]["cpu_ratio_reduced_to_multibody"].get<double>(), 0.005);
  EXPECT_DOUBLE_EQ(j["speed"]["speedup_reduced_over_multibody"].get<double>(), 200.0);
}

TEST(ModelDifferences, QuasiStaticNormalsAndTheLaggedLawDifferInFrictionAndRods) {
  // Loveikin, Pochka, Romasevych (2018): distributed rods and guide friction f = 0.008, with the
  // papers' quasi-static guide normals in the reduced model and the lagged law of the constrained
  // formulation in the multibody model (not the defaults: the next test has those).
  Scene sc = test_scenes::loveikin2018Scene();
  sc.reduced.guide_normals = ReducedGuideNormals::QuasiStatic;
  sc.loads.guide_normal_force = GuideNormalForce::Lagged;
  sc.simulation.formulation = Formulation::Constrained;
  const auto d = modelDifferences(sc);
  EXPECT_TRUE(hasTopic(d, "reactions"));
  EXPECT_TRUE(hasTopic(d, "rod_inertia"));
  ASSERT_TRUE(hasTopic(d, "guide_friction"));
  EXPECT_TRUE(topic(d, "guide_friction")->affects_motion);
  // Distributed rods change the reactions only (exact kinetic energy in both models).
  EXPECT_FALSE(topic(d, "rod_inertia")->affects_motion);
  EXPECT_FALSE(hasTopic(d, "kinematics"));
  ASSERT_TRUE(hasTopic(d, "integrator"));
  EXPECT_TRUE(topic(d, "integrator")->numerical);
  EXPECT_FALSE(motionEquivalent(sc));
}

TEST(ModelDifferences, KinetostaticNormalsAndTheAlgebraicLawLeaveNoFrictionOrReactionDifference) {
  // The defaults of scene files: the same friction law and the same Newton equations in both.
  Scene sc = test_scenes::loveikin2018Scene();
  sc.reduced.guide_normals = ReducedGuideNormals::Kinetostatic;
  sc.loads.guide_normal_force = GuideNormalForce::Algebraic;
  sc.simulation.formulation = Formulation::Minimal;
  const auto d = modelDifferences(sc);
  EXPECT_FALSE(hasTopic(d, "reactions"));
  EXPECT_FALSE(hasTopic(d, "rod_inertia"));
  EXPECT_FALSE(hasTopic(d, "guide_friction"));
  EXPECT_TRUE(motionEquivalent(sc));
  bool named = false;
  for (const std::string& same : identicalPhysics(sc)) named = named || same.rfind("guide friction: f*", 0) == 0;
  EXPECT_TRUE(named);
  // The multibody lag is then the one difference, and it moves the motion.
  sc.loads.guide_normal_force = GuideNormalForce::Lagged;
  ASSERT_TRUE(hasTopic(modelDifferences(sc), "guide_friction"));
  EXPECT_TRUE(topic(modelDifferences(sc), "guide_friction")->affects_motion);
  EXPECT_FALSE(motionEquivalent(sc));
}

TEST(ModelDifferences, EquivalentSceneAndEachSwitch) {
  Scene sc = test_scenes::loveikin2018Scene();
  sc.rods.model = RodModel::Split;
  sc.loads.guide_friction = 0.0;
  EXPECT_TRUE(motionEquivalent(sc));
  EXPECT_FALSE(hasTopic(modelDifferences(sc), "guide_friction"));
  EXPECT_FALSE(hasTopic(modelDifferences(sc), "rod_inertia"));

  Scene truncated = sc;
  truncated.reduced.kinematics = KinematicsForm::Truncated;
  EXPECT_FALSE(motionEquivalent(truncated));
  ASSERT_TRUE(hasTopic(modelDifferences(truncated), "kinematics"));
  EXPECT_TRUE(topic(modelDifferences(truncated), "kinematics")->affects_motion);

  Scene baranov = sc;
  baranov.coupling.type = CouplingType::Rigid;
  baranov.reduced.integrator = ReducedIntegrator::Baranov;
  EXPECT_FALSE(motionEquivalent(baranov));
  EXPECT_FALSE(topic(modelDifferences(baranov), "integrator")->numerical);

  // The distributed rods alone keep the motion equivalent.
  Scene distributed = sc;
  distributed.rods.model = RodModel::Distributed;
  EXPECT_TRUE(motionEquivalent(distributed));
}

// The 6-cart trial at 90°: compare headlined "coupling_torque max_rel_diff 0.429" while δ, swing
// and RMS agreed to 0.1 %: the two models' cranks had drifted apart in phase over 20 s, and the
// difference was normalised by the start-up peak. Two runs of the SAME machine (coupling torque
// and speed the same functions of the crank angle) whose speeds differ by 5e-4 must show equal
// steady answers and shape, and the drift as a drift.
namespace {
rollerdyn::RunResult runOfSameMachine(double speed_factor) {
  rollerdyn::RunResult r;
  r.model = "synthetic";
  r.stats.complete = true;
  r.timeseries.columns = {"t", "phi_crank", "omega_crank", "coupling_torque"};
  auto omega = [&](double phi) { return speed_factor * (10.0 + 0.5 * std::sin(4 * phi)); };
  double phi = 0;
  const double dt = 0.005;
  for (int i = 0; i <= 4000; ++i) {
    r.timeseries.rows.push_back({i * dt, phi, omega(phi), 1000.0 * std::sin(4 * phi) + 200.0});
    const double k1 = omega(phi), k2 = omega(phi + 0.5 * dt * k1), k3 = omega(phi + 0.5 * dt * k2),
                 k4 = omega(phi + dt * k3);
    phi += dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  return r;
}
}  // namespace

TEST(CompareRuns, SteadyAnswersAndShapeHeadlineAndPhaseDriftIsSeparated) {
  rollerdyn::Scene s = rollerdyn::test_scenes::loveikin2018Scene();
  s.simulation.reactions = false;
  const rollerdyn::ModelComparison c = rollerdyn::compareRuns(s, runOfSameMachine(1.0), runOfSameMachine(1.0 + 5e-4));
  // Row by row at equal times the drift looks like a large difference ...
  ASSERT_NE(c.find("coupling_torque"), nullptr);
  EXPECT_GT(c.find("coupling_torque")->stats.max_rel_diff, 0.2);
  // ... while every steady answer agrees and the shape at the same crank angle is the same.
  for (const auto& m : c.steady)
    if (std::isfinite(m.multibody)) EXPECT_LT(std::abs(m.rel_diff), 2e-3) << m.name;
  ASSERT_EQ(c.shapes.size(), 2u);
  for (const auto& sh : c.shapes) EXPECT_LT(sh.rel_diff, 0.02) << sh.name;
  // The drift itself: 5e-4 of about 200 rad over 20 s, the multibody crank behind.
  EXPECT_NEAR(c.phase_drift, -5e-4 * (c.multibody.timeseries.rows.back()[1]), 0.01);
  const std::string text = rollerdyn::comparisonText(c);
  EXPECT_NE(text.find("steady running"), std::string::npos) << text;
  EXPECT_NE(text.find("phase drift"), std::string::npos) << text;
  // Behind in words, not "-0.1 rad ahead" (the trial's reading of a negative drift).
  EXPECT_NE(text.find("rad ("), std::string::npos) << text;
  EXPECT_NE(text.find("behind the reduced one"), std::string::npos) << text;
  EXPECT_EQ(text.find("crank is -"), std::string::npos) << text;
  EXPECT_LT(text.find("steady running"), text.find("row by row")) << text;  // the headline comes first
}
