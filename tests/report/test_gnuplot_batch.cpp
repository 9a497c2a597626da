// Several figures drawn by a few gnuplot processes (renderPlots): the same files, byte for byte, as
// one gnuplot per figure (renderPlot), and a figure that fails is named.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "report/Gnuplot.h"

namespace rollerdyn {
namespace {

namespace fs = std::filesystem;

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

fs::path freshDir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("rollerdyn_batch_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// Three line plots (one with settings a later figure must not inherit: log scale, ranges) and a
// heat map.
std::vector<PlotJob> jobsIn(const fs::path& dir) {
  std::vector<PlotJob> jobs;
  PlotSpec a;
  a.title = "first";
  a.xlabel = "t [s]";
  a.ylabel = "y [-]";
  a.logy = true;
  a.preamble = "set xrange [0:3]";
  a.series.push_back({"a", {0.5, 1, 2, 3}, {1, 10, 100, 1000}});
  jobs.push_back(plotJob(a, (dir / "first").string()));
  PlotSpec b;
  b.title = "second";
  b.series.push_back({"b", {0, 1, 2}, {-1, 0.5, -0.25}});
  jobs.push_back(plotJob(b, (dir / "second").string()));
  PlotSpec c = b;
  c.title = "third";
  jobs.push_back(plotJob(c, (dir / "third").string(), true, false));
  jobs.push_back(heatMapJob("map", "x", "y", "z", {1, 2, 3}, {0, 1}, {{1, 2, 3}, {4, 5, 6}}, (dir / "map").string()));
  return jobs;
}

}  // namespace

TEST(GnuplotBatch, FiguresDrawnTogetherEqualFiguresDrawnOneProcessEach) {
  if (!gnuplotAvailable()) GTEST_SKIP() << "gnuplot not installed";
  const fs::path one = freshDir("one"), together = freshDir("together");
  for (const PlotJob& j : jobsIn(one)) renderPlots({j}, 1);  // one gnuplot per figure, as renderPlot()
  renderPlots(jobsIn(together), 2);                          // two processes, two figures each
  for (const char* f : {"first.png", "first.svg", "second.png", "second.svg", "third.png", "map.png", "map.svg"}) {
    ASSERT_TRUE(fs::exists(together / f)) << f;
    EXPECT_EQ(slurp((one / f).string()), slurp((together / f).string())) << f;
  }
  EXPECT_FALSE(fs::exists(together / "third.svg"));  // asked for PNG only
  for (const auto& e : fs::directory_iterator(together))  // no temporary file or script left
    EXPECT_EQ(e.path().string().find(".tmp."), std::string::npos) << e.path();
  fs::remove_all(one);
  fs::remove_all(together);
}

TEST(GnuplotBatch, FigureThatFailsInABatchIsNamedAndTheOthersAreDrawn) {
  if (!gnuplotAvailable()) GTEST_SKIP() << "gnuplot not installed";
  const fs::path dir = freshDir("fail");
  std::vector<PlotJob> jobs = jobsIn(dir);
  jobs[1].script = "this is no gnuplot command\n";
  try {
    renderPlots(jobs, 1);  // all four in one process: gnuplot stops at the second
    FAIL() << "no error for a figure gnuplot cannot draw";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("second.png"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::exists(dir / "first.png"));
  EXPECT_TRUE(fs::exists(dir / "first.svg"));
  EXPECT_FALSE(fs::exists(dir / "second.png"));
  fs::remove_all(dir);
}

}  // namespace rollerdyn
