// The sign-off sheet (analysis/SignOffSheet.h) built from hand-made summaries: every check of
// sizing.checks and of the separation margins appears with its limit and method; one FAIL makes
// the sheet "NOT SIGNED OFF"; a check that does not apply or has nothing to compare with is n/a
// with its reason and the scene keys it names; the counts add up. Also the limit and method every
// check of the drive sizing carries (SizingChecks.h), and the SHA-256 the sheet states.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "analysis/SignOffSheet.h"
#include "analysis/SizingCheckJson.h"
#include "analysis/SizingChecks.h"
#include "io/Sha256.h"

namespace rollerdyn {
namespace {

using nlohmann::json;

json check(const std::string& name, const json& value, const json& verdict, const std::string& reason = "",
           double limit = 1.0) {
  return {{"check", name}, {"what", name + " in words"}, {"value", value}, {"verdict", verdict},
          {"window", "steady window"}, {"reason", reason}, {"limit", limit}, {"passes_when", "<="},
          {"method", "a method"}, {"basis", "the inputs"}};
}

json summaryWith(const json& checks, const json& separation_checks) {
  json s = {{"model", "multibody"}, {"motion", "turning"}, {"complete", true}, {"status", "completed"},
            {"warnings", json::array()}, {"sizing", {{"checks", checks}}}};
  if (!separation_checks.is_null()) s["modes"] = {{"separation_margins", {{"checks", separation_checks}}}};
  return s;
}

SignOffSource source() {
  SignOffSource src;
  src.scene_name = "test";
  src.scene_path = "/tmp/test.yaml";
  src.scene_text = "abc";
  src.tool_version = "rollerdyn test";
  src.date = "2026-11-28 10:30 UTC";
  return src;
}

const SignOffRow& row(const SignOffSheet& s, const std::string& name) {
  for (const SignOffRow& r : s.rows)
    if (r.check.name == name) return r;
  throw std::runtime_error("no row " + name);
}

// Known answers of FIPS 180-4 (its examples), independent of the implementation.
TEST(SignOffSheet, TheSceneHashIsSha256) {
  EXPECT_EQ(sha256Hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256Hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256Hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(buildSignOffSheet(summaryWith(json::array(), json::array()), source()).scene_sha256, sha256Hex("abc"));
}

TEST(SignOffSheet, EveryCheckOfTheSummaryAndTheSeparationMarginsIsOnTheSheet) {
  const json sizing = json::array({check("motor_heating", 0.8, "pass"), check("coupling", 0.5, "pass"),
                                   check("gear_application_factor", 0.7, "pass")});
  const json sep = json::array({check("separation_margin_order_4", 0.4, "pass")});
  const SignOffSheet s = buildSignOffSheet(summaryWith(sizing, sep), source());
  ASSERT_EQ(s.rows.size(), 4u);
  EXPECT_EQ(s.rows[2].check.name, "gear_application_factor");  // a check the sheet does not know by name
  EXPECT_EQ(s.rows[3].group, "torsional modes");
  const json j = signOffJson(s);
  ASSERT_EQ(j["checks"].size(), 4u);
  for (const json& c : j["checks"]) {
    EXPECT_EQ(c["limit"], 1.0) << c["check"];
    EXPECT_EQ(c["method"], "a method") << c["check"];
  }
  EXPECT_EQ(j["counts"]["pass"], 4);
  EXPECT_EQ(j["counts"]["total"], 4);
  EXPECT_TRUE(s.signable);
  EXPECT_EQ(s.overall.rfind("All checks pass", 0), 0u) << s.overall;
}

TEST(SignOffSheet, OneFailingCheckMeansNotSignedOff) {
  const json sizing = json::array({check("motor_heating", 0.8, "pass"), check("coupling", 1.7, "FAIL", "peak 1700 N·m")});
  const SignOffSheet s = buildSignOffSheet(summaryWith(sizing, json::array()), source());
  EXPECT_EQ(s.failed, 1);
  EXPECT_EQ(s.passed, 1);
  EXPECT_FALSE(s.signable);
  EXPECT_EQ(s.overall.rfind("NOT SIGNED OFF", 0), 0u) << s.overall;
  EXPECT_NE(s.overall.find("not signed off while any check FAILs"), std::string::npos) << s.overall;
  EXPECT_NE(signOffSheetText(s).find("FAIL  coupling"), std::string::npos) << signOffSheetText(s);
}

TEST(SignOffSheet, NotApplicableShowsItsReasonAndTheKeysItNames) {
  const json sizing = json::array(
      {check("coupling", nullptr, "not applicable",
             "the run holds no start from rest: run it from rest (initial.crank_speed: 0)"),
       check("fatigue_starts_rod_force", nullptr, nullptr,
             "damage per start 1e-9; no requirement to compare with (sizing.fatigue.required_starts)")});
  const SignOffSheet s = buildSignOffSheet(summaryWith(sizing, json::array()), source());
  EXPECT_EQ(s.not_applicable, 2);
  const SignOffRow& c = row(s, "coupling");
  EXPECT_EQ(c.verdict, "not applicable");
  EXPECT_NE(c.reason.find("no start from rest"), std::string::npos);
  ASSERT_EQ(c.keys.size(), 1u);
  EXPECT_EQ(c.keys[0], "initial.crank_speed");
  // Nothing to compare with: n/a, and said so, with the run's reason.
  const SignOffRow& f = row(s, "fatigue_starts_rod_force");
  EXPECT_EQ(f.verdict, "not applicable");
  EXPECT_EQ(f.reason.rfind("no verdict: ", 0), 0u) << f.reason;
  ASSERT_EQ(f.keys.size(), 1u);
  EXPECT_EQ(f.keys[0], "sizing.fatigue.required_starts");
  EXPECT_EQ(s.overall.rfind("No check FAILs", 0), 0u) << s.overall;
  EXPECT_TRUE(s.signable);  // no FAIL: the reviewer may sign, accepting each n/a
  EXPECT_NE(signOffSheetText(s).find("n/a   coupling"), std::string::npos) << signOffSheetText(s);
}

TEST(SignOffSheet, WithoutTheModalAnalysisTheSeparationMarginIsNotApplicable) {
  const SignOffSheet s = buildSignOffSheet(summaryWith(json::array(), nullptr), source());
  ASSERT_EQ(s.rows.size(), 1u);
  EXPECT_EQ(s.rows[0].verdict, "not applicable");
  EXPECT_NE(s.rows[0].reason.find("modal analysis was not made"), std::string::npos);
}

TEST(SignOffSheet, AnIncompleteRunIsNotSignedOff) {
  json summary = summaryWith(json::array({check("motor_heating", 0.8, "pass")}), json::array());
  summary["complete"] = false;
  summary["status"] = "integrator failed at t = 1.2 s";
  const SignOffSheet s = buildSignOffSheet(summary, source());
  EXPECT_FALSE(s.signable);
  EXPECT_NE(s.overall.find("did not complete"), std::string::npos) << s.overall;
}

// The drive sizing's checks each carry the limit they are held against and the method, with
// the limits of their definitions (SizingChecks.h): 1 for the ratios, 0.95² for the breakdown.
TEST(SignOffSheet, EverySizingCheckCarriesItsLimitAndMethod) {
  DriveSizing s;
  s.motion = "turning";
  s.steady_reached = true;
  s.start_simulated = true;
  s.can_start_from_rest = 1;
  s.start_load_ratio = 0.5;
  s.motor.available = true;
  s.motor.rms_over_nominal = 0.8;
  s.motor.whole_run.thermal_over_nominal = 0.7;
  s.motor.whole_run.continuous_running = true;
  s.motor.whole_run.starts_per_hour = 40;
  s.motor.peak_over_breakdown = 0.5;
  s.coupling.available = true;
  s.coupling.rating = 1000;
  s.coupling.peak = s.coupling.peak_whole_run = 500;
  s.coupling.peak_over_rating = s.coupling.peak_over_rating_whole_run = 0.5;
  s.coupling_selection.requested = true;
  s.coupling_selection.rated_torque = 2000;
  s.coupling_selection.max_torque = 6000;
  s.coupling_selection.vibratory_torque = 800;
  s.coupling_selection.damping_power = 300;
  const std::vector<SizingCheck> checks = sizingChecks(s, true);
  ASSERT_EQ(checks.size(), 8u);  // start, heating, breakdown, coupling and DIN 740-2's four
  for (const SizingCheck& c : checks) {
    EXPECT_FALSE(c.method.empty()) << c.name;
    EXPECT_FALSE(c.basis.empty()) << c.name;
    EXPECT_FALSE(c.passes_when.empty()) << c.name;
    EXPECT_DOUBLE_EQ(c.limit, c.name == "motor_breakdown" ? 0.9025 : 1.0) << c.name;
    const json j = sizingCheckJson(c);
    EXPECT_TRUE(j["limit"].is_number()) << c.name;
    EXPECT_EQ(sizingCheckFromJson(j).method, c.method);
  }
  EXPECT_NE(checks.back().method.find("DIN 740-2"), std::string::npos);
  EXPECT_NE(checks[2].method.find("IEC 60034-1"), std::string::npos);
}

// Without M_n (no nominal torque, power or Kloss data) the heating check has no ratio: it is
// "not applicable" and names the keys that give M_n (it had no verdict and a reason with "nan").
TEST(SignOffSheet, HeatingWithoutTheNominalTorqueIsNotApplicableAndNamesTheKeys) {
  DriveSizing s;
  s.motion = "turning";
  s.steady_reached = true;
  s.start_simulated = true;
  s.can_start_from_rest = 1;
  s.motor.available = true;
  s.motor.nominal_torque = NAN;
  s.motor.rms_over_nominal = NAN;
  s.motor.whole_run.thermal_over_nominal = NAN;
  s.motor.peak_over_breakdown = 0.5;
  SizingCheck heating;
  for (const SizingCheck& c : sizingChecks(s, true))
    if (c.name == "motor_heating") heating = c;
  EXPECT_EQ(heating.verdict, "not applicable");
  EXPECT_NE(heating.reason.find("sizing.motor_nominal_torque"), std::string::npos) << heating.reason;
  EXPECT_EQ(heating.reason.find("nan"), std::string::npos) << heating.reason;
}

}  // namespace
}  // namespace rollerdyn
