// A stalled and a rocking run are named as such everywhere a user looks: the console summary,
// summary.json, the HTML report and the sweep lines and files (Loveikin, Pochka, Romasevych (2018)
// balanced drive: the opposing-velocity reading of the roller forces stalls it, Δφ = 0 rocks it).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <string>

#include "cli/CliTestSupport.h"

namespace rollerdyn {
namespace {

using test::model;
using test::runRollerdyn;
using test::slurp;
using test::TempDir;

TEST(CliMotion, StalledRunSaysSoAndWhyInConsoleJsonAndReport) {
  TempDir out("stalled");
  const auto r = runRollerdyn({"simulate", model("balanced-4cart.yaml"), "--model", "reduced", "--set",
                               "loads.roller_force_direction=opposes_velocity", "--out", out.str()});
  EXPECT_EQ(r.exit_code, 3) << r.out << r.err;
  EXPECT_NE(r.out.find("motion       stalled"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("the drive stalled: starting torque at the crank"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("δ (unevenness) n/a"), std::string::npos) << r.out;
  const auto j = nlohmann::json::parse(slurp(out.path() / "summary.json"));
  EXPECT_EQ(j["motion"], "stalled");
  EXPECT_TRUE(j["delta"].is_null());
  EXPECT_TRUE(j["k_p"].is_null());
  // The mean load of the four carts (≈ 8.2 kN·m) is above the breakdown torque at the crank,
  // M_kr·u·η = 517.14·9.8·0.9 = 4561 N·m.
  EXPECT_NEAR(j["stall"]["breakdown_torque_crank"].get<double>(), 517.14 * 9.8 * 0.9, 1e-6);
  EXPECT_GT(j["stall"]["load_torque_mean"].get<double>(), 517.14 * 9.8 * 0.9);

  TempDir rep("stalled-report");
  const auto h = runRollerdyn({"report", model("balanced-4cart.yaml"), "--set",
                               "loads.roller_force_direction=opposes_velocity", "--out", rep.str()});
  EXPECT_EQ(h.exit_code, 3) << h.out << h.err;
  const std::string html = slurp(rep.path() / "report.html");
  EXPECT_NE(html.find("Motion of the crank: <b>stalled</b>"), std::string::npos);
  EXPECT_NE(html.find("Why the drive stalled: starting torque at the crank"), std::string::npos);
}

TEST(CliMotion, RockingRunIsNamedInConsoleJsonReportAndSweep) {
  TempDir rep("rocking-report");
  const auto h = runRollerdyn({"report", model("balanced-4cart.yaml"), "--set", "crank.offset_deg=0", "--set",
                               "simulation.t_end=4", "--out", rep.str()});
  EXPECT_EQ(h.exit_code, 0) << h.out << h.err;
  EXPECT_NE(h.out.find("motion       rocking"), std::string::npos) << h.out;
  const auto j = nlohmann::json::parse(slurp(rep.path() / "summary.json"));
  EXPECT_EQ(j["motion"], "rocking");
  EXPECT_TRUE(j["delta"].is_null());
  const std::string html = slurp(rep.path() / "report.html");
  EXPECT_NE(html.find("Motion of the crank: <b>rocking</b>"), std::string::npos);

  TempDir sw("rocking-sweep");
  const auto s = runRollerdyn({"sweep", model("balanced-4cart.yaml"), "--param", "crank.offset_deg", "--values",
                               "0,90", "--model", "reduced", "--set", "simulation.t_end=6", "--out", sw.str()});
  EXPECT_EQ(s.exit_code, 0) << s.out << s.err;
  EXPECT_NE(s.out.find("crank.offset_deg=0  δ n/a  H n/a  k_p n/a"), std::string::npos) << s.out;
  EXPECT_NE(s.out.find("rocking"), std::string::npos) << s.out;
  EXPECT_NE(s.out.find("turning, steady"), std::string::npos) << s.out;
  EXPECT_NE(slurp(sw.path() / "sweep.csv").find(",rocking,"), std::string::npos);
}

}  // namespace
}  // namespace rollerdyn
