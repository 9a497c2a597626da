// What the command line tells about the guide friction: `check` names the rod angle, the
// transmission angle and the self-locking index and warns near dead centre (r/l = 0.995 was
// accepted silently before); every reduced result names its guide normal forces; a quasi-static
// reduced run whose friction work is off warns on stderr and in summary.json.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli/CliTestSupport.h"

namespace rollerdyn {
namespace {

using namespace test;

TEST(CliFriction, CheckWarnsNearDeadCentreAndPrintsTheMargins) {
  const auto r = runRollerdyn({"check", model("balanced-4cart.yaml"), "--set", "rods.length=0.201"}, 60);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("smallest transmission angle 5.72°"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("self-locking index"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("warning: crank-slider close to dead centre: r/l = 0.995"), std::string::npos) << r.err;
  // The shipped geometry: margins printed, no warning.
  const auto ok = runRollerdyn({"check", model("balanced-4cart.yaml")}, 60);
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_NE(ok.out.find("self-locking index"), std::string::npos) << ok.out;
  EXPECT_EQ(ok.err.find("warning"), std::string::npos) << ok.err;
  // What is built, in words with the scene key that sets it: the trial read the builder's class
  // names (KlossMotor, ElasticCoupling(spring+damper)) and identifiers (rods_distributed).
  EXPECT_NE(ok.out.find("  induction motor, Kloss formula (motor.model: kloss)\n"), std::string::npos) << ok.out;
  EXPECT_NE(ok.out.find("  guide friction (loads.guide_friction)\n"), std::string::npos) << ok.out;
  for (const char* internal : {"KlossMotor", "ElasticCoupling", "GuideFriction", "rods_distributed", "kloss_motor"})
    EXPECT_EQ(ok.out.find(internal), std::string::npos) << internal << " in: " << ok.out;
}

TEST(CliFriction, ReducedResultsNameTheirNormalForcesAndWarnWhenQuasiStaticIsOff) {
  TempDir dir("friction");
  const auto r = runRollerdyn({"simulate", model("balanced-4cart.yaml"), "--model", "reduced", "--set",
                               "rods.length=0.2105263157894737", "--set", "reduced.guide_normals=quasi_static",
                               "--out", dir.str()},
                              120);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("guide normal forces  quasi-static"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("quasi-static normal forces (no inertial forces): its friction work"), std::string::npos) << r.err;
  const nlohmann::json s = nlohmann::json::parse(slurp(dir.path() / "summary.json"));
  EXPECT_GT(s["guide_friction"]["friction_work_deviation"].get<double>(), 0.3);
  EXPECT_NE(s["guide_normal_forces"].get<std::string>().find("quasi-static"), std::string::npos);
  bool in_json = false;
  for (const auto& w : s["warnings"]) in_json = in_json || w.get<std::string>().find("friction work") != std::string::npos;
  EXPECT_TRUE(in_json);
}

// A machine without a motor that friction brings to rest: both models end with the rest rule's
// status, the motion at_rest on the console and in summary.json with the self-locking warning, and
// exit code 0 (a finished run, not a failed one: it was 3 before).
TEST(CliFriction, AMachineThatFrictionStopsIsAtRestWithExitCodeZero) {
  for (const char* m : {"reduced", "multibody"}) {
    TempDir dir("at-rest");
    const auto r = runRollerdyn({"simulate", model("balanced-4cart.yaml"), "--model", m, "--set",
                                 "loads.guide_friction.coefficient=0.3", "--set", "motor.enabled=false", "--set",
                                 "initial.crank_speed=10.42", "--out", dir.str()},
                                120);
    EXPECT_EQ(r.exit_code, 0) << m << ": " << r.err;
    EXPECT_NE(r.out.find("motion       at_rest"), std::string::npos) << r.out;
    EXPECT_NE(r.err.find("guide friction near self-locking"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("integrator failure"), std::string::npos) << r.err;
    const nlohmann::json s = nlohmann::json::parse(slurp(dir.path() / "summary.json"));
    EXPECT_EQ(s["motion"], "at_rest") << m;
    EXPECT_EQ(s["status"].get<std::string>().rfind("the machine came to rest at t = 0.82 s", 0), 0u) << s["status"];
    bool warned = false;
    for (const auto& w : s["warnings"]) warned = warned || w.get<std::string>().find("self-locking") != std::string::npos;
    EXPECT_TRUE(warned) << m;
  }
}

}  // namespace
}  // namespace rollerdyn
