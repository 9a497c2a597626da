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
  EXPECT_EQ(r.exit_code, 4) << r.out << r.err;  // the drive does not turn (3: a numerical failure)
  EXPECT_NE(r.out.find("motion       stalled"), std::string::npos) << r.out;
  // The 6-cart trial: a locked rotor passed both motor checks. No check of a stalled drive passes.
  EXPECT_NE(r.out.find("motor_heating"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find(" pass "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("the drive stalled: the motor's starting torque 1032 N·m at the crank"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("run at least"), std::string::npos) << r.out;  // running longer does not help a stall
  EXPECT_NE(r.out.find("δ (unevenness) n/a"), std::string::npos) << r.out;
  const auto j = nlohmann::json::parse(slurp(out.path() / "summary.json"));
  EXPECT_EQ(j["motion"], "stalled");
  EXPECT_TRUE(j["delta"].is_null());
  EXPECT_TRUE(j["k_p"].is_null());
  // The mean load of the four carts (≈ 8.2 kN·m) is above the breakdown torque at the crank,
  // M_kr·u·η = 517.14·9.8·0.9 = 4561 N·m.
  EXPECT_NEAR(j["stall"]["breakdown_torque_crank"].get<double>(), 517.14 * 9.8 * 0.9, 1e-6);
  EXPECT_GT(j["stall"]["load_torque_mean"].get<double>(), 517.14 * 9.8 * 0.9);
  for (const auto& c : j["sizing"]["checks"]) EXPECT_NE(c["verdict"], "pass") << c.dump();
  EXPECT_EQ(j["sizing"]["motor"]["rms_check"], "FAIL");
  EXPECT_EQ(j["sizing"]["motor"]["peak_check"], "FAIL");

  TempDir rep("stalled-report");
  const auto h = runRollerdyn({"report", model("balanced-4cart.yaml"), "--set",
                               "loads.roller_force_direction=opposes_velocity", "--out", rep.str()});
  EXPECT_EQ(h.exit_code, 4) << h.out << h.err;
  const std::string html = slurp(rep.path() / "report.html");
  EXPECT_NE(html.find("Motion of the crank: <b>stalled</b>"), std::string::npos);
  EXPECT_NE(html.find("Why the drive stalled: the motor&#39;s starting torque 1032 N·m at the crank"), std::string::npos);
  // The report shows the checks with their deciding window, none of them passed.
  EXPECT_NE(html.find("<h3>Checks</h3>"), std::string::npos);
  EXPECT_EQ(html.find("class=\"ok\">pass"), std::string::npos);
  EXPECT_NE(html.find("<h3>Technological load</h3>"), std::string::npos);
}

// At Δφ = 0 the swings grow until ~6.6 s and stop growing by ~8 s (before that the start is
// undecided, "starting"): 12 s runs end early as rocking.
TEST(CliMotion, RockingRunIsNamedInConsoleJsonReportAndSweep) {
  TempDir rep("rocking-report");
  const auto h = runRollerdyn({"report", model("balanced-4cart.yaml"), "--set", "crank.offset_deg=0", "--set",
                               "simulation.t_end=12", "--out", rep.str()});
  EXPECT_EQ(h.exit_code, 4) << h.out << h.err;  // a drive that rocks does not work
  EXPECT_NE(h.out.find("motion       rocking"), std::string::npos) << h.out;
  const auto j = nlohmann::json::parse(slurp(rep.path() / "summary.json"));
  EXPECT_EQ(j["motion"], "rocking");
  EXPECT_TRUE(j["delta"].is_null());
  const std::string html = slurp(rep.path() / "report.html");
  EXPECT_NE(html.find("Motion of the crank: <b>rocking</b>"), std::string::npos);

  TempDir sw("rocking-sweep");
  const auto s = runRollerdyn({"sweep", model("balanced-4cart.yaml"), "--param", "crank.offset_deg", "--values",
                               "0,90", "--model", "reduced", "--set", "simulation.t_end=12", "--out", sw.str()});
  EXPECT_EQ(s.exit_code, 4) << s.out << s.err;  // every point ran; one drive rocks
  EXPECT_NE(s.out.find("crank.offset_deg=0  δ n/a  H n/a  k_p n/a"), std::string::npos) << s.out;
  EXPECT_NE(s.out.find("rocking"), std::string::npos) << s.out;
  EXPECT_NE(s.out.find("turning, steady"), std::string::npos) << s.out;
  EXPECT_NE(slurp(sw.path() / "sweep.csv").find(",rocking,"), std::string::npos);
}

// A drive that can never start must not eat minutes: at Δφ = 0 the balanced drive rocks with
// swings that stop growing; asked for 60 s, the run ends within a few periods of that, in both
// models at the same time (one rule).
TEST(CliMotion, HopelessRockingEndsEarlyInBothModels) {
  for (const char* m : {"reduced", "multibody"}) {
    TempDir out(std::string("hopeless-") + m);
    const auto r = runRollerdyn({"simulate", model("balanced-4cart.yaml"), "--model", m, "--set", "crank.offset_deg=0",
                                 "--set", "simulation.t_end=60", "--set", "simulation.reactions=false", "--out",
                                 out.str()},
                                120);
    EXPECT_EQ(r.exit_code, 4) << r.out << r.err;
    const auto j = nlohmann::json::parse(slurp(out.path() / "summary.json"));
    EXPECT_EQ(j["motion"], "rocking") << m;
    EXPECT_LT(j["simulated_time"].get<double>(), 15.0) << m;
    EXPECT_NE(j["status"].get<std::string>().find("swings no longer grow"), std::string::npos) << j["status"];
  }
}

}  // namespace
}  // namespace rollerdyn
