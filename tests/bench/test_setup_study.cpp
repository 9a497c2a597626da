// `bench --study setup` (bench/SetupStudy.h): the medians of each task's phases over the
// repetitions, and the files that show them.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "bench/SetupStudy.h"
#include "io/ReadFile.h"

namespace rollerdyn::bench {
namespace {

SetupSample sample(const std::string& task, double run_wall, double run_cpu, double figures_child) {
  return {task, {{"run", run_wall, run_cpu, 0.0}, {"figures", 0.5, 0.01, figures_child}}};
}

}  // namespace

TEST(SetupStudy, MedianOfEachPhaseOverTheRepetitions) {
  const std::vector<SetupSample> samples = {sample("report", 3.0, 2.0, 1.0), sample("short run", 0.1, 0.05, 0.0),
                                            sample("report", 1.0, 0.5, 3.0), sample("report", 2.0, 1.0, 2.0),
                                            sample("short run", 0.3, 0.07, 0.0)};
  const std::vector<SetupRow> rows = setupRows(samples);
  ASSERT_EQ(rows.size(), 4u);  // (report, run), (report, figures), (short run, run), (short run, figures)
  EXPECT_EQ(rows[0].task, "report");
  EXPECT_EQ(rows[0].phase, "run");
  EXPECT_EQ(rows[0].repeats, 3);
  EXPECT_DOUBLE_EQ(rows[0].wall, 2.0);  // median of 3, 1, 2
  EXPECT_DOUBLE_EQ(rows[0].cpu, 1.0);   // of 2, 0.5, 1
  EXPECT_EQ(rows[1].phase, "figures");
  EXPECT_DOUBLE_EQ(rows[1].child_cpu, 2.0);  // of 1, 3, 2
  EXPECT_EQ(rows[2].task, "short run");
  EXPECT_DOUBLE_EQ(rows[2].wall, 0.2);  // even count: mean of the middle two, 0.1 and 0.3
  EXPECT_DOUBLE_EQ(rows[2].cpu, 0.06);
}

TEST(SetupStudy, PhaseWithoutWallTimeStaysWithoutAndIsNotAddedTwice) {
  const std::vector<SetupSample> samples = {
      {"short run", {{"set-up and integration", 0.2, 0.1, 0.0}, {"of which the integration", NAN, 0.04, 0.0}}}};
  const std::vector<SetupRow> rows = setupRows(samples);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_TRUE(std::isnan(rows[1].wall));
  const std::string md = setupReport("scene", rows, "2 processors");
  // The task's total: 0.2 s wall and 0.1 s CPU (the integration's CPU is part of the 0.1 s).
  EXPECT_NE(md.find("## short run: 0.200 s wall, 0.100 s CPU"), std::string::npos) << md;
  EXPECT_NE(md.find("Machine: 2 processors"), std::string::npos);
}

TEST(SetupStudy, WritesCsvAndMarkdownWithTheMedians) {
  const std::string dir = (std::filesystem::temp_directory_path() / ("rollerdyn_setup_" + std::to_string(::getpid()))).string();
  std::filesystem::create_directories(dir);
  const std::vector<std::string> files =
      writeSetupStudy(dir, "balanced-4cart", setupRows({sample("report", 3.0, 2.0, 1.0)}), "2 processors");
  ASSERT_EQ(files.size(), 2u);
  const std::string csv = readFileContents(dir + "/setup.csv");
  EXPECT_NE(csv.find("task,phase,repeats,wall_s,cpu_s,child_cpu_s\n"), std::string::npos);
  EXPECT_NE(csv.find("report,\"run\",1,3.000000,2.000000,0.000000\n"), std::string::npos) << csv;
  EXPECT_NE(readFileContents(dir + "/setup.md").find("| figures | 0.500 | 0.010 | 1.000 | 1 |"), std::string::npos);
  std::filesystem::remove_all(dir);
}

}  // namespace rollerdyn::bench
