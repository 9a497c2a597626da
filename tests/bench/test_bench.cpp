// The bench library (src/bench): error measure, medians, bounded runs (timeout and failure rows
// instead of hangs or exceptions), the recommendation rule and the CSV. No timing is asserted.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "bench/BenchRun.h"
#include "bench/BenchStudies.h"
#include "support/Loveikin2018Scene.h"

namespace rollerdyn::bench {
namespace {

Table table(std::vector<std::vector<double>> rows) {
  Table t;
  t.columns = {"t", "omega_crank"};
  t.rows = std::move(rows);
  return t;
}

TEST(BenchError, RelativeMaxErrorOverTheCommonGrid) {
  const Table ref = table({{0.0, 1.0}, {0.1, -4.0}, {0.2, 2.0}});
  const Table run = table({{0.0, 1.0}, {0.1, -3.8}, {0.2, 2.1}});
  // max |Δ| = 0.2 at t = 0.1, max |ref| = 4
  EXPECT_NEAR(relativeMaxError(run, ref, "omega_crank"), 0.05, 1e-14);
  // A run that stopped early is compared on the rows it has.
  const Table early = table({{0.0, 1.0}, {0.1, -4.4}});
  EXPECT_NEAR(relativeMaxError(early, ref, "omega_crank"), 0.1, 1e-14);
  // Rows at times the reference does not have are skipped, not interpolated.
  const Table offgrid = table({{0.05, 100.0}, {0.2, 2.4}});
  EXPECT_NEAR(relativeMaxError(offgrid, ref, "omega_crank"), 0.1, 1e-14);
  EXPECT_DOUBLE_EQ(relativeMaxError(ref, ref, "omega_crank"), 0.0);
}

TEST(BenchError, UndefinedCasesAreNaN) {
  const Table ref = table({{0.0, 0.0}, {0.1, 0.0}});
  EXPECT_TRUE(std::isnan(relativeMaxError(ref, ref, "omega_crank")));  // zero reference
  EXPECT_TRUE(std::isnan(relativeMaxError(table({{0.0, 1.0}}), table({{0.0, 1.0}}), "coupling_torque")));
  EXPECT_TRUE(std::isnan(relativeMaxError(table({{0.3, 1.0}}), table({{0.0, 1.0}}), "omega_crank")));
  EXPECT_TRUE(std::isnan(relativeMaxError(table({{0.0, NAN}}), table({{0.0, 1.0}}), "omega_crank")));
}

TEST(BenchError, Median) {
  EXPECT_DOUBLE_EQ(median({3.0, 1.0, 2.0}), 2.0);
  EXPECT_DOUBLE_EQ(median({4.0, 1.0, 2.0, 3.0}), 2.5);
  EXPECT_TRUE(std::isnan(median({})));
}

Scene shortScene() {
  Scene s = test_scenes::loveikin2018Scene();
  s.simulation.t_end = 0.05;
  return s;
}

TEST(BenchRun, ApplySettingSetsAccuracyAndConstraintTolerance) {
  const Scene s = applySetting(shortScene(), {"multibody", "RungeKutta3", 1e-4, 0});
  EXPECT_EQ(s.simulation.integrator, "RungeKutta3");
  EXPECT_EQ(s.simulation.accuracy, 1e-4);
  EXPECT_EQ(s.simulation.constraint_tolerance, 1e-4);
  const Scene b = applySetting(shortScene(), {"reduced", "baranov", 0, 0.01});
  EXPECT_EQ(b.reduced.integrator, ReducedIntegrator::Baranov);
  EXPECT_EQ(b.reduced.baranov_step, 0.01);
  EXPECT_THROW(applySetting(shortScene(), {"reduced", "rk4", 1e-6, 0}), std::invalid_argument);
}

TEST(BenchRun, ApplySettingSelectsTheMultibodyFormulation) {
  Scene minimal_default = shortScene();
  minimal_default.simulation.formulation = Formulation::Minimal;
  // "multibody" is the constrained formulation whatever the scene says.
  EXPECT_EQ(applySetting(minimal_default, {"multibody", "RungeKutta3", 1e-4, 0}).simulation.formulation,
            Formulation::Constrained);
  const Scene m = applySetting(shortScene(), {kMultibodyMinimal, kMinimalIntegrator, 1e-5, 0});
  EXPECT_EQ(m.simulation.formulation, Formulation::Minimal);
  EXPECT_EQ(m.simulation.accuracy, 1e-5);
  EXPECT_EQ(m.simulation.constraint_tolerance, 1e-5);
  // The minimal formulation has one integrator; any other name is an error, not ignored.
  EXPECT_THROW(applySetting(shortScene(), {kMultibodyMinimal, "RungeKuttaMerson", 1e-6, 0}), std::invalid_argument);
}

TEST(BenchRun, BothModelsMeasured) {
  for (const SolverSetting& set : {SolverSetting{"multibody", "RungeKuttaMerson", 1e-6, 0},
                                   SolverSetting{kMultibodyMinimal, kMinimalIntegrator, 1e-6, 0},
                                   SolverSetting{"reduced", "cvode", 1e-6, 0}}) {
    const Measurement m = measure(shortScene(), set, Budget{60.0, nullptr}, 2);
    EXPECT_EQ(m.outcome, Outcome::Ok) << set.label() << ": " << m.status;
    EXPECT_EQ(m.repeats, 2);
    EXPECT_NEAR(m.simulated_time, 0.05, 1e-12);
    EXPECT_GT(m.steps, 0);
    EXPECT_GT(m.realizations, 0);
    EXPECT_LE(m.cpu_min, m.cpu_seconds);
    EXPECT_LE(m.cpu_seconds, m.cpu_max);
    EXPECT_FALSE(m.run.timeseries.rows.empty());
  }
}

TEST(BenchRun, ExhaustedBudgetIsATimeoutRowNotAHang) {
  // A budget of 0 s is exceeded at the first progress callback: the run stops after one output
  // interval and is reported as a timeout, with the time reached.
  Scene s = shortScene();
  s.simulation.t_end = 10.0;
  const Measurement m = measure(s, {"multibody", "RungeKuttaMerson", 1e-6, 0}, Budget{0.0, nullptr}, 3);
  EXPECT_EQ(m.outcome, Outcome::Timeout);
  EXPECT_NE(m.status.find("timeout: CPU budget"), std::string::npos) << m.status;
  EXPECT_EQ(m.repeats, 1);  // a timeout is not repeated
  EXPECT_LT(m.simulated_time, 1.0);
}

TEST(BenchRun, RunStuckInsideOneOutputIntervalIsStoppedByTheHardLimit) {
  // One output interval spanning the whole run: the progress callback never comes, so only the
  // child process's CPU limit (1.5·budget + 2 s, here 2 s) can stop ExplicitEuler at 1e-10.
  Scene s = shortScene();
  s.simulation.t_end = 10.0;
  s.simulation.output_step = 10.0;
  const Measurement m = measure(s, {"multibody", "ExplicitEuler", 1e-10, 0}, Budget{1e-3, nullptr}, 1);
  EXPECT_EQ(m.outcome, Outcome::Timeout);
  EXPECT_NE(m.status.find("hard CPU limit"), std::string::npos) << m.status;
}

TEST(BenchRun, InvalidSettingIsAFailedRowNotAnException) {
  Measurement m;
  EXPECT_NO_THROW(m = measure(shortScene(), {"multibody", "NoSuchIntegrator", 1e-6, 0}, Budget{}, 1));
  EXPECT_EQ(m.outcome, Outcome::Failed);
  EXPECT_NE(m.status.find("NoSuchIntegrator"), std::string::npos) << m.status;
  // Baranov needs a rigid coupling; the Loveikin, Pochka, Romasevych (2018) scene is elastic.
  EXPECT_NO_THROW(m = measure(shortScene(), {"reduced", "baranov", 0, 0.01}, Budget{}, 1));
  EXPECT_EQ(m.outcome, Outcome::Failed);
}

TEST(BenchRun, InterruptIsReported) {
  const std::atomic<bool> stop{true};
  const Measurement m = measure(shortScene(), {"multibody", "RungeKuttaMerson", 1e-6, 0}, Budget{60.0, &stop}, 1);
  EXPECT_EQ(m.outcome, Outcome::Interrupted);
}

BenchRow row(const std::string& model, const std::string& integ, double acc, Outcome o, double cpu, double ew,
             double ec, bool ref = false) {
  BenchRow r;
  r.study = "integrators";
  r.m.setting = {model, integ, acc, 0};
  r.m.outcome = o;
  r.m.cpu_seconds = cpu;
  r.error_omega = ew;
  r.error_coupling = ec;
  r.reference = ref;
  r.carts = 4;
  return r;
}

TEST(BenchStudies, CheapestRunReachingATarget) {
  const std::vector<BenchRow> rows = {
      row("multibody", "RungeKuttaMerson", 1e-10, Outcome::Ok, 0.01, 0, 0, true),  // reference: never picked
      row("multibody", "RungeKuttaMerson", 1e-6, Outcome::Ok, 2.0, 5e-7, 5e-6),
      row("multibody", "RungeKutta3", 1e-6, Outcome::Ok, 1.0, 2e-6, 1e-5),
      row("multibody", "RungeKutta3", 1e-7, Outcome::Ok, 1.5, 4e-7, 2e-6),
      row("multibody", "ExplicitEuler", 1e-6, Outcome::Timeout, 0.1, NAN, NAN),
      row("reduced", "cvode", 1e-6, Outcome::Ok, 0.001, 1e-7, 1e-6)};
  const BenchRow* r = cheapestReaching(rows, "multibody", 1e-6, false);
  ASSERT_NE(r, nullptr);
  EXPECT_EQ(r->m.setting.integrator, "RungeKutta3");
  EXPECT_EQ(r->m.setting.accuracy, 1e-7);
  EXPECT_EQ(cheapestReaching(rows, "multibody", 1e-6, true), nullptr);  // coupling never ≤ 1e-6
  r = cheapestReaching(rows, "multibody", 1e-5, true);
  ASSERT_NE(r, nullptr);
  EXPECT_EQ(r->m.setting.integrator, "RungeKutta3");
  EXPECT_EQ(r->m.setting.accuracy, 1e-6);
  EXPECT_EQ(cheapestReaching(rows, "reduced", 1e-8, false), nullptr);
}

TEST(BenchStudies, CsvHasTheRequiredColumnsAndEmptyFieldsForNaN) {
  std::vector<BenchRow> rows = {row("multibody", "ExplicitEuler", 1e-10, Outcome::Timeout, NAN, NAN, NAN)};
  rows[0].m.status = "timeout: CPU budget 20 s exceeded, \"quoted\"";
  const std::string csv = rowsCsv(rows);
  std::istringstream in(csv);
  std::string header, line;
  std::getline(in, header);
  std::getline(in, line);
  for (const char* c : {"model", "integrator", "accuracy", "cpu_seconds", "steps", "realizations", "error_omega",
                        "error_coupling", "outcome", "status", "error_angle_rad", "cpu_with_setup"})
    EXPECT_NE(header.find(c), std::string::npos) << c;
  EXPECT_NE(line.find("multibody,ExplicitEuler,1e-10,"), std::string::npos) << line;
  EXPECT_NE(line.find(",timeout,\"timeout: CPU budget 20 s exceeded, \"\"quoted\"\"\","), std::string::npos) << line;
  EXPECT_EQ(line.find("nan"), std::string::npos) << line;
}

TEST(BenchStudies, CheapestRunReachingACrankAngleError) {
  std::vector<BenchRow> rows = {row("multibody-minimal", "cvode-adams", 1e-4, Outcome::Ok, 0.05, 1e-5, 1e-4),
                                row("multibody-minimal", "cvode-adams", 1e-5, Outcome::Ok, 0.06, 1e-6, 1e-5),
                                row("multibody-minimal", "cvode-adams", 1e-6, Outcome::Ok, 0.08, 4e-7, 1e-6)};
  rows[0].error_angle = 7.7e-5;
  rows[1].error_angle = 1.4e-6;
  rows[2].error_angle = 5.6e-7;
  const BenchRow* r = cheapestReachingAngle(rows, "multibody-minimal", 1e-5);
  ASSERT_NE(r, nullptr);
  EXPECT_EQ(r->m.setting.accuracy, 1e-5);
  EXPECT_EQ(cheapestReachingAngle(rows, "multibody-minimal", 1e-7), nullptr);
}

TEST(BenchStudies, ReactionsStudyTimesEachAccuracyWithAndWithout) {
  BenchOptions opt;
  opt.quick = true;
  opt.budget = 5;
  const SceneSource source{std::string(ROLLERDYN_SOURCE_DIR) + "/model/balanced-4cart.yaml", {"simulation.t_end=0.2"}};
  const std::vector<BenchRow> rows = runReactionsStudy(source, opt);
  ASSERT_EQ(rows.size(), 2 * accuracyGrid(true).size());  // the quick grid ends at 1e-8
  for (size_t i = 0; i < rows.size(); i += 2) {
    EXPECT_EQ(rows[i].variant, "reactions");
    EXPECT_EQ(rows[i + 1].variant, "no reactions");
    EXPECT_EQ(rows[i].x, rows[i + 1].x);
    EXPECT_EQ(rows[i].m.outcome, Outcome::Ok) << rows[i].m.status;
    EXPECT_EQ(rows[i + 1].m.outcome, Outcome::Ok) << rows[i + 1].m.status;
    // Same integration (the rows never feed back): the same steps.
    EXPECT_EQ(rows[i].m.steps, rows[i + 1].m.steps);
  }
}

TEST(BenchStudies, Grids) {
  const auto g = accuracyGrid(false);
  ASSERT_EQ(g.size(), 17u);
  EXPECT_DOUBLE_EQ(g.front(), 1e-2);
  EXPECT_DOUBLE_EQ(g[1], 3e-3);
  for (std::size_t i = 1; i < g.size(); ++i) EXPECT_LT(g[i], g[i - 1]) << i;
  EXPECT_DOUBLE_EQ(g.back(), 1e-10);
  EXPECT_LT(accuracyGrid(true).size(), g.size());
  // The reference's own error (~its accuracy) must vanish beside the 1e-6 error the bench judges
  // runs against: three orders below it, and no looser than the finest grid point.
  EXPECT_LE(kReferenceAccuracy, 1e-6 / 1000);
  EXPECT_LE(kReferenceAccuracy, g.back());
  EXPECT_NEAR(baranovSteps(false).front(), 8 * M_PI / 180, 1e-15);
}

}  // namespace
}  // namespace rollerdyn::bench
