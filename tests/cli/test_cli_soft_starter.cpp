// A soft starter's current limit as the user meets it on the command line. The trial: initial
// voltage 0.35, a 2 s ramp and a current limit that holds the motor below breakaway; at the ramp's
// end full voltage came on, a direct-on-line start the output never mentioned. Now the limit holds
// until the motor is up to speed, and a start that cannot finish within the starter's maximum
// start time trips it: a failed start, exit 4, said alike by the status, the start-up block and
// summary.json.
#include <gtest/gtest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "cli/CliTestSupport.h"

namespace rollerdyn {
namespace {

using test::model;
using test::runRollerdyn;
using test::slurp;
using test::TempDir;

TEST(CliSoftStarter, AStartTheLimitCannotFinishTripsTheStarterAndExitsWith4) {
  TempDir out("soft-trip");
  // The six-cart trial's design: six carts of 1200 kg at 60°, μ_r = 0.1.
  const auto r = runRollerdyn({"simulate", model("balanced-4cart.yaml"), "--model", "reduced", "--set", "carts.count=6",
                               "--set", "crank.offset_deg=60", "--set", "carts.mass=1200", "--set",
                               "loads.rolling_resistance=0.1", "--set", "motor.model=circuit", "--set",
                               "motor.start.method=soft_starter", "--set", "motor.start.initial_voltage=0.35", "--set",
                               "motor.start.ramp_time=2", "--set", "motor.start.current_limit=150", "--set",
                               "motor.start.max_start_time=3", "--set", "simulation.t_end=6", "--out", out.str()},
                              120);
  EXPECT_EQ(r.exit_code, 4) << r.out << r.err;
  const auto j = nlohmann::json::parse(slurp(out.path() / "summary.json"));
  const std::string status = j["status"];
  EXPECT_EQ(status.rfind("the soft starter tripped at t = 3 s: the motor had not reached the rotor speed ", 0), 0u)
      << status;
  EXPECT_NE(status.find("within motor.start.max_start_time = 3 s of the switch-on"), std::string::npos) << status;
  EXPECT_EQ(j["motion"], "stalled");
  const auto& su = j["start_up"];
  EXPECT_EQ(su["starts"], false);
  EXPECT_EQ(su["verdict"].get<std::string>().rfind("the drive does not start: the soft starter tripped at t = 3 s", 0),
            0u)
      << su["verdict"];
  EXPECT_EQ(su["current_limit"]["outcome"], "tripped");
  EXPECT_EQ(su["current_limit"]["held_time"], 3.0);
  EXPECT_NE(su["verdict"].get<std::string>().find("so the motor cannot break away"), std::string::npos) << su["verdict"];
  // The console says the same: status, the verdict, the limit's line.
  EXPECT_NE(r.out.find("the soft starter tripped at t = 3 s"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("current limit I_lim           150 A held 3 s from switch-on, until the starter tripped at t = 3 s"),
            std::string::npos)
      << r.out;
}

// A key the chosen method would ignore is refused on the command line too, naming key and method.
TEST(CliSoftStarter, AChangeoverSpeedWithASoftStarterIsRefused) {
  const auto r = runRollerdyn({"simulate", model("balanced-4cart.yaml"), "--model", "reduced", "--set",
                               "motor.start.method=soft_starter", "--set", "motor.start.initial_voltage=0.35", "--set",
                               "motor.start.ramp_time=2", "--set", "motor.start.changeover_speed=95"},
                              60);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("motor.start.changeover_speed: expected no motor.start.changeover_speed with motor.start.method "
                       "soft_starter (only a star_delta start changes over"),
            std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace rollerdyn
