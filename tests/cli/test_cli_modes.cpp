// `rollerdyn modes` and `simulate --modes` as a user runs them; the resonance verdict of simulate.
#include <cstdio>
#include <cstring>
#include <filesystem>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli/CliTestSupport.h"

using namespace rollerdyn::test;
namespace fs = std::filesystem;

TEST(CliModes, WritesItsFilesForTheBalancedMachine) {
  TempDir out("modes");
  const auto r = runRollerdyn({"modes", model("balanced-4cart.yaml"), "--grid", "4x3", "--speeds", "5", "--out", out.str()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* f : {"modes.json", "frozen.csv", "campbell.csv", "stability.csv"})
    EXPECT_TRUE(fs::exists(out.path() / f)) << f;
  const auto j = nlohmann::json::parse(slurp(out.path() / "modes.json"));
  EXPECT_EQ(j["steady_motion"]["verdict"], "stable");
  EXPECT_EQ(j["excitation_orders"]["layout"], (std::vector<int>{4, 8, 12, 16, 20, 24}));
  EXPECT_EQ(j["frozen_angle_modes"].size(), 2u);  // both models
  EXPECT_EQ(j["stability_charts"].size(), 2u);    // c x omega at the scene's k, c x k
  EXPECT_NE(r.out.find("Floquet (reduced): stable"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("first estimate, two constant inertias"), std::string::npos);
}

TEST(CliModes, WarnsOfParametricResonance) {
  TempDir out("modes-unstable");
  const auto r = runRollerdyn({"modes", model("recuperative-2cart.yaml"), "--set", "coupling.type=elastic", "--set",
                               "coupling.stiffness=24000", "--set", "coupling.damping=0", "--no-charts", "--speeds", "3",
                               "--out", out.str()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: parametric resonance"), std::string::npos) << r.err;
  const auto j = nlohmann::json::parse(slurp(out.path() / "modes.json"));
  EXPECT_EQ(j["steady_motion"]["verdict"], "parametrically unstable");
  EXPECT_GT(j["steady_motion"]["max_modulus"].get<double>(), 1.0);
}

TEST(CliModes, BadGridIsAUsageError) {
  const auto r = runRollerdyn({"modes", model("balanced-4cart.yaml"), "--grid", "4by3"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--grid"), std::string::npos) << r.err;
}

// The two-mass check puts p0 = 4.0ω (c = 72.9 kN·m/rad), an order four equal carts at 90° excite;
// with k = 8000 N·m·s/rad the coupling mode is overdamped and the modal analysis refutes it. One
// answer: no warning (the trials saw the first estimate's warning on every run the analysis
// refuted, with another ω than the verdict's), a verdict line that says the analysis refutes the
// first estimate and why, every crank speed in it the run's steady mean one.
TEST(CliModes, AFirstEstimateTheModalAnalysisRefutesIsNoWarningAndUsesTheRunsOmega) {
  TempDir out("sim-modes");
  const auto r = runRollerdyn(
      {"simulate", model("balanced-4cart.yaml"), "--set", "coupling.stiffness=72900", "--modes", "--out", out.str()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("warning: first estimate"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("resonance: coupling natural frequency"), std::string::npos) << r.err;
  const std::string tag = "resonance verdict: the modal analysis refutes the first estimate";
  const auto at = r.err.find(tag);
  ASSERT_NE(at, std::string::npos) << r.err;
  const std::string line = r.err.substr(at, r.err.find('\n', at) - at);
  EXPECT_NE(line.find("no resonance peak"), std::string::npos) << line;
  const auto s = nlohmann::json::parse(slurp(out.path() / "summary.json"));
  char w[32];
  std::snprintf(w, sizeof w, "omega = %.4g rad/s", s["omega_crank"]["mean"].get<double>());
  for (std::size_t i = line.find("omega = "); i != std::string::npos; i = line.find("omega = ", i + 1))
    if (i == 0 || (line[i - 1] != '*' && line[i - 1] != '/'))  // not "k*omega = ", "p/omega = "
      EXPECT_EQ(line.compare(i, std::strlen(w), w), 0) << "expected " << w << " in: " << line;
  char k4[48];
  std::snprintf(k4, sizeof k4, "4*omega = %.4g rad/s", 4 * s["omega_crank"]["mean"].get<double>());
  EXPECT_NE(line.find(k4), std::string::npos) << line;
  EXPECT_EQ(s["resonance_verdict"]["verdict"], "no resonance");
  EXPECT_EQ(s["resonance"]["status"], "refuted by the modal analysis");
  for (const auto& x : s["warnings"]) EXPECT_EQ(x.get<std::string>().find("first estimate"), std::string::npos) << x;
  EXPECT_TRUE(fs::exists(out.path() / "spectrum.csv"));
  EXPECT_TRUE(s["order_spectrum"]["signals"].contains("F_rod_1"));
}

// A drive that does not turn has no steady motion: no stability verdict (the report showed a green
// "the steady motion is stable" under a red "Run INCOMPLETE: motor stalled"). Six carts of 1200 kg
// with μ_r = 0.1: the starting torque at the crank, 1032 N·m, is below the load at the start angle,
// so the drive stalls at once, while the motor would carry the mean load running (its breakdown
// torque 4561 N·m): the modal analysis of the scene finds a stable steady motion the run never has.
TEST(CliModes, AStalledDriveHasNoStabilityVerdictInSummaryConsoleOrReport) {
  const std::vector<std::string> sets = {"--set", "carts.count=6",         "--set", "crank.offset_deg=60",
                                         "--set", "carts.mass=1200",       "--set", "loads.rolling_resistance=0.1",
                                         "--set", "simulation.t_end=3"};
  TempDir out("stalled-modes");
  std::vector<std::string> args = {"simulate", model("balanced-4cart.yaml"), "--model", "reduced", "--modes",
                                   "--out", out.str()};
  args.insert(args.end(), sets.begin(), sets.end());
  const auto r = runRollerdyn(args);
  ASSERT_EQ(r.exit_code, 4) << r.out << r.err;  // the drive does not turn
  const auto s = nlohmann::json::parse(slurp(out.path() / "summary.json"));
  ASSERT_EQ(s["motion"], "stalled");
  EXPECT_EQ(s["stability"]["verdict"], "not applicable");
  EXPECT_NE(s["stability"]["reason"].get<std::string>().find("does not turn"), std::string::npos);
  EXPECT_EQ(s["resonance_verdict"]["verdict"], "not applicable");
  EXPECT_FALSE(s["resonance_modal"].contains("conclusion")) << s["resonance_modal"].dump();
  EXPECT_EQ(s["modes"]["steady_motion"]["verdict"], "not applicable");
  EXPECT_EQ(r.out.find("Floquet (reduced): stable"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("stability of the steady motion n/a"), std::string::npos) << r.out;

  TempDir page("stalled-report");
  std::vector<std::string> rep = {"report", model("balanced-4cart.yaml"), "--out", page.str()};
  rep.insert(rep.end(), sets.begin(), sets.end());
  const auto rr = runRollerdyn(rep);
  ASSERT_EQ(rr.exit_code, 4) << rr.out << rr.err;
  const std::string html = slurp(page.path() / "report.html");
  EXPECT_EQ(html.find("steady motion is stable"), std::string::npos);
  EXPECT_EQ(html.find("Floquet verdict (reduced model)"), std::string::npos);
  EXPECT_NE(html.find("Stability of the steady motion (Floquet): n/a"), std::string::npos);
}
