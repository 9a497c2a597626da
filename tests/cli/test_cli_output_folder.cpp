// The output folder, end-to-end: every command that writes checks its folder before computing
// (a bad --out is exit 2 with one line, nothing printed, nothing run); a run into a folder of an
// earlier run removes that run's figures and report but no file of the user's; and an output
// folder is readable from any working directory (summary.json's scene path is absolute).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include "cli/CliTestSupport.h"

namespace rollerdyn {
namespace {

namespace fs = std::filesystem;
using test::model;
using test::runRollerdyn;
using test::runRollerdynIn;
using test::slurp;
using test::TempDir;

// Each command with a workload that could not finish within the test's time limit if it ran
// (a 10^6 s simulation, a 2000-point sweep, the validation suite): exit code 2 from the folder
// check, one line, no output, proves that the check came first. Were it missing, the process
// would be killed at the limit (exit_code -1) and the test would fail.
TEST(CliOutputFolder, UnusableOutFailsBeforeAnyComputation) {
  TempDir tmp("failfast");
  const fs::path file = tmp.path() / "a-file";
  { std::ofstream(file) << "not a folder\n"; }
  const std::string below_file = (file / "out").string();  // cannot be created: its parent is a file
  const std::string scene = model("balanced-4cart.yaml");
  const std::vector<std::vector<std::string>> commands = {
      {"simulate", scene, "--model", "reduced", "--set", "simulation.t_end=1e6", "--out", below_file},
      {"simulate", scene, "--set", "simulation.t_end=1e6", "--out", file.string()},
      {"report", scene, "--set", "simulation.t_end=1e6", "--out", below_file},
      {"compare", scene, "--set", "simulation.t_end=1e6", "--out", below_file},
      {"sweep", scene, "--param", "crank.offset_deg", "--values", "0:1999:1", "--model", "reduced", "--out", below_file},
      {"bench", scene, "--study", "all", "--out", below_file},
      {"validate", "--out", below_file},
      {"cam-profile", model("cam-drive.yaml"), "--compare", "--out", below_file},
      {"chain", "--t-end", "1e6", "--out", below_file},
      {"motor", scene, "--out", below_file},
  };
  for (const auto& args : commands) {
    SCOPED_TRACE(args[0] + " " + args.back());
    const auto r = runRollerdyn(args, 90);
    EXPECT_EQ(r.exit_code, 2) << "killed or wrong exit code; stdout:\n" << r.out << "stderr:\n" << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(r.err.rfind("rollerdyn: --out '", 0), 0u) << r.err;
    const bool file_case = args.back() == file.string();
    EXPECT_NE(r.err.find(file_case ? "expected a folder, got an existing file" : "cannot create the folder"),
              std::string::npos) << r.err;
  }
  // Nothing was written next to the blocking file.
  std::vector<std::string> left;
  for (const auto& e : fs::directory_iterator(tmp.path())) left.push_back(e.path().filename().string());
  EXPECT_EQ(left, std::vector<std::string>{"a-file"});
  EXPECT_EQ(slurp(file), "not a folder\n");
}

TEST(CliOutputFolder, PlotChecksItsFiguresFolder) {
  TempDir out("plot-figfile");
  const auto sim = runRollerdyn({"simulate", model("recuperative-2cart.yaml"), "--model", "reduced", "--set",
                                 "simulation.t_end=1", "--out", out.str()});
  ASSERT_EQ(sim.exit_code, 0) << sim.err;
  { std::ofstream(out.path() / "figures") << "mine\n"; }
  const auto r = runRollerdyn({"plot", out.str()});
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("figures"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("expected a folder, got an existing file"), std::string::npos) << r.err;
  EXPECT_EQ(slurp(out.path() / "figures"), "mine\n");
}

std::vector<std::string> pngs(const fs::path& dir) {
  std::vector<std::string> out;
  if (!fs::is_directory(dir)) return out;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".png") out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

// A second simulate into the folder of a `simulate --plot` and a `report`: the old figures and
// the old report.html would describe the first run beside the second run's tables, so they go;
// the user's own files stay.
TEST(CliOutputFolder, RerunRemovesStaleFiguresAndReportOnly) {
  TempDir out("stale");
  const std::string scene = model("recuperative-2cart.yaml");
  const auto first = runRollerdyn({"simulate", scene, "--model", "reduced", "--set", "simulation.t_end=1", "--plot",
                                   "--out", out.str()});
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const fs::path figs = out.path() / "figures";
  ASSERT_FALSE(pngs(figs).empty());
  { std::ofstream(out.path() / "report.html") << "<html>report of the first run</html>\n"; }
  { std::ofstream(out.path() / "notes.txt") << "my notes\n"; }
  { std::ofstream(figs / "my_sketch.png") << "user figure\n"; }
  { std::ofstream(figs / "crank_speed_vs_angle.txt") << "user text\n"; }

  const auto second = runRollerdyn({"simulate", scene, "--model", "reduced", "--set", "simulation.t_end=1", "--set",
                                    "crank.offset_deg=60", "--out", out.str()});
  ASSERT_EQ(second.exit_code, 0) << second.err;
  EXPECT_EQ(pngs(figs), std::vector<std::string>{"my_sketch.png"});
  for (const auto& e : fs::directory_iterator(figs)) EXPECT_NE(e.path().extension(), ".svg") << e.path();
  EXPECT_FALSE(fs::exists(out.path() / "report.html"));
  EXPECT_EQ(slurp(out.path() / "notes.txt"), "my notes\n");
  EXPECT_EQ(slurp(figs / "my_sketch.png"), "user figure\n");
  EXPECT_EQ(slurp(figs / "crank_speed_vs_angle.txt"), "user text\n");
  EXPECT_TRUE(fs::exists(out.path() / "timeseries.csv"));

  // With nothing of the user's in figures/, the emptied folder goes too.
  fs::remove(figs / "my_sketch.png");
  fs::remove(figs / "crank_speed_vs_angle.txt");
  const auto plot = runRollerdyn({"simulate", scene, "--model", "reduced", "--set", "simulation.t_end=1", "--plot",
                                  "--out", out.str()});
  ASSERT_EQ(plot.exit_code, 0) << plot.err;
  const auto third = runRollerdyn({"simulate", scene, "--model", "reduced", "--set", "simulation.t_end=1", "--out",
                                   out.str()});
  ASSERT_EQ(third.exit_code, 0) << third.err;
  EXPECT_FALSE(fs::exists(figs));
}

// `plot DIR` from another working directory still finds the scene (and so the Kloss curve).
TEST(CliOutputFolder, ReadableFromAnyWorkingDirectory) {
  TempDir out("anywhere");
  TempDir elsewhere("cwd");
  // Relative scene path, run from the source tree (the test helper's working directory).
  const auto sim = runRollerdyn({"simulate", "model/recuperative-2cart.yaml", "--model", "reduced", "--set",
                                 "simulation.t_end=1", "--out", out.str()});
  ASSERT_EQ(sim.exit_code, 0) << sim.err;
  const auto summary = nlohmann::json::parse(slurp(out.path() / "summary.json"));
  EXPECT_EQ(summary["scene_path"], (fs::path(ROLLERDYN_SOURCE_DIR) / "model/recuperative-2cart.yaml").lexically_normal().string());
  const auto plot = runRollerdynIn(elsewhere.str(), {"plot", out.str()});
  ASSERT_EQ(plot.exit_code, 0) << plot.err;
  EXPECT_EQ(plot.err.find("not found from here"), std::string::npos) << plot.err;
  EXPECT_EQ(plot.out.find("without its Kloss curve"), std::string::npos) << plot.out;
  EXPECT_TRUE(fs::exists(out.path() / "figures" / "motor_operating_point.png"));
}

}  // namespace
}  // namespace rollerdyn
