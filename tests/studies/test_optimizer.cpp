// Design optimization (src/studies/Optimizer.h) against sweeps computed here, and its errors.
#include <gtest/gtest.h>

#include <cmath>

#include "cli/CliTestSupport.h"
#include "studies/Optimizer.h"

namespace rollerdyn {
namespace {

using test::model;

// Loveikin and Pochka (2007): the crank offset Δφ of the two-cart recuperative drive that
// minimises δ (eq. (12)). Reference: a 10° sweep and the vertex of the parabola through its best
// point and the two neighbours, computed here in closed form. BOBYQA must land within 0.5° of
// it with fewer runs than that sweep (19).
TEST(Optimizer, TwoCartOffsetOptimumAgreesWithTheSweepParabola) {
  SweepOptions s;
  s.scene_path = model("recuperative-2cart.yaml");
  s.params = {parseSweepValues("crank.offset_deg", "0:180:10")};
  s.model = "reduced";
  const SweepResult sweep = runSweep(s);
  ASSERT_EQ(sweep.points.size(), 19u);
  std::size_t b = 0;
  for (std::size_t i = 0; i < sweep.points.size(); ++i) {
    ASSERT_TRUE(sweep.points[i].complete && sweep.points[i].steady) << i;
    if (sweep.points[i].metric("delta") < sweep.points[b].metric("delta")) b = i;
  }
  ASSERT_GT(b, 0u);
  ASSERT_LT(b, 18u);
  // Vertex of the parabola through three equally spaced points (spacing h): x_b + h(y0 − y2)/(2(y0 − 2y1 + y2)).
  const double h = 10.0, y0 = sweep.points[b - 1].metric("delta"), y1 = sweep.points[b].metric("delta"),
               y2 = sweep.points[b + 1].metric("delta");
  const double vertex = sweep.points[b].values[0] + h * (y0 - y2) / (2.0 * (y0 - 2.0 * y1 + y2));

  OptimizeOptions o;
  o.scene_path = s.scene_path;
  o.params = {{"crank.offset_deg", 0.0, 180.0}};
  o.model = "reduced";
  o.minimize = "delta";
  o.method = "bobyqa";  // the local method alone: its cost against the sweep's
  const OptimizeResult r = runOptimize(o);
  EXPECT_EQ(r.method, "bobyqa");
  EXPECT_NE(r.scope.find("local"), std::string::npos);
  ASSERT_TRUE(r.found) << r.stop_reason;
  const OptimizeEvaluation& best = r.history[r.best];
  EXPECT_NEAR(best.x[0], vertex, 0.5) << "sweep best " << sweep.points[b].values[0];
  EXPECT_LT(r.history.size(), 19u);
  EXPECT_LE(best.objective, y1);  // at least as good as the best grid point
  EXPECT_EQ(best.objective, best.point.metric("delta"));

  // Two BOBYQA searches side by side on two threads (multistart) find the same optimum.
  o.method = "multistart";
  o.threads = 2;
  o.max_evals = 40;
  const OptimizeResult m = runOptimize(o);
  EXPECT_EQ(m.method, "multistart bobyqa x2");
  ASSERT_TRUE(m.found) << m.stop_reason;
  EXPECT_NEAR(m.history[m.best].x[0], vertex, 0.5);
  EXPECT_LE(m.history.size(), 40u);
}

// The flywheel that brings the energy-balanced three-cart drive to δ = 0.05: minimise its
// inertia subject to δ ≤ 0.05 (COBYLA). Reference: a 5 kg·m² sweep done here. δ falls with the
// inertia over the sweep (checked), so the smallest feasible inertia lies in the bracket
// (I_k, I_k+1] where δ crosses 0.05: the optimum must be feasible, above I_k (every smaller
// inertia violates δ ≤ 0.05) and at most I_k+1 plus COBYLA's stopping step (1e-3 of the 400
// kg·m² range = 0.4 kg·m²) — it cannot do worse than the feasible grid point by more than that.
TEST(Optimizer, ThreeCartFlywheelForDelta005AgreesWithAFineSweep) {
  SweepOptions s;
  s.scene_path = model("energy-balanced-3cart.yaml");
  s.params = {parseSweepValues("flywheel.inertia", "100:250:5")};
  s.model = "reduced";
  const SweepResult sweep = runSweep(s);
  std::size_t k = sweep.points.size();
  for (std::size_t i = 0; i < sweep.points.size(); ++i) {
    ASSERT_TRUE(sweep.points[i].complete && sweep.points[i].steady) << i;
    if (i > 0) ASSERT_LT(sweep.points[i].metric("delta"), sweep.points[i - 1].metric("delta")) << i;
    if (k == sweep.points.size() && sweep.points[i].metric("delta") <= 0.05) k = i;
  }
  ASSERT_GT(k, 0u);
  ASSERT_LT(k, sweep.points.size());
  const double lower = sweep.points[k - 1].values[0], upper = sweep.points[k].values[0];

  OptimizeOptions o;
  o.scene_path = s.scene_path;
  o.params = {{"flywheel.inertia", 0.0, 400.0}};
  o.model = "reduced";
  o.minimize = "flywheel.inertia";
  o.constraints = {parseConstraint("delta<=0.05")};
  o.method = "cobyla";  // the local method alone: its cost against the sweep's
  const OptimizeResult r = runOptimize(o);
  EXPECT_EQ(r.method, "cobyla");
  ASSERT_TRUE(r.found) << r.stop_reason;
  const OptimizeEvaluation& best = r.history[r.best];
  EXPECT_LE(best.point.metric("delta"), 0.05);
  EXPECT_GT(best.x[0], lower);
  EXPECT_LE(best.x[0], upper + 0.4);
  EXPECT_LT(r.history.size(), sweep.points.size());
}

// Loveikin, Pochka, Romasevych (2018): the balanced four-cart drive rocks at small Δφ (δ is then
// meaningless, here even negative) and stalls at 80°. Such designs have the lowest δ numbers
// but must never be the optimum.
// The 6-cart trial: six carts of the balanced drive, δ against the crank offset over 0:180°. The
// evenly spread layout 60° has δ ≈ 2e-4 (a sharp minimum: 0.1 at 55° and 65°); BOBYQA alone from
// the middle of the range ends in the local minimum near 97.4° (δ ≈ 0.165), and said nothing.
// The default must find 60° and say it searched globally; the local method must say it is local.
TEST(Optimizer, DefaultFindsTheGlobalOffsetOfSixCartsAndLocalSaysItIsLocal) {
  OptimizeOptions o;
  o.scene_path = model("balanced-4cart.yaml");
  o.base_overrides = {"carts.count=6"};
  o.params = {{"crank.offset_deg", 0.0, 180.0}};
  o.model = "reduced";
  o.minimize = "delta";
  const OptimizeResult r = runOptimize(o);
  ASSERT_TRUE(r.found) << r.stop_reason;
  EXPECT_NEAR(r.history[r.best].x[0], 60.0, 0.5) << r.stop_reason;
  EXPECT_LT(r.history[r.best].objective, 0.01);
  EXPECT_NE(r.scope.find("global"), std::string::npos) << r.scope;
  for (double v : r.values_handed) EXPECT_TRUE(std::isfinite(v));  // no NaN or inf ever reaches NLopt
  // The trial's --max-evals 30: the grid used the rest, and the scope said "polished by bobyqa"
  // with no polishing run. It says what happened: the polish only when evaluations were left.
  {
    OptimizeOptions few = o;
    few.max_evals = 30;
    const OptimizeResult q = runOptimize(few);
    ASSERT_TRUE(q.found) << q.stop_reason;
    const bool polished = q.stop_reason.find("from the grid's best") != std::string::npos;
    EXPECT_EQ(q.scope.find("polished by") != std::string::npos, polished) << q.scope << " | " << q.stop_reason;
    EXPECT_NE(q.stop_reason.find("its share: 10 of the 30 evaluations"), std::string::npos) << q.stop_reason;
    if (!polished) EXPECT_NE(q.scope.find("no evaluations were left to polish it"), std::string::npos) << q.scope;
  }

  o.method = "bobyqa";
  const OptimizeResult local = runOptimize(o);
  ASSERT_TRUE(local.found);
  EXPECT_GT(std::abs(local.history[local.best].x[0] - 60.0), 10.0);  // the trap this test is about
  EXPECT_NE(local.scope.find("local"), std::string::npos) << local.scope;
}

// Early runs that are all unusable (six carts against forces opposing the velocity: every design
// stalls) gave BOBYQA inf (top + 10·span with span = 1e-3·|-inf|); the values handed over must be
// finite, and the search must end with "nothing usable", not an NLopt failure.
TEST(Optimizer, UnusableEarlyRunsNeverHandNonFiniteValuesToNLopt) {
  OptimizeOptions o;
  o.scene_path = model("balanced-4cart.yaml");
  o.base_overrides = {"carts.count=6", "loads.roller_force_direction=opposes_velocity", "simulation.t_end=2"};
  o.params = {{"crank.offset_deg", 0.0, 180.0}};
  o.model = "reduced";
  o.minimize = "delta";
  o.method = "bobyqa";
  o.max_evals = 15;
  const OptimizeResult r = runOptimize(o);
  EXPECT_FALSE(r.found);
  ASSERT_FALSE(r.values_handed.empty());
  for (double v : r.values_handed) EXPECT_TRUE(std::isfinite(v)) << v;
  EXPECT_EQ(r.stop_reason.find("NLopt failed"), std::string::npos) << r.stop_reason;
}

// The 6-cart trial at Δφ = 90° from rest: with a flywheel of 100 or 150 kg·m² the crank first
// rocks (swinging back at about -1 rad/s for over a second) and then turns. The fixed 1 s rule
// called those drives stalled, so the sweep showed them stalled and optimize found every
// flywheel infeasible. Both must now turn, and optimize must find a feasible flywheel.
TEST(Optimizer, RockingThenStartingDrivesAreFeasibleFlywheels) {
  SweepOptions s;
  s.scene_path = model("balanced-4cart.yaml");
  s.base_overrides = {"carts.count=6", "crank.offset_deg=90", "simulation.t_end=20"};
  s.params = {parseSweepValues("flywheel.inertia", "100,150")};
  s.model = "reduced";
  const SweepResult sweep = runSweep(s);
  ASSERT_EQ(sweep.points.size(), 2u);
  for (const SweepPoint& p : sweep.points) {
    EXPECT_EQ(p.motion, "turning") << p.values[0] << ": " << p.status;
    EXPECT_TRUE(p.complete) << p.status;
    EXPECT_GT(p.metric("omega_crank_min"), 0.0);
  }
  OptimizeOptions o;
  o.scene_path = s.scene_path;
  o.base_overrides = s.base_overrides;
  o.params = {{"flywheel.inertia", 0.0, 300.0}};
  o.model = "reduced";
  o.minimize = "flywheel.inertia";
  o.constraints = {parseConstraint("delta<=0.16")};
  const OptimizeResult r = runOptimize(o);
  ASSERT_TRUE(r.found) << r.stop_reason;
  EXPECT_LE(r.history[r.best].point.metric("delta"), 0.16);
  EXPECT_LT(r.history[r.best].x[0], 150.0);  // δ(150) = 0.153 < 0.16: the optimum is below 150
}

TEST(Optimizer, RockingAndStalledDesignsAreNeverTheOptimum) {
  OptimizeOptions o;
  o.scene_path = model("balanced-4cart.yaml");
  o.params = {{"crank.offset_deg", 30.0, 90.0}};
  o.model = "reduced";
  o.minimize = "delta";
  o.method = "direct-l";
  o.max_evals = 15;
  const OptimizeResult r = runOptimize(o);
  ASSERT_TRUE(r.found);
  std::size_t unusable = 0;
  double lowest_usable = INFINITY;
  for (const OptimizeEvaluation& e : r.history) {
    if (!e.run_ok) ++unusable;
    else lowest_usable = std::min(lowest_usable, e.objective);
  }
  ASSERT_GT(unusable, 0u) << "the search never met a rocking or stalled design: the test shows nothing";
  const OptimizeEvaluation& best = r.history[r.best];
  EXPECT_TRUE(best.run_ok);
  EXPECT_TRUE(best.point.complete && best.point.steady);
  EXPECT_GT(best.point.metric("omega_crank_min"), 0.0);
  EXPECT_GT(best.objective, 0.0);
  EXPECT_EQ(best.objective, lowest_usable);
}

TEST(Optimizer, BadInputIsRefusedClearly) {
  EXPECT_EQ(parseConstraint("delta <= 0.05").metric, "delta");
  EXPECT_FALSE(parseConstraint("k_p>=1e-3").upper);
  for (const char* bad : {"delta<0.05", "delta<=", "<=0.05", "delta<=abc", "delta"})
    EXPECT_THROW(parseConstraint(bad), std::invalid_argument) << bad;
  OptimizeOptions o;
  o.scene_path = model("recuperative-2cart.yaml");
  o.params = {{"crank.offset_deg", 0.0, 180.0}};
  o.model = "reduced";
  o.minimize = "deltaa";
  EXPECT_THROW(runOptimize(o), std::invalid_argument);
  o.minimize = "delta";
  o.constraints = {parseConstraint("hh<=1")};
  EXPECT_THROW(runOptimize(o), std::invalid_argument);
  o.constraints = {parseConstraint("H<=1")};
  o.method = "bobyqa";  // no constraints in BOBYQA
  EXPECT_THROW(runOptimize(o), std::invalid_argument);
  o.method = "newton";
  EXPECT_THROW(runOptimize(o), std::invalid_argument);
  o.method = "auto";
  o.params = {{"crank.offset_deg", 90.0, 10.0}};
  EXPECT_THROW(runOptimize(o), std::invalid_argument);
  o.params = {{"crank.ofset_deg", 0.0, 10.0}};
  EXPECT_THROW(runOptimize(o), std::invalid_argument);
}

TEST(OptimizeCommand, ErrorsExitWithCode2AndSayWhy) {
  const std::vector<std::string> base = {"optimize", model("recuperative-2cart.yaml"), "--param", "crank.offset_deg",
                                         "--model", "reduced"};
  auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> a = base;
    a.insert(a.end(), extra.begin(), extra.end());
    return test::runRollerdyn(a, 60);
  };
  test::CliResult r = with({"--range", "0:180", "--minimize", "deltaa"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--minimize: unknown metric 'deltaa' (did you mean 'delta'?)"), std::string::npos) << r.err;
  r = with({"--range", "180:0", "--minimize", "delta"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--range for crank.offset_deg"), std::string::npos) << r.err;
  r = with({"--range", "0:180", "--minimize", "delta", "--constraint", "H=<1"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--constraint 'H=<1': expected METRIC<=VALUE"), std::string::npos) << r.err;
}

TEST(OptimizeCommand, WritesOptimizeJsonAndHistory) {
  test::TempDir dir("optimize");
  const test::CliResult r = test::runRollerdyn(
      {"optimize", model("energy-balanced-3cart.yaml"), "--param", "flywheel.inertia", "--range", "0:400",
       "--minimize", "flywheel.inertia", "--constraint", "delta<=0.05", "--model", "reduced", "--out", dir.str()},
      120);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(test::slurp(dir.path() / "optimize.json"));
  EXPECT_EQ(j["method"], "cobyla, grid");  // no basin better than the first: no polish ran
  EXPECT_TRUE(j["constraints_hold"].get<bool>());
  const double inertia = j["optimum"]["parameters"]["flywheel.inertia"];
  EXPECT_LE(j["optimum"]["metrics"]["delta"].get<double>(), 0.05);
  EXPECT_EQ(j["optimum"]["objective"].get<double>(), inertia);
  // history.csv: a header and one row per evaluation.
  std::istringstream h(test::slurp(dir.path() / "history.csv"));
  std::string line;
  std::getline(h, line);
  EXPECT_EQ(line.rfind("evaluation,flywheel.inertia,objective,delta<=0.05,usable_run,constraints_hold,best_so_far", 0), 0u);
  int rows = 0;
  while (std::getline(h, line)) ++rows;
  EXPECT_EQ(rows, j["evaluations"].get<int>());
}

}  // namespace
}  // namespace rollerdyn
