// `rollerdyn motor`, end to end: the fit's table on the console, motor.json, the curves and
// catalogue CSV, the figures; a scene without machine data gives the Kloss curves only; usage
// and scene errors are exit 2 with one line.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#include "cli/CliTestSupport.h"

namespace rollerdyn {
namespace {

namespace fs = std::filesystem;
using test::model;
using test::runRollerdyn;
using test::slurp;
using test::TempDir;

TEST(CliMotor, FitsThePapersMotorAndWritesEverything) {
  TempDir out("motor");
  const auto r = runRollerdyn({"motor", model("balanced-4cart.yaml"), "--out", out.str()});
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("equivalent circuit fitted to motor.catalogue (double cage"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("per phase of the equivalent star"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("starting torque"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("the winding is in delta"), std::string::npos) << r.out;
  const auto j = nlohmann::json::parse(slurp(out.path() / "motor.json"));
  EXPECT_EQ(j["motor_model"], "kloss");
  ASSERT_EQ(j["catalogue_points"].size(), 7u);
  for (const auto& p : j["catalogue_points"]) {
    if (p["unit"] == "N·m") {
      EXPECT_LT(std::abs(p["relative_error"].get<double>()), 0.03) << p.dump();
    }
  }
  EXPECT_EQ(j["machine"]["cages"], 2);
  // Kloss's starting torque beside the catalogue's: the gap the circuit closes.
  EXPECT_LT(j["catalogue_points"][4]["kloss"].get<double>(), 0.5 * j["catalogue_points"][4]["catalogue"].get<double>());
  const std::string curves = slurp(out.path() / "motor_curves.csv");
  EXPECT_EQ(curves.rfind("slip[-],omega_rotor_kloss[rad/s],omega_rotor_circuit[rad/s],M_kloss[N*m],M_circuit[N*m],"
                         "M_park[N*m],I_circuit[A],I_park[A]\n", 0), 0u) << curves.substr(0, 200);
  EXPECT_EQ(std::count(curves.begin(), curves.end(), '\n'), 502);
  const std::string cat = slurp(out.path() / "motor_catalogue.csv");
  EXPECT_EQ(std::count(cat.begin(), cat.end(), '\n'), 8);
  if (r.out.find("gnuplot not found") == std::string::npos) {
    for (const char* f : {"motor_torque_slip.png", "motor_torque_slip.svg", "motor_current_slip.png", "motor_current_slip.svg"})
      EXPECT_TRUE(fs::exists(out.path() / f)) << f;
  }
}

TEST(CliMotor, SaysTheFitWasMadeNowThenThatItCameFromTheCache) {
  TempDir cache("fit-cache"), out("motor-cache");
  const char* before = std::getenv("ROLLERDYN_CACHE_DIR");
  const std::string old = before ? before : "";
  struct Restore {  // the variable as it was, whatever happens below
    std::string old;
    bool had;
    ~Restore() { had ? (void)::setenv("ROLLERDYN_CACHE_DIR", old.c_str(), 1) : (void)::unsetenv("ROLLERDYN_CACHE_DIR"); }
  } restore{old, before != nullptr};
  ::setenv("ROLLERDYN_CACHE_DIR", cache.str().c_str(), 1);  // inherited by the command; never the user's
  const auto first = runRollerdyn({"motor", model("balanced-4cart.yaml"), "--out", out.str()});
  ASSERT_EQ(first.exit_code, 0) << first.out << first.err;
  EXPECT_NE(first.out.find("  fitted now in "), std::string::npos) << first.out;
  EXPECT_NE(first.out.find(" s, kept in " + cache.str() + "/"), std::string::npos) << first.out;
  const auto second = runRollerdyn({"motor", model("balanced-4cart.yaml"), "--out", out.str()});
  ASSERT_EQ(second.exit_code, 0) << second.out << second.err;
  EXPECT_NE(second.out.find("  from the cache " + cache.str() + "/"), std::string::npos) << second.out;
  EXPECT_NE(second.out.find("(fitted on "), std::string::npos) << second.out;
  const auto j = nlohmann::json::parse(slurp(out.path() / "motor.json"));
  EXPECT_EQ(j["fit"]["origin"].get<std::string>().rfind("from the cache " + cache.str(), 0), 0u) << j["fit"].dump();
  // The table printed from the kept fit is the fitted one, digit for digit.
  const auto table = [](const std::string& text) { return text.substr(text.find("per phase of the equivalent star")); };
  EXPECT_EQ(table(first.out), table(second.out));
}

TEST(CliMotor, ARunsSummarySaysWhereItsFittedCircuitCameFrom) {
  TempDir cache("fit-cache-run"), circuit("run-circuit"), kloss("run-kloss");
  const char* before = std::getenv("ROLLERDYN_CACHE_DIR");
  const std::string old = before ? before : "";
  struct Restore {
    std::string old;
    bool had;
    ~Restore() { had ? (void)::setenv("ROLLERDYN_CACHE_DIR", old.c_str(), 1) : (void)::unsetenv("ROLLERDYN_CACHE_DIR"); }
  } restore{old, before != nullptr};
  ::setenv("ROLLERDYN_CACHE_DIR", cache.str().c_str(), 1);
  const std::vector<std::string> run = {"simulate", model("balanced-4cart.yaml"), "--model", "reduced", "--set",
                                        "simulation.t_end=0.5", "--set", "motor.model=circuit", "--out", circuit.str()};
  ASSERT_EQ(runRollerdyn(run).exit_code, 0);
  const auto first = nlohmann::json::parse(slurp(circuit.path() / "summary.json"))["motor_fit"];
  EXPECT_EQ(first["from_cache"], false) << first.dump();
  EXPECT_EQ(first["text"].get<std::string>().rfind("fitted now in ", 0), 0u) << first.dump();
  ASSERT_EQ(runRollerdyn(run).exit_code, 0);
  const auto second = nlohmann::json::parse(slurp(circuit.path() / "summary.json"))["motor_fit"];
  EXPECT_EQ(second["from_cache"], true) << second.dump();
  EXPECT_EQ(second["cache_file"], first["cache_file"]);
  EXPECT_EQ(second["fitted_on"], first["fitted_on"]);
  EXPECT_EQ(second["text"].get<std::string>().rfind("from the cache " + cache.str() + "/", 0), 0u) << second.dump();
  // Kloss's law is not fitted: nothing to say.
  ASSERT_EQ(runRollerdyn({"simulate", model("balanced-4cart.yaml"), "--model", "reduced", "--set",
                          "simulation.t_end=0.5", "--out", kloss.str()})
                .exit_code,
            0);
  EXPECT_TRUE(nlohmann::json::parse(slurp(kloss.path() / "summary.json"))["motor_fit"].is_null());
}

TEST(CliMotor, WithoutMachineDataOnlyKloss) {
  TempDir out("motor-kloss");
  const auto r = runRollerdyn({"motor", model("recuperative-2cart.yaml"), "--out", out.str()});
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("Kloss curves only"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(out.path() / "motor_catalogue.csv"));
  EXPECT_TRUE(fs::exists(out.path() / "motor_curves.csv"));
}

TEST(CliMotor, UsageAndSceneErrorsAreExitTwo) {
  const auto bad_option = runRollerdyn({"motor", model("balanced-4cart.yaml"), "--sett", "a=b"});
  EXPECT_EQ(bad_option.exit_code, 2);
  EXPECT_NE(bad_option.err.find("did you mean '--set'"), std::string::npos) << bad_option.err;
  const auto bad_key = runRollerdyn({"motor", model("balanced-4cart.yaml"), "--set", "motor.catalogue.powr=1"});
  EXPECT_EQ(bad_key.exit_code, 2);
  EXPECT_NE(bad_key.err.find("did you mean 'power'"), std::string::npos) << bad_key.err;
  const auto partial = runRollerdyn({"motor", model("balanced-4cart.yaml"), "--set", "motor.circuit.R_s=0.1"});
  EXPECT_EQ(partial.exit_code, 2);
  EXPECT_NE(partial.err.find("motor.circuit.L_sigma_s"), std::string::npos) << partial.err;
  EXPECT_EQ(std::count(partial.err.begin(), partial.err.end(), '\n'), 1) << partial.err;
}

}  // namespace
}  // namespace rollerdyn
