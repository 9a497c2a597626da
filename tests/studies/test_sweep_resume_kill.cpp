// A sweep killed with SIGKILL (what a cluster's wall-time limit or a lost node amounts to)
// keeps every row it finished; `--resume` computes only the missing points and the final rows
// equal those of an uninterrupted run. Real process, real signal.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <thread>

#include "studies/SweepCliSupport.h"

namespace rollerdyn {
namespace {

using test::model;

constexpr int kPoints = 24;

std::vector<std::string> sweepArgs(const std::string& out) {
  // About 0.1 s of CPU per point (reduced model, 20 s simulated), one thread: a few seconds.
  return {"sweep", model("recuperative-2cart.yaml"), "--param", "crank.offset_deg", "--values", "0:172.5:7.5",
          "--set", "simulation.t_end=20", "--model", "reduced", "--threads", "1", "--out", out};
}

// Whole rows saved in a progress file (a line cut by the kill does not parse).
int savedRows(const std::string& path) {
  std::ifstream in(path);
  int rows = 0;
  std::string line;
  for (bool header = true; std::getline(in, line); header = false) {
    if (header) continue;
    try {
      if (nlohmann::json::parse(line).contains("point")) ++rows;
    } catch (const nlohmann::json::exception&) {
    }
  }
  return rows;
}

TEST(SweepResume, AfterSigkillOnlyTheMissingPointsAreComputed) {
  test::TempDir dir("sweep-kill");
  const std::string out = dir.str() + "/out", progress = out + "/sweep.progress.jsonl";
  const pid_t pid = test::startRollerdyn(sweepArgs(out), dir.path());
  const auto t0 = std::chrono::steady_clock::now();
  while (savedRows(progress) < 3 &&
         std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() < 120)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ::kill(pid, SIGKILL);
  const test::CliResult killed = test::waitRollerdyn(pid, dir.path());
  ASSERT_EQ(killed.signal, SIGKILL) << "the sweep ended before the kill: " << killed.out;
  const int saved = savedRows(progress);
  ASSERT_GE(saved, 3);
  ASSERT_LT(saved, kPoints) << "every point was done before the kill: nothing to resume";
  EXPECT_FALSE(std::filesystem::exists(out + "/sweep.csv"));  // final files only at the end

  auto resume_args = sweepArgs(out);
  resume_args.push_back("--resume");
  const test::CliResult resumed = test::runRollerdyn(resume_args, 300);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  const auto j = test::sweepJson(out);
  EXPECT_EQ(j["points_resumed"], saved);
  EXPECT_EQ(j["points_computed"], kPoints - saved);
  EXPECT_NE(resumed.out.find("resumed " + std::to_string(saved) + " saved point(s), computed " +
                             std::to_string(kPoints - saved)),
            std::string::npos)
      << resumed.out;
  // Only the missing points were printed as computed: kPoints - saved progress lines.
  std::size_t lines = 0;
  for (std::size_t at = 0; (at = resumed.out.find("crank.offset_deg=", at)) != std::string::npos; ++at) ++lines;
  EXPECT_EQ(lines, std::size_t(kPoints - saved));

  const std::string whole = dir.str() + "/whole";
  const test::CliResult uninterrupted = test::runRollerdyn(sweepArgs(whole), 300);
  ASSERT_EQ(uninterrupted.exit_code, 0) << uninterrupted.err;
  EXPECT_EQ(test::csvWithoutCpu(out), test::csvWithoutCpu(whole));
  test::expectSameRows(test::sweepJson(out), test::sweepJson(whole));
}

TEST(SweepResume, ADifferentSweepIsRefusedWithExitCode2) {
  test::TempDir dir("sweep-refuse");
  const std::string out = dir.str() + "/out";
  auto args = sweepArgs(out);
  args[5] = "0,90";
  ASSERT_EQ(test::runRollerdyn(args, 120).exit_code, 0);
  args[5] = "0,60";
  args.push_back("--resume");
  const test::CliResult r = test::runRollerdyn(args, 120);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("saved by a different sweep"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace rollerdyn
