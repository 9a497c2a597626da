// The smaller findings of the 6-cart trial, each as the user met it on the command line.
#include <gtest/gtest.h>

#include <sstream>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include "cli/CliTestSupport.h"

namespace rollerdyn {
namespace {

using test::model;
using test::runRollerdyn;
using test::slurp;
using test::TempDir;
namespace fs = std::filesystem;

// `--minimize detla` printed the sweep header and then a bare "expected one of ..." list.
TEST(CliTrialFindings, MisspelledMetricGetsADidYouMeanBeforeAnyHeader) {
  TempDir out("detla");
  const auto r = runRollerdyn({"sweep", model("recuperative-2cart.yaml"), "--param", "crank.offset_deg", "--values",
                               "80,90", "--model", "reduced", "--minimize", "detla", "--out", out.str()},
                              60);
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("did you mean 'delta'?"), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("sweep of"), std::string::npos) << r.out;
}

// optimize ran 7 designs and then failed with a raw filesystem error on a bad --out.
TEST(CliTrialFindings, OptimizeChecksOutBeforeAnyRun) {
  TempDir tmp("optout");
  const fs::path file = tmp.path() / "a_file";
  std::ofstream(file) << "x";
  const auto r = runRollerdyn({"optimize", model("recuperative-2cart.yaml"), "--param", "crank.offset_deg", "--range",
                               "0:180", "--minimize", "delta", "--model", "reduced", "--out", (file / "sub").string()},
                              60);
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("--out"), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("[1]"), std::string::npos) << r.out;  // no design was run
}

// The flywheel hint printed `--range 0:0` (rejected), a literal SCENE and none of the user's --set.
TEST(CliTrialFindings, FlywheelHintRunsAsPrinted) {
  TempDir out("hint");
  const auto r = runRollerdyn({"simulate", model("recuperative-2cart.yaml"), "--model", "reduced", "--set",
                               "sizing.target_delta=0.04", "--set", "simulation.t_end=8", "--out", out.str()},
                              60);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const std::size_t at = r.out.find("rollerdyn optimize ");
  ASSERT_NE(at, std::string::npos) << r.out;
  const std::string cmd = r.out.substr(at, r.out.find('\n', at) - at);
  EXPECT_EQ(cmd.find("SCENE"), std::string::npos) << cmd;
  EXPECT_EQ(cmd.find("--range 0:0 "), std::string::npos) << cmd;
  EXPECT_NE(cmd.find(model("recuperative-2cart.yaml")), std::string::npos) << cmd;
  EXPECT_NE(cmd.find("--set sizing.target_delta=0.04 --set simulation.t_end=8"), std::string::npos) << cmd;
  EXPECT_NE(cmd.find("--set initial.crank_speed="), std::string::npos) << cmd;  // sized for steady running
  // The run's model: the trial's reduced run got a hint that optimized the multibody model.
  EXPECT_NE(cmd.find(" --model reduced "), std::string::npos) << cmd;
  // Run it as printed (few evaluations, to keep the test short).
  TempDir opt("hint-run");
  const std::string line = std::string(ROLLERDYN_BINARY) + cmd.substr(std::string("rollerdyn").size()) +
                           " --max-evals 6 --out " + opt.str() + " > /dev/null 2>&1";
  EXPECT_EQ(WEXITSTATUS(std::system(line.c_str())) == 2, false) << line;  // not a usage error
  EXPECT_TRUE(fs::exists(opt.path() / "optimize.json")) << line;
}

// designs.png plotted the minimised parameter against itself; why a figure is missing was only in
// optimize.json. With a constraint the figure shows the constrained metric against the parameter.
TEST(CliTrialFindings, OptimizeDesignsFigureIsNeverAParameterAgainstItself) {
  TempDir out("designs");
  auto r = runRollerdyn({"optimize", model("energy-balanced-3cart.yaml"), "--param", "flywheel.inertia", "--range",
                         "0:400", "--minimize", "flywheel.inertia", "--model", "reduced", "--max-evals", "8", "--out",
                         out.str()},
                        120);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.err.find("figures: no designs figure"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out.path() / "designs.png"));
  TempDir out2("designs2");
  r = runRollerdyn({"optimize", model("energy-balanced-3cart.yaml"), "--param", "flywheel.inertia", "--range", "0:400",
                    "--minimize", "flywheel.inertia", "--constraint", "delta<=0.05", "--model", "reduced", "--out",
                    out2.str()},
                   120);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  const auto j = nlohmann::json::parse(slurp(out2.path() / "optimize.json"));
  EXPECT_EQ(j["plot_note"], "") << j["plot_note"];
}

// A sweep over designs from a file wrote no plots and did not say why.
TEST(CliTrialFindings, ValuesFileSweepSaysWhyThereAreNoPlots) {
  TempDir out("vfile");
  const fs::path values = out.path() / "designs.txt";
  std::ofstream(values) << "crank.offset_deg\n80\n90\n";
  const auto r = runRollerdyn({"sweep", model("recuperative-2cart.yaml"), "--param", "crank.offset_deg", "--values-file",
                               values.string(), "--model", "reduced", "--out", (out.path() / "o").string()},
                              60);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("figures: no plots"), std::string::npos) << r.out;
}

// "steady state reached from revolution 1 of 15" did not say what either number means.
TEST(CliTrialFindings, SteadyStateLineSaysWhatItsNumbersMean) {
  TempDir out("steady");
  const auto r = runRollerdyn({"simulate", model("recuperative-2cart.yaml"), "--model", "reduced", "--out", out.str()},
                              60);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("the crank speed repeats from revolution"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("whole revolutions in the run"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("metrics window: the last"), std::string::npos) << r.out;
}

// Without a steady state the sizing block's figures are over the run's last part, and each line
// says so: the trial of a star-delta start that stalls read "(steady window)" under a heading
// saying there was none.
TEST(CliTrialFindings, NoSizingFigureClaimsASteadyWindowThatDoesNotExist) {
  TempDir out("no-steady");
  const auto r = runRollerdyn({"simulate", model("balanced-4cart.yaml"), "--model", "reduced", "--set",
                               "simulation.t_end=3", "--set", "crank.offset_deg=60", "--out", out.str()},
                              60);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("drive sizing over the run's last part (no steady state)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("N·m (the run's last part)"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("(steady window)"), std::string::npos) << r.out;
}

// A key that every point of a sweep or an optimisation sets counts as given when the base scene is
// checked: the trial swept coupling.stiffness under --set coupling.type=elastic on a scene with a
// rigid coupling and was refused for a missing coupling.stiffness before any run.
TEST(CliTrialFindings, AKeyTheParametersSetCountsAsGiven) {
  TempDir sweep_out("sweep-sets-key");
  const auto sweep = runRollerdyn({"sweep", model("energy-balanced-3cart.yaml"), "--model", "reduced", "--set",
                                   "coupling.type=elastic", "--set", "coupling.damping=1500", "--set",
                                   "simulation.t_end=2", "--param", "coupling.stiffness", "--values", "50000,100000",
                                   "--out", sweep_out.str()},
                                  120);
  EXPECT_EQ(sweep.exit_code, 0) << sweep.out << sweep.err;
  EXPECT_NE(sweep.out.find("coupling.stiffness=100000"), std::string::npos) << sweep.out;
  TempDir opt_out("optimize-sets-key");
  const auto opt = runRollerdyn({"optimize", model("energy-balanced-3cart.yaml"), "--model", "reduced", "--set",
                                 "coupling.type=elastic", "--set", "coupling.damping=1500", "--set",
                                 "simulation.t_end=2", "--param", "coupling.stiffness", "--range", "50000:100000",
                                 "--minimize", "coupling_torque_swing", "--max-evals", "3", "--out", opt_out.str()},
                                120);
  EXPECT_NE(opt.exit_code, 2) << opt.out << opt.err;
  EXPECT_EQ(opt.err.find("coupling.stiffness: expected"), std::string::npos) << opt.err;
}

// A drive that rocked at first and then got going, in a run too short to settle, is "starting":
// no δ from a window that holds its rocking (the 6-cart trial's sweep printed δ = 10.49 for it)
// and no sizing verdict, while a drive that keeps rocking is "rocking".
TEST(CliTrialFindings, ShortRunOfAStartingDriveGivesNoVerdict) {
  TempDir out("starting");
  const auto r = runRollerdyn({"simulate", model("balanced-4cart.yaml"), "--model", "reduced", "--set",
                               "simulation.t_end=3", "--set", "crank.offset_deg=60", "--out", out.str()},
                              60);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  const auto j = nlohmann::json::parse(slurp(out.path() / "summary.json"));
  EXPECT_EQ(j["motion"], "starting");
  EXPECT_TRUE(j["delta"].is_null());
  for (const auto& c : j["sizing"]["checks"]) EXPECT_NE(c["verdict"], "pass") << c.dump();
  EXPECT_EQ(j["sizing"]["checks"][0]["verdict"], "not applicable");
}

// `validate` only ran from the repository's top folder ("cannot read published table
// 'validation/published/...'" from anywhere else). --quick: about 3 s of CPU.
TEST(CliTrialFindings, ValidateRunsFromAnyFolder) {
  TempDir cwd("validate-cwd");
  const auto r = test::runRollerdynIn(cwd.str(), {"validate", "--quick", "--out", (cwd.path() / "v").string()}, 600);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_TRUE(fs::exists(cwd.path() / "v" / "report.md")) << r.out << r.err;
}

// optimize printed "delta 0.720692 infeasible: no steady state" and "delta nan": a metric of an
// unusable run is "n/a", as in the sweep.
TEST(CliTrialFindings, OptimizePrintsNoMetricOfAnUnusableRun) {
  TempDir out("opt-na");
  const auto r = runRollerdyn({"optimize", model("balanced-4cart.yaml"), "--set", "carts.count=6", "--set",
                               "simulation.t_end=5", "--param", "crank.offset_deg", "--range", "0:180", "--minimize",
                               "delta", "--model", "reduced", "--max-evals", "12", "--out", out.str()},
                              120);
  ASSERT_NE(r.out.find("infeasible"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find(" nan"), std::string::npos) << r.out;
  std::istringstream lines(r.out);
  for (std::string line; std::getline(lines, line);)
    if (line.find("infeasible") != std::string::npos) EXPECT_NE(line.find("delta n/a"), std::string::npos) << line;
}

// simulate warned of crank.offset_deg = 1.0472 (60° in radians); a sweep over 0:3.1416:0.5236 ran
// silently. The swept values get the same warning, once per parameter, naming the values.
TEST(CliTrialFindings, ASweepWarnsOfValuesTypedInTheWrongUnit) {
  TempDir out("sweep-units");
  const auto r = runRollerdyn({"sweep", model("balanced-4cart.yaml"), "--param", "crank.offset_deg", "--values",
                               "0.5236,1.0472,60", "--model", "reduced", "--set", "simulation.t_end=2", "--out",
                               out.str()},
                              120);
  EXPECT_NE(r.err.find("warning: --param crank.offset_deg 0.5236, 1.0472: crank.offset_deg = 0.5236 is read as "
                       "0.5236°"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find(", 60:"), std::string::npos) << r.err;  // 60 is a plausible offset
}

}  // namespace
}  // namespace rollerdyn
