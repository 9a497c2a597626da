// A sweep's interpolated optimum is run before it is printed (Sweep.h SweepVertex): the vertex of
// the parabola through the best grid point and its neighbours is a prediction; the optimum is
// always a run. Metrics of known shape (a kinked minimum, where the parabola through three grid
// points is wrong, and an exact parabola, where it is right) and a shipped scene.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <mutex>
#include <string>
#include <vector>

#include "analysis/Summary.h"
#include "cli/CliTestSupport.h"
#include "reduced/ReducedModel.h"
#include "scene/SceneParser.h"
#include "studies/Sweep.h"

namespace rollerdyn {
namespace {

using test::model;

constexpr auto npos = std::string::npos;

// A run of a metric known beforehand: completes at steady state, turning, with delta = y.
SweepPoint knownRun(const std::vector<std::string>& texts, const std::vector<double>& values, double y) {
  SweepPoint p;
  p.texts = texts;
  p.values = values;
  p.metrics.assign(sweepNumericMetrics().size(), NAN);
  p.metrics[0] = y;  // delta (the first numeric metric)
  p.ran = p.complete = p.steady = true;
  p.motion = "turning";
  p.status = "complete";
  return p;
}

// A sweep of crank.offset_deg over 0:180:15 whose points are `metric` (no model is run); the
// parameters asked for are recorded in order.
struct KnownSweep {
  SweepOptions o;
  std::vector<std::string> asked;
  std::mutex mu;
  explicit KnownSweep(std::function<double(double)> metric) {
    o.scene_path = model("recuperative-2cart.yaml");  // simulation.accuracy 1e-6 (the default)
    o.params = {parseSweepValues("crank.offset_deg", "0:180:15")};
    o.model = "reduced";
    o.minimize = "delta";
    o.run_point = [this, metric](const std::vector<std::string>& t, const std::vector<double>& v) {
      std::lock_guard<std::mutex> lock(mu);
      asked.push_back(t[0]);
      return knownRun(t, v, metric(v[0]));
    };
  }
};

// δ with a kink at 60°, twice as steep to the right: 0.001 + 0.002·(60 − x) left, 0.001 + 0.004·(x − 60) right.
double kinked(double x) { return x < 60 ? 0.001 + 0.002 * (60 - x) : 0.001 + 0.004 * (x - 60); }

// By hand: the grid's best is 60° (0.001), its neighbours 45° (0.031) and 75° (0.061). The
// parabola through them has its vertex at x = 60 + 15·(y0 − y2)/(2·(y0 − 2y1 + y2)) = 60 + 15·(−0.03)/0.18
// = 57.5° and predicts y1 − (y0 − y2)²/(8·(y0 − 2y1 + y2)) = 0.001 − 0.0009/0.72 = −0.00025, a
// negative δ; the metric there is 0.001 + 0.002·2.5 = 0.006. The trial's six carts printed such a
// prediction (0.00077 at 61.1°, a run there 0.01696) as the optimum.
TEST(SweepVertex, AKinkedMinimumIsRunAndTheParabolasEstimateIsNotClaimed) {
  KnownSweep s(kinked);
  const SweepResult r = runSweep(s.o);
  const SweepOptimum& opt = r.optimum;
  ASSERT_TRUE(opt.found);
  ASSERT_TRUE(opt.vertex.available);
  EXPECT_EQ(opt.vertex.text, "57.5");
  EXPECT_NEAR(opt.vertex.predicted, -0.00025, 1e-12);
  ASSERT_EQ(s.asked.size(), 14u);  // the 13 grid points, then the vertex
  EXPECT_EQ(s.asked.back(), "57.5");
  ASSERT_TRUE(opt.vertex.ran);
  EXPECT_TRUE(opt.vertex.usable);
  EXPECT_NEAR(opt.vertex.value, 0.006, 1e-15);
  EXPECT_FALSE(opt.vertex.holds);
  // The optimum is the better run: the grid point at 60°.
  EXPECT_FALSE(opt.at_vertex);
  EXPECT_EQ(opt.index, 4u);
  EXPECT_NEAR(opt.value, 0.001, 1e-15);
  const std::string text = describeOptimum(s.o, r);
  EXPECT_EQ(text.rfind("minimum of delta = 0.001 at crank.offset_deg=60 (steady state reached)", 0), 0u) << text;
  EXPECT_NE(text.find("the parabola's estimate delta = -0.00025 at crank.offset_deg=57.5 does not hold: a run there "
                      "gives 0.006; the minimum is a kink or lies between grid points: refine the grid near 60 "
                      "(--values 45:75:1.5)"),
            npos)
      << text;
  const nlohmann::json j = sweepOptimumJson(s.o, r);
  EXPECT_EQ(j["source"], "grid point") << j.dump(2);
  EXPECT_NEAR(j["value"].get<double>(), 0.001, 1e-15);
  EXPECT_EQ(j["at"]["crank.offset_deg"], 60.0);
  EXPECT_NEAR(j["parabola"]["predicted"].get<double>(), -0.00025, 1e-12);
  EXPECT_NEAR(j["parabola"]["run"]["value"].get<double>(), 0.006, 1e-15);
  EXPECT_EQ(j["parabola"]["holds"], false);
  EXPECT_EQ(j["parabola"]["is_optimum"], false);
  EXPECT_EQ(j["parabola"]["refine"], "--values 45:75:1.5");
}

// δ = 0.01 + (x − 62)²/1000, an exact parabola: the vertex 62° predicts 0.01 and its run gives 0.01,
// below the best grid point (60°: 0.014); the optimum is that run.
TEST(SweepVertex, AVertexRunBetterThanTheGridIsTheOptimum) {
  KnownSweep s([](double x) { return 0.01 + (x - 62) * (x - 62) / 1000; });
  const SweepResult r = runSweep(s.o);
  const SweepOptimum& opt = r.optimum;
  ASSERT_TRUE(opt.vertex.ran);
  EXPECT_EQ(opt.vertex.text, "62");
  EXPECT_TRUE(opt.vertex.holds);
  EXPECT_TRUE(opt.at_vertex);
  EXPECT_NEAR(opt.value, 0.01, 1e-15);
  EXPECT_NEAR(opt.grid_value, 0.014, 1e-15);
  const std::string text = describeOptimum(s.o, r);
  EXPECT_EQ(text.rfind("minimum of delta = 0.01 at crank.offset_deg=62 (steady state reached), a run at the vertex "
                       "of the parabola through the best grid point crank.offset_deg=60 (delta = 0.014)",
                       0),
            0u)
      << text;
  EXPECT_NE(text.find("a run there gives 0.01 (the estimate holds)"), npos) << text;
  const nlohmann::json j = sweepOptimumJson(s.o, r);
  EXPECT_EQ(j["source"], "run at the parabola's vertex");
  EXPECT_EQ(j["at"]["crank.offset_deg"], 62.0);
  EXPECT_EQ(j["parabola"]["is_optimum"], true);
}

// δ = 0.001·|x − 62|, a symmetric kink between grid points. By hand: 45°, 60°, 75° give 0.017, 0.002,
// 0.013; the vertex x = 60 + 15·0.004/(2·0.026) = 61.1538461538°, predicted 0.002 − 0.004²/(8·0.026)
// = 0.00192308; the run there gives 0.001·0.846153846 = 0.000846154, lower than the prediction and than
// the grid: it is the optimum, and the line says the metric is no parabola there.
TEST(SweepVertex, AVertexRunLowerThanPredictedIsTheOptimumAndAsksForAFinerGrid) {
  KnownSweep s([](double x) { return 0.001 * std::abs(x - 62); });
  const SweepResult r = runSweep(s.o);
  const SweepOptimum& opt = r.optimum;
  ASSERT_TRUE(opt.vertex.ran);
  EXPECT_EQ(opt.vertex.text, "61.1538461538");
  EXPECT_NEAR(opt.vertex.predicted, 0.002 - 0.004 * 0.004 / (8 * 0.026), 1e-12);
  EXPECT_FALSE(opt.vertex.holds);
  EXPECT_TRUE(opt.vertex.lower);
  EXPECT_TRUE(opt.at_vertex);
  EXPECT_NEAR(opt.value, 0.001 * (62 - 61.1538461538), 1e-15);
  const std::string text = describeOptimum(s.o, r);
  EXPECT_EQ(text.rfind("minimum of delta = 0.000846154 at crank.offset_deg=61.1538461538 (steady state reached)", 0), 0u)
      << text;
  EXPECT_NE(text.find("a run there gives 0.000846154, lower still: the metric is no parabola between the grid points; "
                      "refine the grid near 61.1538461538 (--values 45:75:1.5)"),
            npos)
      << text;
  EXPECT_EQ(text.find("does not hold"), npos) << text;
}

// A vertex whose run stalls is no optimum and no value: the grid's best stays, and the line says
// the run there is not usable instead of printing the prediction as a result.
TEST(SweepVertex, AVertexRunThatStallsIsNotUsable) {
  KnownSweep s(kinked);
  s.o.run_point = [](const std::vector<std::string>& t, const std::vector<double>& v) {
    SweepPoint p = knownRun(t, v, kinked(v[0]));
    if (t[0] == "57.5") p.motion = "stalled", p.steady = false, p.complete = false, p.status = "stalled";
    return p;
  };
  const SweepResult r = runSweep(s.o);
  ASSERT_TRUE(r.optimum.vertex.ran);
  EXPECT_FALSE(r.optimum.vertex.usable);
  EXPECT_TRUE(std::isnan(r.optimum.vertex.value));
  EXPECT_FALSE(r.optimum.at_vertex);
  EXPECT_NEAR(r.optimum.value, 0.001, 1e-15);
  const std::string text = describeOptimum(s.o, r);
  EXPECT_NE(text.find("a run there is not usable (stalled)"), npos) << text;
  EXPECT_TRUE(sweepOptimumJson(s.o, r)["parabola"]["run"]["value"].is_null());
}

// Interrupted after the grid (Ctrl-C): the vertex is not run, and the parabola's value is printed
// only as an estimate, never as the minimum.
TEST(SweepVertex, AnInterruptedSweepLabelsTheVertexAnEstimate) {
  KnownSweep s(kinked);
  std::atomic<bool> stop{false};
  s.o.threads = 1;
  s.o.interrupt = &stop;
  s.o.run_point = [&s, &stop](const std::vector<std::string>& t, const std::vector<double>& v) {
    s.asked.push_back(t[0]);
    if (s.asked.size() == 13) stop = true;  // Ctrl-C during the last grid point
    return knownRun(t, v, kinked(v[0]));
  };
  const SweepResult r = runSweep(s.o);
  EXPECT_EQ(s.asked.size(), 13u);
  ASSERT_TRUE(r.optimum.vertex.available);
  EXPECT_FALSE(r.optimum.vertex.ran);
  EXPECT_NEAR(r.optimum.value, 0.001, 1e-15);
  const std::string text = describeOptimum(s.o, r);
  EXPECT_EQ(text.rfind("minimum of delta = 0.001 at crank.offset_deg=60", 0), 0u) << text;
  EXPECT_NE(text.find("puts the minimum at crank.offset_deg=57.5 with delta = -0.00025: an estimate, not run (interrupted)"),
            npos)
      << text;
  EXPECT_TRUE(sweepOptimumJson(s.o, r)["parabola"]["run"].is_null());
}

// On a shipped scene the vertex is run with the sweep's model, --set overrides and settings: its
// δ equals a run of the scene with those overrides and the vertex's value, made here.
TEST(SweepVertex, TheVertexRunIsTheScenesRunWithTheSweepsOverrides) {
  SweepOptions o;
  o.scene_path = model("recuperative-2cart.yaml");
  o.base_overrides = {"simulation.t_end=4", "simulation.steady_window_revolutions=2"};
  o.params = {parseSweepValues("crank.offset_deg", "80,90,100")};
  o.model = "reduced";
  o.minimize = "delta";
  const SweepResult r = runSweep(o);
  ASSERT_TRUE(r.optimum.found);
  ASSERT_EQ(r.optimum.index, 1u);
  ASSERT_TRUE(r.optimum.vertex.ran) << r.optimum.vertex.note;
  const std::string at = r.optimum.vertex.text;
  std::vector<std::string> overrides = o.base_overrides;
  overrides.push_back("crank.offset_deg=" + at);
  const Scene scene = parseSceneFile(o.scene_path, overrides);
  const nlohmann::json summary = makeSummary(scene, runReducedModel(scene));
  EXPECT_EQ(r.optimum.vertex.point.metric("delta"), summary["delta"].get<double>()) << at;
  // Whichever is better is the optimum, and its value is a run's.
  const double grid = r.points[1].metric("delta"), vertex = summary["delta"].get<double>();
  EXPECT_EQ(r.optimum.value, std::min(grid, vertex));
  EXPECT_EQ(r.optimum.at_vertex, vertex < grid);
}

}  // namespace
}  // namespace rollerdyn
