// Joint lives as the user meets them: the console and summary.json give the same life in hours,
// the rod end's from the oscillating-bearing conversion of ISO 281's life (the 6-cart trial: the
// console "2.34e+07 rev", the JSON L10_revolutions 2.34e7, the report "n/a", for a joint that
// swings 1.67 times a second), and a stalled drive gets no life at all.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "cli/CliTestSupport.h"

namespace rollerdyn {
namespace {

using test::model;
using test::runRollerdyn;
using test::slurp;
using test::TempDir;

constexpr double kPi = 3.14159265358979323846;

// The console's row of a joint in the sizing's joint table, up to the end of the line.
std::string consoleRow(const std::string& out, const std::string& name) {
  const std::size_t table = out.find("joint (most loaded cart)");
  if (table == std::string::npos) return "";
  const std::size_t at = out.find("\n  " + name + " ", table);
  if (at == std::string::npos) return "";
  return out.substr(at + 1, out.find('\n', at + 1) - at - 1);
}

std::string lastField(const std::string& line) {
  std::istringstream in(line);
  std::string w, last;
  while (in >> w) last = w;
  return last;
}

TEST(CliJointLives, RodEndLifeInHoursAgreesBetweenConsoleJsonAndTheOscillationFormula) {
  TempDir out("lives");
  const auto r = runRollerdyn({"simulate", model("balanced-4cart.yaml"), "--model", "reduced", "--set",
                               "sizing.bearing_rating.rod_end=60000", "--set", "sizing.bearing_rating.guide_roller=30000",
                               "--out", out.str()},
                              120);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const auto j = nlohmann::json::parse(slurp(out.path() / "summary.json"));
  ASSERT_EQ(j["motion"], "turning");
  const auto& rod = j["sizing"]["joints"]["rod_end"]["worst"];
  ASSERT_TRUE(rod["L10_hours"].is_number()) << rod.dump(1);
  // The scene's r = 0.2 m, l = 0.8 m: the rod swings through 2γ = 2·asin(r/l) once per crank
  // revolution, f = ω̄/2π; L10 = (C/P)³·10⁶, L10_osc = L10·180°/(2γ), L10h = L10_osc/(3600·f).
  const double two_gamma_deg = 2 * std::asin(0.2 / 0.8) * 180 / kPi;
  const double f = j["omega_crank"]["mean"].get<double>() / (2 * kPi);
  const double P = rod["equivalent_load"].get<double>();
  const double hours = std::pow(60000 / P, 3) * 1e6 * 180 / two_gamma_deg / (3600 * f);
  EXPECT_NEAR(rod["L10_hours"].get<double>(), hours, 1e-3 * hours);
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", rod["L10_hours"].get<double>());
  EXPECT_NE(r.out.find("L10 [h]\n"), std::string::npos) << r.out;
  EXPECT_EQ(lastField(consoleRow(r.out, "rod end")), text) << r.out;
  const auto& roller = j["sizing"]["joints"]["guide_roller_front"]["worst"];
  std::snprintf(text, sizeof text, "%.3g", roller["L10_hours"].get<double>());
  EXPECT_EQ(lastField(consoleRow(r.out, "guide roller, front")), text) << r.out;
}

// The shipped scene with the roller forces opposing the velocity stalls (model/balanced-4cart.yaml):
// no joint turns, so no life, in the JSON and on the console.
TEST(CliJointLives, StalledDriveGetsNoLives) {
  TempDir out("stalled-lives");
  const auto r = runRollerdyn({"simulate", model("balanced-4cart.yaml"), "--model", "reduced", "--set",
                               "loads.roller_force_direction=opposes_velocity", "--set",
                               "sizing.bearing_rating.guide_roller=30000", "--out", out.str()},
                              120);
  const auto j = nlohmann::json::parse(slurp(out.path() / "summary.json"));
  ASSERT_EQ(j["motion"], "stalled") << r.out;
  const auto& roller = j["sizing"]["joints"]["guide_roller_front"]["worst"];
  EXPECT_TRUE(roller["L10_hours"].is_null()) << roller.dump(1);
  EXPECT_EQ(lastField(consoleRow(r.out, "guide roller, front")), "n/a") << r.out;
  EXPECT_NE(r.out.find("L10 n/a: the drive does not turn (motion: stalled): no running to wear the bearing"),
            std::string::npos)
      << r.out;
}

}  // namespace
}  // namespace rollerdyn
