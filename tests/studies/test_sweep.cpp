// Parameter sweeps (src/studies/Sweep.h): value grammar, per-point failures, the thread pool,
// the optimum and the output files.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "studies/Sweep.h"
#include "studies/SweepPlots.h"

namespace rollerdyn {
namespace {

const std::string kScene = std::string(ROLLERDYN_SOURCE_DIR) + "/model/recuperative-2cart.yaml";

TEST(SweepValues, RangesAndLists) {
  const SweepParameter a = parseSweepValues("crank.offset_deg", "0:180:10");
  ASSERT_EQ(a.values.size(), 19u);
  EXPECT_EQ(a.texts.front(), "0");
  EXPECT_EQ(a.texts.back(), "180");
  EXPECT_TRUE(a.numeric());
  // 0.1-steps land on round values (no 0.30000000000000004 in the --set text).
  const SweepParameter b = parseSweepValues("k", "0:0.5:0.1");
  ASSERT_EQ(b.texts.size(), 6u);
  EXPECT_EQ(b.texts[3], "0.3");
  // Descending with a negative step, and lists of numbers or words.
  EXPECT_EQ(parseSweepValues("k", "10:0:-5").texts, (std::vector<std::string>{"10", "5", "0"}));
  EXPECT_EQ(parseSweepValues("k", "2000, 8000").values, (std::vector<double>{2000, 8000}));
  const SweepParameter w = parseSweepValues("coupling.type", "elastic,rigid");
  EXPECT_FALSE(w.numeric());
  EXPECT_EQ(w.texts, (std::vector<std::string>{"elastic", "rigid"}));
  for (const char* bad : {"", "0:10", "0:10:0", "10:0:5", "a:b:c", "1,,2", "0:1:2:3"})
    EXPECT_THROW(parseSweepValues("k", bad), std::invalid_argument) << bad;
}

SweepOptions smallSweep() {
  SweepOptions o;
  o.scene_path = kScene;
  o.base_overrides = {"simulation.t_end=4", "simulation.steady_window_revolutions=2"};
  o.params = {parseSweepValues("crank.offset_deg", "0,90,400,180")};  // 400 deg is out of range
  o.model = "reduced";
  o.minimize = "delta";
  return o;
}

TEST(Sweep, BadPointIsReportedAndTheSweepGoesOn) {
  const SweepResult r = runSweep(smallSweep());
  ASSERT_EQ(r.points.size(), 4u);
  EXPECT_TRUE(r.points[0].complete);
  EXPECT_TRUE(r.points[1].complete);
  EXPECT_FALSE(r.points[2].ran);
  EXPECT_EQ(r.points[2].status.rfind("invalid: ", 0), 0u) << r.points[2].status;
  EXPECT_NE(r.points[2].status.find("crank.offset_deg"), std::string::npos);
  EXPECT_TRUE(std::isnan(r.points[2].metric("delta")));
  EXPECT_TRUE(r.points[3].complete);
  // Loveikin and Pochka's (2007) table and our model agree that 90° is the best of these (δ 0.151 vs 0.5 / 0.49).
  ASSERT_TRUE(r.optimum.found);
  EXPECT_EQ(r.optimum.index, 1u);
  EXPECT_LT(r.points[1].metric("delta"), r.points[0].metric("delta"));
}

TEST(Sweep, TwoThreadsGiveTheSameNumbersAsOne) {
  SweepOptions o = smallSweep();
  o.threads = 1;
  const SweepResult one = runSweep(o);
  o.threads = 2;
  const SweepResult two = runSweep(o);
  // Each run is deterministic and independent of the other thread: bit-identical metrics.
  for (std::size_t i = 0; i < one.points.size(); ++i)
    for (const std::string& m : sweepNumericMetrics()) {
      const double a = one.points[i].metric(m), b = two.points[i].metric(m);
      if (std::isnan(a)) EXPECT_TRUE(std::isnan(b)) << i << ' ' << m;
      else EXPECT_EQ(a, b) << i << ' ' << m;
    }
}

TEST(Sweep, ParabolasVertexInsideTheGridIsPredicted) {
  std::vector<SweepParameter> params = {parseSweepValues("x", "0,1,2,3")};
  std::vector<SweepPoint> pts(4);
  const double ys[] = {5.0, 2.0, 1.0, 2.0};  // parabola through (1,2),(2,1),(3,2): vertex at 2
  for (int i = 0; i < 4; ++i) {
    pts[i].values = {double(i)};
    pts[i].texts = {std::to_string(i)};
    pts[i].complete = pts[i].steady = true;
    pts[i].metrics.assign(sweepNumericMetrics().size(), NAN);
    pts[i].metrics[0] = ys[i];  // delta
  }
  pts[3].steady = false;  // a point not at steady state is not a candidate when others are
  const SweepOptimum o = findOptimum(params, pts, "delta");
  ASSERT_TRUE(o.found);
  EXPECT_EQ(o.index, 2u);
  EXPECT_FALSE(o.vertex.available);  // its right neighbour is not a candidate
  pts[3].steady = true;
  const SweepOptimum o2 = findOptimum(params, pts, "delta");
  ASSERT_TRUE(o2.vertex.available);
  EXPECT_NEAR(o2.vertex.parameter, 2.0, 1e-12);
  EXPECT_NEAR(o2.vertex.predicted, 1.0, 1e-12);
  EXPECT_FALSE(o2.vertex.ran);  // a prediction until runSweep runs it (test_sweep_vertex.cpp)
}

TEST(Sweep, WritesCsvJsonAndPlots) {
  SweepOptions o = smallSweep();
  const SweepResult r = runSweep(o);
  const std::string dir = ::testing::TempDir() + "/rollerdyn_sweep_test";
  std::filesystem::remove_all(dir);
  writeSweepOutputs(o, r, dir);
  std::ifstream csv(dir + "/sweep.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header,
            "crank.offset_deg[deg],delta[-],H[-],k_p[-],omega_crank_mean[rad/s],coupling_torque_swing[N*m],"
            "twist_swing[rad],eps_crank_abs_max[rad/s^2],energy_residual_rel[-],steady_state_reached,motion,status,"
            "cpu_seconds[s],omega_crank_min[rad/s],omega_crank_max[rad/s],omega_crank_midrange[rad/s],"
            "twist_rate_swing[rad/s],twist_accel_swing[rad/s^2],resonance_warnings,motor_torque_rotor_rms[N*m],"
            "motor_torque_rotor_peak[N*m],motor_rms_over_nominal[-],motor_peak_over_breakdown[-],motor_power_mean[W],"
            "motor_power_peak[W],energy_per_revolution[J],kinetic_energy_swing[J],coupling_torque_peak[N*m],"
            "load_power_per_cart[W],load_net_over_gross[-],motor_torque_rotor_rms_whole_run[N*m],"
            "motor_thermal_whole_run[-],motor_power_line_mean_whole_run[W],coupling_torque_peak_whole_run[N*m],"
            "guide_roller_peak[N],guide_roller_rear_peak[N],rod_force_peak[N],crank_pin_peak[N],"
            "main_bearing_peak[N],guide_roller_equivalent_load[N],crank_pin_equivalent_load[N],"
            "main_bearing_equivalent_load[N]");
  int rows = 0;
  for (std::string line; std::getline(csv, line);) ++rows;
  EXPECT_EQ(rows, 4);
  std::ifstream js(dir + "/sweep.json");
  std::stringstream ss;
  ss << js.rdbuf();
  const auto j = nlohmann::json::parse(ss.str());
  EXPECT_EQ(j["points"].size(), 4u);
  EXPECT_EQ(j["optimum"]["at"]["crank.offset_deg"], 90.0);
  if (!j["plots"].empty()) EXPECT_TRUE(std::filesystem::exists(dir + "/plot_delta.png"));
  else EXPECT_FALSE(j["plot_note"].get<std::string>().empty());
}

TEST(Sweep, RejectsUnknownKeysMetricsAndModels) {
  SweepOptions o = smallSweep();
  o.params = {parseSweepValues("crank.ofset_deg", "0,90")};
  EXPECT_THROW(runSweep(o), std::invalid_argument);
  o = smallSweep();
  o.minimize = "deltaa";
  EXPECT_THROW(runSweep(o), std::invalid_argument);
  o = smallSweep();
  o.model = "fem";
  EXPECT_THROW(runSweep(o), std::invalid_argument);
}

// Heat-map cells end halfway to the neighbours and at the first and last grid value: none runs
// past the grid (a damping grid 2000, 8000 once drew a cell down to -1000).
TEST(SweepPlots, HeatMapCellsStayInsideTheGrid) {
  const auto e = heatMapCellEdges({2000, 8000});
  EXPECT_EQ(e[0], (std::pair<double, double>{2000, 5000}));
  EXPECT_EQ(e[1], (std::pair<double, double>{5000, 8000}));
  const auto u = heatMapCellEdges({90, 0, 30});  // any order, uneven steps
  EXPECT_EQ(u[1], (std::pair<double, double>{0, 15}));
  EXPECT_EQ(u[2], (std::pair<double, double>{15, 60}));
  EXPECT_EQ(u[0], (std::pair<double, double>{60, 90}));
}

TEST(SweepPlots, OnlyTurningPointsAtSteadyStateSetTheScale) {
  SweepPoint p;
  p.complete = true;
  p.motion = "turning";
  p.steady = true;
  EXPECT_EQ(classifySweepPoint(p), SweepPointClass::Steady);
  p.steady = false;
  EXPECT_EQ(classifySweepPoint(p), SweepPointClass::Unsteady);
  p.motion = "rocking";
  EXPECT_EQ(classifySweepPoint(p), SweepPointClass::NoValue);
  p.motion = "turning";
  p.complete = false;
  EXPECT_EQ(classifySweepPoint(p), SweepPointClass::NoValue);
}

// Axis labels of scene keys carry the unit of model/README.md; dimensionless keys and names that
// are not scene keys (a metric) stay bare.
TEST(SweepPlots, ParameterLabelsCarryTheSchemaUnit) {
  EXPECT_EQ(sweepParamLabel("crank.offset_deg"), "crank.offset_deg [deg]");
  EXPECT_EQ(sweepParamLabel("flywheel.inertia"), "flywheel.inertia [kg·m²]");
  EXPECT_EQ(sweepParamLabel("simulation.accuracy"), "simulation.accuracy");
  EXPECT_EQ(sweepParamLabel("delta"), "delta");
}

// Loveikin, Pochka, Romasevych (2018) at Δφ = 0: the four carts' loads rock the crank; at 90° it
// turns. The rocking point is named in the point, sweep.csv and sweep.json, has no δ, and is never
// the optimum even where its numbers are smaller.
TEST(Sweep, RockingPointIsNamedEverywhereAndNeverTheOptimum) {
  SweepOptions o;
  o.scene_path = std::string(ROLLERDYN_SOURCE_DIR) + "/model/balanced-4cart.yaml";
  o.base_overrides = {"simulation.t_end=12"};  // its swings grow until ~6.6 s, stop growing by ~8 s
  o.params = {parseSweepValues("crank.offset_deg", "0,90")};
  o.model = "reduced";
  o.minimize = "motor_peak_over_breakdown";
  const SweepResult r = runSweep(o);
  ASSERT_EQ(r.points.size(), 2u);
  EXPECT_EQ(r.points[0].motion, "rocking");
  EXPECT_TRUE(std::isnan(r.points[0].metric("delta")));
  EXPECT_EQ(r.points[1].motion, "turning");
  EXPECT_TRUE(std::isfinite(r.points[1].metric("delta")));
  EXPECT_TRUE(std::isfinite(r.points[1].metric("motor_rms_over_nominal")));
  ASSERT_TRUE(r.optimum.found);
  EXPECT_EQ(r.optimum.index, 1u);
  const std::string dir = ::testing::TempDir() + "/rollerdyn_sweep_rocking";
  std::filesystem::remove_all(dir);
  writeSweepOutputs(o, r, dir);
  std::ifstream csv(dir + "/sweep.csv");
  std::stringstream text;
  text << csv.rdbuf();
  EXPECT_NE(text.str().find(",rocking,"), std::string::npos) << text.str();
  std::ifstream js(dir + "/sweep.json");
  std::stringstream jt;
  jt << js.rdbuf();
  const auto j = nlohmann::json::parse(jt.str());
  EXPECT_EQ(j["points"][0]["motion"], "rocking");
  EXPECT_TRUE(j["points"][0]["metrics"]["delta"].is_null());
}

}  // namespace
}  // namespace rollerdyn
