// `rollerdyn signoff`: the sheet of a drive whose coupling is rated far below its torque (100 N·m
// against peaks of kN·m): the coupling check FAILs, the sheet says "NOT SIGNED OFF", and the
// command still exits 0 (the sheet was written); every check of the run's summary.json
// (sizing.checks) and of the modal analysis (modes.json's separation_margins.checks) is on it with
// its limit and method; each n/a has its reason; the PDF is printed where Chromium is installed.
// Without Chromium the JSON and HTML are written, the console says the PDF needs Chromium, exit 5.
#include <gtest/gtest.h>

#include <cstdlib>

#include <nlohmann/json.hpp>

#include "cli/CliTestSupport.h"

namespace rollerdyn {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::model;
using test::runRollerdyn;
using test::slurp;
using test::TempDir;

bool chromiumInstalled() { return std::system("command -v chromium >/dev/null 2>&1") == 0; }

class SignoffCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    out_ = new TempDir("signoff");
    result_ = new test::CliResult(runRollerdyn({"signoff", model("balanced-4cart.yaml"), "--set", "simulation.t_end=3",
                                                "--set", "sizing.coupling_rated_torque=100", "--out", out_->str()}));
  }
  static void TearDownTestSuite() {
    delete result_;
    delete out_;
  }
  static json read(const std::string& name) { return json::parse(slurp(out_->path() / name)); }
  static TempDir* out_;
  static test::CliResult* result_;
};
TempDir* SignoffCli::out_ = nullptr;
test::CliResult* SignoffCli::result_ = nullptr;

TEST_F(SignoffCli, AFailingCheckIsNotSignedOffAndTheCommandStillSucceeds) {
  ASSERT_EQ(result_->exit_code, chromiumInstalled() ? 0 : 5) << result_->err;
  const json sheet = read("signoff.json");
  EXPECT_GE(sheet["counts"]["FAIL"].get<int>(), 1);
  EXPECT_FALSE(sheet["signable"].get<bool>());
  EXPECT_EQ(sheet["overall"].get<std::string>().rfind("NOT SIGNED OFF", 0), 0u) << sheet["overall"];
  bool coupling_fails = false;
  for (const json& c : sheet["checks"]) coupling_fails = coupling_fails || (c["check"] == "coupling" && c["verdict"] == "FAIL");
  EXPECT_TRUE(coupling_fails);
  const std::string html = slurp(out_->path() / "signoff.html");
  EXPECT_NE(html.find("NOT SIGNED OFF"), std::string::npos);
  EXPECT_NE(html.find("reviewer's name"), std::string::npos);
  EXPECT_NE(result_->out.find("NOT SIGNED OFF"), std::string::npos) << result_->out;
  const int total = sheet["counts"]["total"];
  EXPECT_EQ(sheet["counts"]["pass"].get<int>() + sheet["counts"]["FAIL"].get<int>() +
                sheet["counts"]["not_applicable"].get<int>(),
            total);
}

TEST_F(SignoffCli, EveryCheckOfTheRunIsOnTheSheetWithLimitAndMethod) {
  const json summary = read("summary.json");
  const json modes = read("modes.json");
  const json sheet = read("signoff.json");
  std::vector<std::string> expected;
  for (const json& c : summary["sizing"]["checks"]) expected.push_back(c["check"]);
  for (const json& c : modes["separation_margins"]["checks"]) expected.push_back(c["check"]);
  ASSERT_GE(expected.size(), 4u);
  ASSERT_EQ(sheet["checks"].size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const json& c = sheet["checks"][i];
    EXPECT_EQ(c["check"], expected[i]);
    EXPECT_TRUE(c["limit"].is_number()) << expected[i];
    EXPECT_FALSE(c["method"].get<std::string>().empty()) << expected[i];
    if (c["sheet_verdict"] == "not applicable")
      EXPECT_FALSE(c["sheet_reason"].get<std::string>().empty()) << expected[i];
  }
  for (const json& c : summary["sizing"]["checks"]) {
    EXPECT_TRUE(c["limit"].is_number()) << c["check"];
    EXPECT_FALSE(c["method"].get<std::string>().empty()) << c["check"];
  }
  EXPECT_EQ(sheet["overrides"].size(), 2u);
  EXPECT_EQ(sheet["scene_sha256"].get<std::string>().size(), 64u);
}

TEST_F(SignoffCli, ThePdfIsPrintedWithChromium) {
  if (!chromiumInstalled()) GTEST_SKIP() << "chromium not installed (Debian package chromium; scripts/setup.sh installs it)";
  const std::string pdf = slurp(out_->path() / "signoff.pdf");
  ASSERT_GT(pdf.size(), 1000u);
  EXPECT_EQ(pdf.rfind("%PDF", 0), 0u);
}

TEST(SignoffCliWithoutChromium, WritesJsonAndHtmlAndSaysThePdfNeedsChromium) {
  TempDir out("signoff-nopdf");
  fs::create_directories(out.path());
  {
    std::ofstream(out.path() / "signoff.pdf") << "%PDF of an earlier sheet";
  }
  ::setenv("ROLLERDYN_CHROMIUM", "/nonexistent/chromium", 1);
  const auto r = runRollerdyn({"signoff", model("recuperative-2cart.yaml"), "--set", "simulation.t_end=2", "--out",
                               out.str()});
  ::unsetenv("ROLLERDYN_CHROMIUM");
  EXPECT_EQ(r.exit_code, 5) << r.err;
  EXPECT_NE(r.err.find("needs Chromium"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(out.path() / "signoff.json"));
  EXPECT_TRUE(fs::exists(out.path() / "signoff.html"));
  EXPECT_FALSE(fs::exists(out.path() / "signoff.pdf"));  // never the PDF of an earlier sheet
}

}  // namespace
}  // namespace rollerdyn
