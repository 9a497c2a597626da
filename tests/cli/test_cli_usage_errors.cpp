// Every usage error of the command line, end-to-end on the built binary: exit code 2, exactly one
// line on stderr starting "rollerdyn: ", naming what is wrong and, for a near miss, the closest
// command, option, choice or scene key; nothing on stdout (nothing was computed). Plus the other
// documented exit codes: 0 for --help and --version, 3 for a run that ended early.
#include <gtest/gtest.h>

#include <algorithm>
#include <regex>
#include <string>
#include <vector>

#include "cli/CliTestSupport.h"

namespace rollerdyn {
namespace {

namespace fs = std::filesystem;
using test::model;
using test::runRollerdyn;
using test::TempDir;

struct UsageCase {
  std::vector<std::string> args;
  std::vector<std::string> fragments;  // all must appear in the stderr line
};

void expectUsageError(const UsageCase& c) {
  std::string shown;
  for (const std::string& a : c.args) shown += a + " ";
  SCOPED_TRACE("rollerdyn " + shown);
  const auto r = runRollerdyn(c.args, 120);
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_EQ(r.err.rfind("rollerdyn: ", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "expected one line:\n" << r.err;
  EXPECT_EQ(r.out, "") << "a usage error must stop before any output";
  for (const std::string& f : c.fragments) EXPECT_NE(r.err.find(f), std::string::npos) << "lacks \"" << f << "\":\n" << r.err;
}

TEST(CliUsageErrors, CommandsAndTopLevelOptions) {
  const std::string scene = model("balanced-4cart.yaml");
  const std::vector<UsageCase> cases = {
      {{}, {"expected a command", "simulate", "see rollerdyn --help"}},
      {{"simulat", scene}, {"unknown command 'simulat'", "did you mean 'simulate'?"}},
      {{"reprot"}, {"unknown command 'reprot'", "did you mean 'report'?"}},
      {{"frobnicate"}, {"unknown command 'frobnicate'", "commands: check, simulate"}},
      {{"--verison"}, {"unknown option '--verison'", "did you mean '--version'?"}},
  };
  for (const UsageCase& c : cases) expectUsageError(c);
  // No hint when nothing is close.
  const auto far = runRollerdyn({"frobnicate"}, 60);
  EXPECT_EQ(far.err.find("did you mean"), std::string::npos) << far.err;
}

TEST(CliUsageErrors, OptionsArgumentsAndValues) {
  const std::string scene = model("balanced-4cart.yaml");
  const std::vector<UsageCase> cases = {
      {{"simulate", scene, "--outt", "x"}, {"simulate: unknown option '--outt'", "did you mean '--out'?",
                                            "see rollerdyn simulate --help"}},
      {{"simulate", scene, "--modle=reduced"}, {"unknown option '--modle'", "did you mean '--model'?"}},
      {{"report", scene, "--sett", "crank.offset_deg=60"}, {"report: unknown option '--sett'", "did you mean '--set'?"}},
      {{"sweep", scene, "--parm", "crank.offset_deg", "--values", "0:90:10"}, {"did you mean '--param'?"}},
      {{"simulate", scene, "-x"}, {"unknown option '-x'"}},
      {{"simulate", scene, "extra"}, {"unexpected argument 'extra'"}},
      {{"simulate", "/nonexistent/scene.yaml"}, {"simulate: scene", "/nonexistent/scene.yaml"}},
      {{"sweep", "/nonexistent/scene.yaml", "--param", "crank.offset_deg", "--values", "1"}, {"/nonexistent/scene.yaml"}},
      {{"simulate"}, {"simulate: scene is required"}},
      {{"plot"}, {"plot: dir is required"}},
      {{"plot", "/nonexistent-folder"}, {"plot: dir", "/nonexistent-folder"}},
      {{"simulate", scene, "--out"}, {"--out"}},
      {{"simulate", scene, "--model", "reducd"}, {"--model: expected one of multibody, reduced, got 'reducd'",
                                                  "did you mean 'reduced'?"}},
      {{"cam-profile", model("cam-drive.yaml"), "--model", "multbody"}, {"did you mean 'multibody'?"}},
      {{"bench", scene, "--study", "integrator"}, {"--study: expected one of integrators, carts, effects, reactions, all",
                                                   "did you mean 'integrators'?"}},
      {{"bench", scene, "--repeat", "0"}, {"--repeat"}},
      {{"chain", "--J1", "abc"}, {"chain:", "--J1", "abc"}},
      {{"sweep", scene, "--param", "crank.offset_deg"}, {"give the values one way", "--values after each --param"}},
  };
  for (const UsageCase& c : cases) expectUsageError(c);
}

// Errors found after parsing (scene keys, values, sweep keys and grids) are bad input too.
TEST(CliUsageErrors, SceneAndSweepValues) {
  const std::string scene = model("recuperative-2cart.yaml");
  const std::vector<UsageCase> cases = {
      {{"check", scene, "--set", "carts.cuont=3"}, {"--set #1", "did you mean 'count'?"}},
      {{"simulate", scene, "--set", "rods.length=abc"}, {"rods.length: expected a number"}},
      {{"sweep", scene, "--param", "crank.offest_deg", "--values", "0:90:10"},
       {"sweep: --param crank.offest_deg", "did you mean 'crank.offset_deg'?"}},
      {{"sweep", scene, "--param", "crank.offset_deg", "--values", "0:90:0"}, {"--values for crank.offset_deg", "step"}},
      {{"sweep", scene, "--param", "crank.offset_deg", "--values", "0:90:10", "--param", "coupling.damping"},
       {"one --values after each --param"}},
  };
  for (const UsageCase& c : cases) expectUsageError(c);
}

TEST(CliUsageErrors, VersionIsProjectVersionAndCommit) {
  const auto r = runRollerdyn({"--version"}, 60);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  // ROLLERDYN_EXPECTED_VERSION: CMake's project(VERSION), given to this test by tests/CMakeLists.txt.
  const std::regex form("rollerdyn " + std::regex_replace(std::string(ROLLERDYN_EXPECTED_VERSION), std::regex("\\."), "\\.") +
                        "( \\(commit [0-9a-f]{7,40}\\))?\n");
  EXPECT_TRUE(std::regex_match(r.out, form)) << r.out;
  EXPECT_EQ(r.err, "");
}

TEST(CliUsageErrors, HelpIsNotAnError) {
  for (const std::vector<std::string>& args : {std::vector<std::string>{"--help"}, {"-h"}, {"sweep", "--help"}}) {
    const auto r = runRollerdyn(args, 60);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("Usage"), std::string::npos);
  }
}

// Exit code 3: the run ended early (here the motor stalls); the outputs are still written.
// A stalled drive is a valid run of a drive that does not work: exit 4, not the 3 of a
// numerical failure (the 6-cart trial: a stalled sweep point exited 3 like a failed one).
TEST(CliUsageErrors, StalledDriveIsFourNotANumericalFailure) {
  TempDir out("stall");
  const auto r = runRollerdyn({"simulate", model("balanced-4cart.yaml"), "--model", "reduced", "--set",
                               "simulation.t_end=3", "--set", "motor.breakdown_torque=20", "--out", out.str()},
                              120);
  EXPECT_EQ(r.exit_code, 4) << r.out << r.err;
  EXPECT_NE(r.err.find("rollerdyn: motor stalled"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(out.path() / "summary.json"));
  EXPECT_TRUE(fs::exists(out.path() / "timeseries.csv"));
}

}  // namespace
}  // namespace rollerdyn
