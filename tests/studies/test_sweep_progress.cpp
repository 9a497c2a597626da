// Saved rows and --resume (src/studies/SweepProgress.h, SweepExecution.h), in-process: the
// JSON of a point reads back to the same doubles, the progress file skips a line cut by a kill,
// refuses rows of another sweep, and a resumed sweep computes only the missing points.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>

#include "cli/CliTestSupport.h"
#include "studies/SweepExecution.h"
#include "studies/SweepProgress.h"

namespace rollerdyn {
namespace {

const std::string kScene = std::string(ROLLERDYN_SOURCE_DIR) + "/model/recuperative-2cart.yaml";

SweepOptions smallSweep() {
  SweepOptions o;
  o.scene_path = kScene;
  o.base_overrides = {"simulation.t_end=4", "simulation.steady_window_revolutions=2"};
  o.params = {parseSweepValues("crank.offset_deg", "0:150:30")};  // 6 points
  o.model = "reduced";
  return o;
}

void expectSameMetrics(const SweepPoint& a, const SweepPoint& b, const std::string& where) {
  ASSERT_EQ(a.metrics.size(), b.metrics.size()) << where;
  for (std::size_t k = 0; k < a.metrics.size(); ++k) {
    if (std::isnan(a.metrics[k])) EXPECT_TRUE(std::isnan(b.metrics[k])) << where << " metric " << k;
    else EXPECT_EQ(a.metrics[k], b.metrics[k]) << where << " metric " << k;
  }
  EXPECT_EQ(a.status, b.status) << where;
  EXPECT_EQ(a.steady, b.steady) << where;
  EXPECT_EQ(a.complete, b.complete) << where;
  EXPECT_EQ(a.texts, b.texts) << where;
}

TEST(SweepProgress, PointJsonRoundTripsExactly) {
  SweepPoint p;
  p.texts = {"0.1", "rigid"};
  p.values = {0.1, std::numeric_limits<double>::quiet_NaN()};
  p.metrics.assign(sweepNumericMetrics().size(), std::numeric_limits<double>::quiet_NaN());
  p.metrics[0] = 1.0 / 3.0;        // needs all 17 digits
  p.metrics[1] = 6.02214076e23;
  p.metrics[2] = -4.9406564584124654e-324;  // smallest subnormal
  p.ran = p.complete = true;
  p.status = "status with \"quotes\",\nand a newline";
  p.cpu_seconds = 0.125;
  p.warnings = nlohmann::json::array({{{"harmonic", 2}}});
  const SweepPoint q = sweepPointFromJson(nlohmann::json::parse(sweepPointToJson(p).dump()));
  expectSameMetrics(p, q, "round trip");
  EXPECT_EQ(q.values[0], 0.1);
  EXPECT_TRUE(std::isnan(q.values[1]));
  EXPECT_EQ(q.cpu_seconds, 0.125);
  EXPECT_EQ(q.warnings, p.warnings);
}

TEST(SweepProgress, FingerprintFollowsWhatDeterminesTheRows) {
  SweepOptions o = smallSweep();
  const auto d = sweepDesigns(o).texts;
  const std::string f = sweepFingerprint(o, d);
  EXPECT_EQ(f.size(), 16u);
  EXPECT_EQ(sweepFingerprint(o, d), f);
  SweepOptions other = o;
  other.base_overrides.push_back("coupling.damping=3000");
  EXPECT_NE(sweepFingerprint(other, d), f);
  other = o;
  other.model = "multibody";
  EXPECT_NE(sweepFingerprint(other, d), f);
  auto d2 = d;
  d2.back()[0] = "151";
  EXPECT_NE(sweepFingerprint(o, d2), f);
}

TEST(SweepProgress, ResumeComputesOnlyTheMissingPointsAndGivesTheSameRows) {
  test::TempDir dir("progress");
  SweepOptions o = smallSweep();
  o.progress_path = dir.str() + "/sweep.progress.jsonl";
  const SweepResult full = runSweep(o);
  ASSERT_EQ(full.points.size(), 6u);
  EXPECT_EQ(full.execution["points_computed"], 6);
  EXPECT_EQ(full.execution["points_resumed"], 0);
  // Keep the header and three rows, and cut the fourth in the middle, as a kill mid-write would.
  std::ifstream in(o.progress_path);
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  ASSERT_EQ(lines.size(), 7u);
  {
    std::ofstream out(o.progress_path, std::ios::trunc);
    for (int i = 0; i < 4; ++i) out << lines[i] << '\n';
    out << lines[4].substr(0, lines[4].size() / 2);
  }
  std::vector<std::size_t> computed;
  o.resume = true;
  o.on_point = [&](const SweepPoint& p, std::size_t, std::size_t) { computed.push_back(std::size_t(p.values[0] / 30)); };
  const SweepResult resumed = runSweep(o);
  EXPECT_EQ(resumed.execution["points_resumed"], 3);
  EXPECT_EQ(resumed.execution["points_computed"], 3);
  EXPECT_EQ(computed.size(), 3u);
  for (std::size_t i = 0; i < 6; ++i) expectSameMetrics(full.points[i], resumed.points[i], "point " + std::to_string(i));
  // The file is whole again: resuming once more computes nothing.
  computed.clear();
  const SweepResult again = runSweep(o);
  EXPECT_EQ(again.execution["points_resumed"], 6);
  EXPECT_TRUE(computed.empty());
}

TEST(SweepProgress, ResumeRefusesRowsOfAnotherSweep) {
  test::TempDir dir("progress-other");
  SweepOptions o = smallSweep();
  o.params = {parseSweepValues("crank.offset_deg", "0,90")};
  o.progress_path = dir.str() + "/sweep.progress.jsonl";
  runSweep(o);
  o.base_overrides.push_back("coupling.damping=3000");
  o.resume = true;
  try {
    runSweep(o);
    FAIL() << "rows of a different sweep were reused";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("different sweep"), std::string::npos) << e.what();
  }
  // A damaged line that is not the last one is an error naming file and line.
  std::ofstream(o.progress_path, std::ios::app) << "garbage\n{\"index\":0}\n";
  o.base_overrides.pop_back();
  try {
    runSweep(o);
    FAIL() << "a damaged progress file was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("sweep.progress.jsonl:4:"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace rollerdyn
