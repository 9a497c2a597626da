// summary.json: required keys, values carried through, valid JSON with NaN/inf input, atomic
// write, and the terminal text.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "analysis/Summary.h"

using namespace rollerdyn;
using nlohmann::json;

namespace {

constexpr double kPi = 3.14159265358979323846;

Scene testScene() {
  Scene s{};
  s.name = "synthetic-2cart";
  s.simulation.steady_window_revolutions = 3;
  s.motor.enabled = true;
  s.coupling.type = CouplingType::Elastic;
  s.coupling.damping = 2000;
  s.rods.model = RodModel::Split;
  return s;
}

// Steady sinusoidal crank motion ω = 10 + 0.5·sin(20t) over 10 revolutions (see test_metrics).
RunResult testRun() {
  RunResult r;
  r.model = "reduced";
  r.integrator = "cvode";
  r.effects = {"kloss_motor", "elastic_coupling"};
  r.timeseries.columns = {"t", "phi_crank", "omega_crank", "eps_crank", "twist", "twist_rate",
                          "twist_accel", "coupling_torque"};
  r.reactions.columns = {"t", "F_rod_1"};
  const double w0 = 10, A = 0.5, t_end = 10 * 2 * kPi / w0 + 0.2;
  for (int i = 0; i * 1e-3 <= t_end; ++i) {
    const double t = i * 1e-3, s = std::sin(2 * w0 * t), c = std::cos(2 * w0 * t);
    r.timeseries.rows.push_back({t, w0 * t + A / (2 * w0) * (1 - c), w0 + A * s, 2 * w0 * A * c,
                                 1e-3 * s, 0.02 * c, -0.4 * s, 300 + 150 * s});
    r.reactions.rows.push_back({t, -2000 + 500 * s});
  }
  r.stats.steps = 1234;
  r.stats.realizations = 5678;
  r.stats.cpu_seconds = 0.5;
  r.stats.constraint_error_max = 1e-10;
  r.energy.motor_work = 1000;
  r.energy.load_work = 900;
  r.energy.damping_dissipation = 60;
  r.energy.kinetic_final = 40;  // residual 0
  return r;
}

const char* kRequired[] = {
    "scene", "model", "integrator", "effects", "status", "complete", "omega_crank",
    "eps_crank_abs_max", "delta", "H", "k_p", "coupling_torque_swing", "twist_swing",
    "twist_rate_swing", "twist_accel_swing", "steady_state", "energy", "energy_residual_rel",
    "constraint_error_max", "steps", "realizations", "cpu_seconds", "real_time_factor",
    "reactions"};

}  // namespace

TEST(Summary, HasRequiredKeysAndValues) {
  const json j = makeSummary(testScene(), testRun());
  for (const char* k : kRequired) EXPECT_TRUE(j.contains(k)) << "missing key " << k;
  for (const char* k : {"min", "max", "mean"}) EXPECT_TRUE(j["omega_crank"].contains(k)) << k;
  for (const char* k : {"reached", "after_revolutions", "window_revolutions", "t_begin", "t_end"})
    EXPECT_TRUE(j["steady_state"].contains(k)) << k;
  for (const char* k : {"motor_work", "damping_dissipation", "friction_dissipation", "load_work",
                        "kinetic_change", "potential_change", "residual"})
    EXPECT_TRUE(j["energy"].contains(k)) << k;

  EXPECT_EQ(j["scene"], "synthetic-2cart");
  EXPECT_EQ(j["model"], "reduced");
  EXPECT_EQ(j["integrator"], "cvode");
  EXPECT_EQ(j["effects"], json(testScene().effects()));
  EXPECT_EQ(j["status"], "completed");
  EXPECT_TRUE(j["non_finite"].empty());
  EXPECT_TRUE(j["complete"].get<bool>());
  EXPECT_NEAR(j["omega_crank"]["mean"].get<double>(), 10.0, 1e-5);
  EXPECT_NEAR(j["delta"].get<double>(), 0.1, 1e-4);   // 2A/ω0
  EXPECT_NEAR(j["H"].get<double>(), 0.1, 1e-4);       // 2ω0A/ω0²
  EXPECT_NEAR(j["k_p"].get<double>(), 0.11, 1e-4);
  EXPECT_NEAR(j["coupling_torque_swing"].get<double>(), 300.0, 0.1);
  EXPECT_TRUE(j["steady_state"]["reached"].get<bool>());
  EXPECT_EQ(j["steady_state"]["window_revolutions"], 3);
  EXPECT_DOUBLE_EQ(j["energy"]["kinetic_change"].get<double>(), 40.0);
  EXPECT_DOUBLE_EQ(j["energy"]["residual"].get<double>(), 0.0);
  EXPECT_EQ(j["steps"], 1234);
  EXPECT_EQ(j["realizations"], 5678);
  EXPECT_TRUE(j["jacobian_evaluations"].is_null());  // not counted by this integrator
  EXPECT_TRUE(j["newton_convergence_failures"].is_null());
  const double simulated = j["simulated_time"].get<double>();
  EXPECT_NEAR(j["real_time_factor"].get<double>(), simulated / 0.5, 1e-9);
  ASSERT_TRUE(j["reactions"].contains("F_rod_1"));
  EXPECT_NEAR(j["reactions"]["F_rod_1"]["abs_max"].get<double>(), 2500.0, 0.5);
  EXPECT_NEAR(j["reactions"]["F_rod_1"]["mean"].get<double>(), -2000.0, 1.0);
  EXPECT_FALSE(j["reactions"].contains("t"));
}

TEST(Summary, NewtonCountersAreWrittenWhenCounted) {
  RunResult r = testRun();
  r.stats.jacobian_evaluations = 12;
  r.stats.newton_convergence_failures = 3;
  const json j = makeSummary(testScene(), r);
  EXPECT_EQ(j["jacobian_evaluations"], 12);
  EXPECT_EQ(j["newton_convergence_failures"], 3);
}

TEST(Summary, NaNInputGivesValidJsonWithNullsAndStatusSaysSo) {
  RunResult run = testRun();
  run.energy.motor_work = NAN;
  run.stats.constraint_error_max = INFINITY;
  const int k_eps = run.timeseries.index("eps_crank");
  for (auto& row : run.timeseries.rows) row[k_eps] = NAN;  // ε unknown in the window
  const json j = makeSummary(testScene(), run);

  const std::string text = j.dump(2);
  json back;
  ASSERT_NO_THROW(back = json::parse(text)) << text;
  EXPECT_EQ(text.find("nan"), std::string::npos);
  EXPECT_EQ(text.find("inf"), std::string::npos);
  EXPECT_TRUE(back["energy"]["motor_work"].is_null());
  EXPECT_TRUE(back["energy"]["residual"].is_null());
  EXPECT_TRUE(back["constraint_error_max"].is_null());
  EXPECT_TRUE(back["eps_crank_abs_max"].is_null());
  EXPECT_TRUE(back["H"].is_null());
  EXPECT_TRUE(back["k_p"].is_null());
  EXPECT_TRUE(back["delta"].is_number());  // δ does not need ε
  const std::string status = back["status"];
  EXPECT_EQ(status.rfind("completed", 0), 0u) << status;
  EXPECT_NE(status.find("non-finite"), std::string::npos) << status;
  EXPECT_NE(status.find("energy.motor_work"), std::string::npos) << status;
  EXPECT_NE(status.find("constraint_error_max"), std::string::npos) << status;
  for (const char* k : kRequired) EXPECT_TRUE(back.contains(k)) << "missing key " << k;
}

TEST(Summary, TurningCrankIsReportedAsTurning) {
  const json j = makeSummary(testScene(), testRun());
  EXPECT_EQ(j["crank_motion"], "turning");
  EXPECT_EQ(j["status"], "completed");
}

// A crank that swings back and forth (Loveikin, Pochka, Romasevych (2018) at small Δφ): the run completes, but the summary
// must say that the crank does not turn, in crank_motion and in the status line.
TEST(Summary, RockingCrankIsReportedInStatus) {
  RunResult run = testRun();
  run.timeseries.rows.clear();
  for (int i = 0; i * 1e-3 <= 10.0; ++i) {
    const double t = i * 1e-3;  // φ = 0.3·sin(3t): never a whole revolution
    run.timeseries.rows.push_back({t, 0.3 * std::sin(3 * t), 0.9 * std::cos(3 * t),
                                   -2.7 * std::sin(3 * t), 0, 0, 0, 100});
  }
  const json j = makeSummary(testScene(), run);
  EXPECT_EQ(j["crank_motion"], "rocking");
  EXPECT_FALSE(j["steady_state"]["reached"].get<bool>());
  const std::string status = j["status"];
  EXPECT_EQ(status.rfind("completed", 0), 0u) << status;
  EXPECT_NE(status.find("rocks back and forth"), std::string::npos) << status;
}

TEST(Summary, BlownUpTimeseriesIsFlaggedInStatus) {
  RunResult run = testRun();
  const int k = run.timeseries.index("omega_crank");
  for (std::size_t i = 5000; i < run.timeseries.rows.size(); ++i) run.timeseries.rows[i][k] = NAN;
  const json j = makeSummary(testScene(), run);
  EXPECT_NO_THROW(json::parse(j.dump()));
  EXPECT_NE(j["status"].get<std::string>().find("non-finite"), std::string::npos);
}

TEST(Summary, EmptyRunStillGivesAllKeys) {
  RunResult run;
  run.model = "multibody";
  run.stats.complete = false;
  run.stats.status = "failed at t = 0";
  const json j = makeSummary(testScene(), run);
  for (const char* key : kRequired) EXPECT_TRUE(j.contains(key)) << "missing key " << key;
  EXPECT_NO_THROW(json::parse(j.dump()));
  EXPECT_FALSE(j["steady_state"]["reached"].get<bool>());
  EXPECT_TRUE(j["real_time_factor"].is_null());  // cpu_seconds = 0: not measured
  EXPECT_NO_THROW(summaryText(j));
}

TEST(Summary, WriteSummaryAtomicWritesPrettyJson) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("rollerdyn_summary_" + std::to_string(::getpid()));
  const std::string path = (dir / "out" / "summary.json").string();
  const json j = makeSummary(testScene(), testRun());
  writeSummaryAtomic(path, j);
  std::ifstream in(path);
  std::stringstream buf;
  buf << in.rdbuf();
  const std::string text = buf.str();
  EXPECT_EQ(json::parse(text), j);
  EXPECT_NE(text.find("\n  \"H\": "), std::string::npos) << "expected 2-space indent";
  for (const auto& e : fs::directory_iterator(dir / "out"))
    EXPECT_EQ(e.path().filename(), "summary.json") << "temporary file left behind";
  fs::remove_all(dir);
}

TEST(Summary, TextMentionsSceneStatusAndKeyNumbers) {
  RunResult run = testRun();
  run.stats.status = "interrupted at t = 3.2 s";
  run.stats.complete = false;
  const json j = makeSummary(testScene(), run);
  const std::string text = summaryText(j);
  EXPECT_NE(text.find("interrupted at t = 3.2 s"), std::string::npos) << text;
  EXPECT_NE(text.find("motion       turning"), std::string::npos) << text;
  EXPECT_NE(text.find("synthetic-2cart"), std::string::npos) << text;
  EXPECT_NE(text.find("reduced"), std::string::npos) << text;
  EXPECT_NE(text.find("δ (unevenness) 0.1"), std::string::npos) << text;
  EXPECT_NE(text.find("real-time factor"), std::string::npos) << text;
  const auto lines = std::count(text.begin(), text.end(), '\n');
  EXPECT_GE(lines, 8);
  EXPECT_LE(lines, 12);
}
