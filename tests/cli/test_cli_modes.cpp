// `rollerdyn modes` and `simulate --modes` as a user runs them; the resonance verdict of simulate.
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

// The two-mass check puts p0 = 4.0ω (c = 72.9 kN·m/rad), an order four equal carts at 90° excite,
// and warns; with k = 8000 N·m·s/rad the coupling mode is overdamped (ζ ≈ 1.7), and the analysis of
// the drive says so: the first estimate is labelled as such (once) and the verdict says why there
// is no resonance although the order meets the band.
TEST(CliModes, SimulateLabelsTheFirstEstimateAndGivesTheVerdict) {
  TempDir out("sim-modes");
  const auto r = runRollerdyn(
      {"simulate", model("balanced-4cart.yaml"), "--set", "coupling.stiffness=72900", "--modes", "--out", out.str()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: first estimate (two constant inertias"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("warning: torsional resonance: coupling natural frequency"), std::string::npos)
      << "the two-mass warning is printed only with its label\n" << r.err;
  EXPECT_NE(r.err.find("resonance verdict: no torsional resonance"), std::string::npos) << r.err;
  // p0 = 4ω by the two-mass check; the verdict names order 4 and the damping that keeps it from resonating.
  EXPECT_NE(r.err.find("below order 4, the lowest order the layout excites"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("no resonance peak"), std::string::npos) << r.err;
  const auto s = nlohmann::json::parse(slurp(out.path() / "summary.json"));
  ASSERT_TRUE(s.contains("modes"));
  ASSERT_TRUE(s.contains("resonance_modal"));
  EXPECT_TRUE(s["resonance_modal"]["warnings"].empty());
  int labelled = 0;
  for (const auto& w : s["warnings"]) labelled += w.get<std::string>().rfind("first estimate", 0) == 0 ? 1 : 0;
  EXPECT_EQ(labelled, 1) << s["warnings"].dump(1);
  EXPECT_TRUE(fs::exists(out.path() / "spectrum.csv"));
  EXPECT_TRUE(s["order_spectrum"]["signals"].contains("F_rod_1"));
}
