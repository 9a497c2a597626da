// Which figures an output folder gets and what they show, on a synthetic periodic run whose
// every curve is known in closed form; drawing itself is checked when gnuplot is installed.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>

#include "physics/KlossMotor.h"
#include "report/RunFigures.h"
#include "scene/SceneParser.h"

namespace rollerdyn {
namespace {

namespace fs = std::filesystem;
constexpr double kTwoPi = 6.283185307179586;

Scene balanced() {
  return parseSceneFile(std::string(ROLLERDYN_SOURCE_DIR) + "/model/balanced-4cart.yaml");
}

// 6 s of a periodic run at ~10 rad/s, steady window 3 ... 6 s, two carts, motor on its curve.
OutputFolder syntheticFolder(const Scene& scene, bool elastic = true, double torque_factor = 1.0) {
  OutputFolder f;
  f.dir = "unused";
  f.has_timeseries = f.has_reactions = f.has_summary = true;
  f.timeseries.columns = {"t",     "phi_crank",  "omega_crank", "eps_crank",       "omega_motor",
                          "twist", "twist_rate", "twist_accel", "coupling_torque", "motor_torque"};
  f.reactions.columns = {"t", "N_front_1", "N_rear_1", "F_rod_1", "N_front_2", "N_rear_2", "F_rod_2"};
  for (int i = 0; i <= 600; ++i) {
    const double t = 0.01 * i, phi = 10 * t, w = 10 + 0.5 * std::sin(phi);
    const double psi = elastic ? 0.01 * std::sin(phi) : 0.0;
    const double wm = w + (elastic ? 0.1 * std::cos(phi) : 0.0);
    const double m = torque_factor * klossCrankTorque(scene.motor, scene.reducer.ratio, scene.reducer.efficiency, wm);
    f.timeseries.rows.push_back({t, phi, w, 5 * std::cos(phi), wm, psi, 10 * psi, -100 * psi, 2e5 * psi, m});
    f.reactions.rows.push_back({t, 1000 * std::sin(phi), 900, -500, 800, 700 * std::cos(phi), 400});
  }
  f.summary = {{"scene", "synthetic"}, {"steady_state", {{"t_begin", 3.0}, {"t_end", 6.0}}}};
  return f;
}

std::set<std::string> names(const std::vector<FigurePlan>& plans) {
  std::set<std::string> s;
  for (const auto& p : plans) s.insert(p.name);
  return s;
}

const FigurePlan& find(const std::vector<FigurePlan>& plans, const std::string& name) {
  for (const auto& p : plans)
    if (p.name == name) return p;
  throw std::runtime_error("no figure " + name);
}

bool mentions(const std::vector<std::string>& notes, const std::string& what) {
  for (const auto& n : notes)
    if (n.find(what) != std::string::npos) return true;
  return false;
}

TEST(RunFigures, FoldedAngleBreaksAtEachWrap) {
  std::vector<double> phi;
  for (int i = 0; i <= 100; ++i) phi.push_back(0.13 * i);  // 0 ... 13 rad: two wraps
  std::vector<long> index;
  const std::vector<double> a = foldedAngle(phi, &index);
  ASSERT_EQ(a.size(), index.size());
  EXPECT_EQ(a.size(), phi.size() + 2);
  int gaps = 0;
  for (size_t k = 0; k < a.size(); ++k) {
    if (std::isnan(a[k])) {
      ++gaps;
      EXPECT_EQ(index[k], -1);
      continue;
    }
    EXPECT_GE(a[k], 0.0);
    EXPECT_LT(a[k], kTwoPi);
    EXPECT_NEAR(a[k], std::fmod(phi[index[k]], kTwoPi), 1e-12);
  }
  EXPECT_EQ(gaps, 2);
  // Negative rotation folds into [0, 2π) too.
  const std::vector<double> neg = foldedAngle({-0.1, -0.2}, nullptr);
  EXPECT_NEAR(neg[0], kTwoPi - 0.1, 1e-12);
}

TEST(RunFigures, ElasticRunGetsEveryFigure) {
  const Scene scene = balanced();
  std::vector<std::string> notes;
  const auto plans = planRunFigures(syntheticFolder(scene), &scene, notes);
  EXPECT_EQ(names(plans), (std::set<std::string>{"crank_speed_vs_angle", "crank_accel_vs_angle", "crank_speed_vs_time",
                                                 "crank_accel_vs_time", "coupling_torque_vs_time",
                                                 "motor_operating_point", "motor_operating_point_steady",
                                                 "motor_torque_vs_time", "motor_torque_vs_angle", "motor_power_vs_time",
                                                 "motor_power_vs_angle", "guide_reactions_vs_angle",
                                                 "rod_forces_vs_angle", "twist_phase_rate", "twist_phase_rate_accel",
                                                 "twist_phase_accel"}));
  EXPECT_TRUE(notes.empty()) << notes.front();
}

TEST(RunFigures, AnglePlotsCoverTheSteadyWindowOnly) {
  const Scene scene = balanced();
  std::vector<std::string> notes;
  const auto plans = planRunFigures(syntheticFolder(scene), &scene, notes);
  const PlotSeries& s = find(plans, "crank_speed_vs_angle").spec.series.at(0);
  EXPECT_TRUE(s.break_at_nonfinite);
  size_t points = 0;
  for (size_t k = 0; k < s.x.size(); ++k) {
    if (std::isnan(s.x[k])) continue;
    ++points;
    EXPECT_NEAR(s.y[k], 10 + 0.5 * std::sin(s.x[k]), 1e-9);  // ω(φ) is the same every revolution
  }
  EXPECT_EQ(points, 301u);  // t = 3.00 ... 6.00 s
  const auto& gr = find(plans, "guide_reactions_vs_angle").spec.series;
  ASSERT_EQ(gr.size(), 4u);
  EXPECT_EQ(gr[0].title, "N_{front,1}");
  EXPECT_EQ(gr[3].title, "N_{rear,2}");
  EXPECT_EQ(find(plans, "rod_forces_vs_angle").spec.series.size(), 2u);
}

TEST(RunFigures, KlossCurveIsTheScenesMotorReducedToTheCrank) {
  const Scene scene = balanced();
  std::vector<std::string> notes;
  const auto plans = planRunFigures(syntheticFolder(scene), &scene, notes);
  const auto& series = find(plans, "motor_operating_point").spec.series;
  ASSERT_EQ(series.size(), 3u);  // curve, whole trajectory, steady window
  const PlotSeries& curve = series[0];
  // Kloss's formula written out here (Loveikin, Pochka, Romasevych (2018), eq. (37)): rotor slip
  // s = 1 − u·ω/ω0, rotor torque 2·M_kr/(s/s_kr + s_kr/s), times u·η at the crank.
  const KlossMotor& mo = scene.motor;
  const double u = scene.reducer.ratio, eta = scene.reducer.efficiency;
  for (size_t k = 0; k < curve.x.size(); k += 50) {
    const double slip = 1.0 - u * curve.x[k] / mo.omega_sync;
    const double rotor = slip == 0.0 ? 0.0 : 2.0 * mo.breakdown_torque / (slip / mo.critical_slip + mo.critical_slip / slip);
    EXPECT_NEAR(curve.y[k], rotor * u * eta, 1e-9 * mo.breakdown_torque * u) << "omega = " << curve.x[k];
  }
  // The curve reaches past synchronous speed, where the torque changes sign.
  EXPECT_GT(curve.x.back(), scene.motor.omega_sync / scene.reducer.ratio);
  EXPECT_LT(curve.y.back(), 0.0);
  EXPECT_FALSE(mentions(notes, "differs from the Kloss curve"));
}

TEST(RunFigures, WarnsWhenTheRunsMotorIsNotTheScenes) {
  const Scene scene = balanced();
  std::vector<std::string> notes;
  planRunFigures(syntheticFolder(scene, true, 1.1), &scene, notes);
  EXPECT_TRUE(mentions(notes, "differs from the Kloss curve")) << (notes.empty() ? "" : notes.front());
}

TEST(RunFigures, WithoutSceneTheTrajectoryIsDrawnAlone) {
  const Scene scene = balanced();
  std::vector<std::string> notes;
  const auto plans = planRunFigures(syntheticFolder(scene), nullptr, notes);
  EXPECT_EQ(find(plans, "motor_operating_point").spec.series.size(), 2u);
  EXPECT_TRUE(mentions(notes, "without its Kloss curve"));
}

TEST(RunFigures, MotorTorqueAndPowerAtTheRotorWithNominalAndBreakdownLevels) {
  const Scene scene = balanced();
  std::vector<std::string> notes;
  const OutputFolder f = syntheticFolder(scene);
  const auto plans = planRunFigures(f, &scene, notes);
  const double u = scene.reducer.ratio, eta = scene.reducer.efficiency;
  const PlotSeries& torque = find(plans, "motor_torque_vs_time").spec.series.at(0);
  const PlotSeries& power = find(plans, "motor_power_vs_time").spec.series.at(0);
  const int iw = f.timeseries.index("omega_motor"), im = f.timeseries.index("motor_torque");
  for (std::size_t k : {0ul, 137ul, 600ul}) {
    const double M = f.timeseries.rows[k][im] / (u * eta);  // the column is M·u·η at the crank
    EXPECT_NEAR(torque.y[k], M, 1e-9 * std::abs(M) + 1e-12);
    EXPECT_NEAR(power.y[k], M * u * f.timeseries.rows[k][iw] * 1e-3, 1e-9 * std::abs(M) + 1e-12);
  }
  // Levels: M_n = M_kr/λ = 517.14/2.4 and M_kr = 517.14 N·m (scene), drawn as horizontal lines
  // the y range keeps in view.
  const std::string& pre = find(plans, "motor_torque_vs_angle").spec.preamble;
  EXPECT_NE(pre.find("first 215.475 "), std::string::npos) << pre;
  EXPECT_NE(pre.find("first 517.14 "), std::string::npos) << pre;
  EXPECT_NE(pre.find("set yrange"), std::string::npos) << pre;
  // Nominal power M_n·ω_n = 215.475·102.1 W, in kW.
  char level[64];
  std::snprintf(level, sizeof level, "first %.9g ", 517.14 / 2.4 * 102.1 * 1e-3);
  EXPECT_NE(find(plans, "motor_power_vs_time").spec.preamble.find(level), std::string::npos)
      << find(plans, "motor_power_vs_time").spec.preamble;
}

TEST(RunFigures, OperatingPointsOfTheSteadyWindowAreMarkedOnTheKlossCurve) {
  const Scene scene = balanced();
  std::vector<std::string> notes;
  const auto plans = planRunFigures(syntheticFolder(scene), &scene, notes);
  const FigurePlan& p = find(plans, "motor_operating_point");
  const PlotSeries& steady = p.spec.series.back();
  EXPECT_EQ(steady.style.rfind("points", 0), 0u);
  EXPECT_EQ(steady.x.size(), 301u);  // rows with 3 <= t <= 6 of 0.01-s rows
  // Breakdown point at ω_kr/u = ω0(1 - s_kr)/u and M_kr·u·η, nominal point marked too.
  const double u = scene.reducer.ratio, eta = scene.reducer.efficiency;
  char at[96];
  std::snprintf(at, sizeof at, "at %.9g,%.9g point", scene.motor.omega_sync * (1 - scene.motor.critical_slip) / u,
                scene.motor.breakdown_torque * u * eta);
  EXPECT_NE(p.spec.preamble.find(at), std::string::npos) << p.spec.preamble;
  EXPECT_NE(p.spec.preamble.find("nominal M_n"), std::string::npos);
  // The close-up spans the steady operating range, not the whole curve.
  const std::string& zoom = find(plans, "motor_operating_point_steady").spec.preamble;
  EXPECT_NE(zoom.find("set xrange"), std::string::npos);
  EXPECT_NE(zoom.find("breakdown torque"), std::string::npos);
}

TEST(RunFigures, RigidCouplingHasNoPhasePortraits) {
  const Scene scene = balanced();
  std::vector<std::string> notes;
  const auto plans = planRunFigures(syntheticFolder(scene, false), &scene, notes);
  EXPECT_FALSE(names(plans).count("twist_phase_rate"));
  EXPECT_TRUE(mentions(notes, "rigid coupling"));
}

TEST(RunFigures, WindowFromSummaryElseDetected) {
  const Scene scene = balanced();
  OutputFolder f = syntheticFolder(scene);
  TimeWindow w = steadyWindow(f);
  EXPECT_TRUE(w.found);
  EXPECT_EQ(w.source, "summary.json");
  EXPECT_DOUBLE_EQ(w.t_begin, 3.0);
  f.summary = nlohmann::json::object();
  f.has_summary = false;
  w = steadyWindow(f);
  EXPECT_TRUE(w.found);
  EXPECT_EQ(w.source, "detected");
  EXPECT_GT(w.t_end, w.t_begin);
}

TEST(RunFigures, ComparisonOverlays) {
  OutputFolder f;
  f.has_comparison = true;
  f.comparison.columns = {"t", "omega_crank_multibody", "omega_crank_reduced", "N_front_1_multibody",
                          "N_front_1_reduced", "N_front_1_reduced_kinetostatic"};
  f.comparison.rows = {{0, 1, 1.1, 5, 6, 7}, {1, 2, 2.1, 5, 6, 7}};
  std::vector<std::string> notes;
  const auto plans = planRunFigures(f, nullptr, notes);
  EXPECT_EQ(names(plans), (std::set<std::string>{"comparison_omega_crank", "comparison_N_front_1"}));
  EXPECT_EQ(find(plans, "comparison_omega_crank").spec.series.size(), 2u);
  EXPECT_EQ(find(plans, "comparison_N_front_1").spec.series.size(), 3u);
}

TEST(RunFigures, ComparisonFromAnotherRunIsLeftOut) {
  const Scene scene = balanced();
  OutputFolder f = syntheticFolder(scene);
  f.has_comparison = true;
  f.comparison.columns = {"t", "omega_crank_multibody", "omega_crank_reduced"};
  for (const auto& row : f.timeseries.rows) f.comparison.rows.push_back({row[0], row[2], row[2] + 0.01});
  std::vector<std::string> notes;
  EXPECT_TRUE(names(planRunFigures(f, &scene, notes)).count("comparison_omega_crank")) << "same run: drawn";
  for (auto& row : f.comparison.rows) row[1] += 0.5;  // another run's multibody speed
  notes.clear();
  EXPECT_FALSE(names(planRunFigures(f, &scene, notes)).count("comparison_omega_crank"));
  EXPECT_TRUE(mentions(notes, "comparison.csv comes from another run"));
}

TEST(RunFigures, ColumnNamesNeverLeaveTheFiguresFolder) {
  OutputFolder f;
  f.has_comparison = true;
  f.comparison.columns = {"t", "../../../tmp/evil_multibody", "x\rset output '/tmp/x'_multibody"};
  f.comparison.rows = {{0, 1, 1}, {1, 2, 2}};
  std::vector<std::string> notes;
  for (const FigurePlan& p : planRunFigures(f, nullptr, notes)) {
    EXPECT_EQ(p.name.find('/'), std::string::npos) << p.name;
    EXPECT_EQ(p.name.find('.'), std::string::npos) << p.name;
    EXPECT_EQ(p.name.find('\r'), std::string::npos) << p.name;
  }
  if (!gnuplotAvailable()) return;
  // A title with a newline and quotes is drawn as text, not run as gnuplot commands.
  const fs::path dir = fs::temp_directory_path() / ("rollerdyn-quote-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const fs::path marker = dir / "injected.png";
  PlotSpec spec;
  spec.title = "a\"\nset output '" + marker.string() + "'\nplot x\n";
  spec.series.push_back({"b\\\n\"", {0, 1}, {0, 1}});
  renderPlot(spec, (dir / "quoted").string(), true, false);
  EXPECT_TRUE(fs::exists(dir / "quoted.png"));
  EXPECT_FALSE(fs::exists(marker)) << "a title escaped its string";
  fs::remove_all(dir);
}

TEST(RunFigures, DrawsPngAndSvgWithGnuplot) {
  if (!gnuplotAvailable()) GTEST_SKIP() << "gnuplot not installed";
  const Scene scene = balanced();
  const fs::path dir = fs::temp_directory_path() / ("rollerdyn-figures-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  { std::ofstream(dir / "comparison_omega_crank.png") << "stale figure of an earlier plot"; }
  { std::ofstream(dir / "notes.txt") << "someone else's file"; }
  const FigureSet set = drawRunFigures(syntheticFolder(scene), &scene, dir.string());
  EXPECT_FALSE(fs::exists(dir / "comparison_omega_crank.png")) << "stale figure left in place";
  EXPECT_TRUE(fs::exists(dir / "notes.txt")) << "removed a file that is not a figure of ours";
  fs::remove(dir / "notes.txt");
  ASSERT_EQ(set.figures.size(), 16u);
  for (const FigureFile& f : set.figures) {
    std::ifstream png(f.png, std::ios::binary);
    char sig[8] = {};
    png.read(sig, 8);
    EXPECT_EQ(std::string(sig, 8), "\x89PNG\r\n\x1a\n") << f.png;
    EXPECT_GT(fs::file_size(f.svg), 1000u) << f.svg;
  }
  // Only the figures: no scripts or temporaries left behind.
  size_t files = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    ++files;
    EXPECT_TRUE(e.path().extension() == ".png" || e.path().extension() == ".svg") << e.path();
  }
  EXPECT_EQ(files, 32u);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rollerdyn
