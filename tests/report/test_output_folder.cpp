// Reading output folders back: CSV written by toCsv() round-trips (NaN included), malformed CSV
// and folders are reported with file and line; the published tables through the same reader.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "io/AtomicFile.h"
#include "report/OutputFolder.h"
#include "support/FreshTempDir.h"
#include "support/ThrownMessage.h"

namespace rollerdyn {
namespace {

namespace fs = std::filesystem;

using test::messageOf;

fs::path freshDir(const std::string& tag) { return test::freshTempDir("report-" + tag); }

TEST(ReportCsv, RoundTripsToCsv) {
  Table t;
  t.columns = {"t", "omega_crank", "N_front_1"};
  t.rows = {{0, 1.5, -2e5}, {0.002, NAN, 3.25e-7}, {0.004, INFINITY, 1.0 / 3.0}};
  const Table back = parseCsv(toCsv(t), "x.csv");
  ASSERT_EQ(back.columns, t.columns);
  ASSERT_EQ(back.rows.size(), 3u);
  EXPECT_DOUBLE_EQ(back.rows[0][2], -2e5);
  EXPECT_TRUE(std::isnan(back.rows[1][1]));
  EXPECT_TRUE(std::isinf(back.rows[2][1]));
  EXPECT_NEAR(back.rows[2][2], 1.0 / 3.0, 1e-12);
}

// A run without reactions (simulation.reactions: false) into a folder that holds an earlier
// run's reactions.csv: the stale file goes, so the folder never mixes two runs.
TEST(RunTables, RunWithoutReactionsRemovesTheEarlierRunsReactions) {
  const fs::path dir = freshDir("run-tables");
  RunResult with;
  with.timeseries.columns = {"t", "omega_crank"};
  with.timeseries.rows = {{0, 1}, {1, 2}};
  with.reactions.columns = {"t", "N_front_1"};
  with.reactions.rows = {{0, 5}, {1, 6}};
  writeRunTables(dir.string(), with);
  ASSERT_TRUE(fs::exists(dir / "reactions.csv"));
  EXPECT_EQ(readOutputFolder(dir.string()).reactions.rows.size(), 2u);

  RunResult without = with;
  without.reactions = Table{};
  without.timeseries.rows = {{0, 3}};
  writeRunTables(dir.string(), without);
  EXPECT_FALSE(fs::exists(dir / "reactions.csv"));
  const OutputFolder back = readOutputFolder(dir.string());
  EXPECT_FALSE(back.has_reactions);
  ASSERT_EQ(back.timeseries.rows.size(), 1u);
  EXPECT_EQ(back.timeseries.rows[0][1], 3.0);
  fs::remove_all(dir);
}

// The CSV numbers are what an ostream with precision 12 writes (printf's %.12g), the format the
// files always had: same text for ordinary, tiny, huge, negative and non-finite values.
TEST(ReportCsv, NumbersAsAStreamWithPrecision12WritesThem) {
  const std::vector<double> values = {0.0, -0.0, 1.0, 0.1, 1.0 / 3.0, -2.0 / 3.0, 1e-5, 123456789012.5,
                                      1234567890123456.0, 1e21, -2.5e-300, 4.9e-324, 1.7976931348623157e308,
                                      NAN, INFINITY, -INFINITY, 299.99999999999994};
  Table t;
  t.columns = {"x"};
  std::ostringstream expected;
  expected.precision(12);
  expected << "x\n";
  for (double v : values) {
    t.rows.push_back({v});
    expected << v << '\n';
  }
  EXPECT_EQ(toCsv(t), expected.str());
}

TEST(ReportCsv, MalformedInputNamesFileAndLine) {
  EXPECT_EQ(messageOf([] { parseCsv("", "a.csv"); }), "a.csv: expected a header row, got an empty file");
  EXPECT_EQ(messageOf([] { parseCsv("t,x\n1,2\n3\n", "a.csv"); }), "a.csv:3: expected 2 fields, got 1");
  EXPECT_EQ(messageOf([] { parseCsv("t,x\n1,abc\n", "a.csv"); }), "a.csv:2: column 'x' (column 2): expected a number, got 'abc'");
  EXPECT_EQ(messageOf([] { parseCsv("t,x\n1,\n", "a.csv"); }), "a.csv:2: column 'x' (column 2): expected a number, got ''");
  EXPECT_EQ(messageOf([] { parseCsv("t,,x\n", "a.csv"); }),
            "a.csv:1: expected a header of column names, got an empty name");
  EXPECT_NO_THROW(parseCsv("t,x\r\n1,2\r\n", "crlf.csv"));
}

// A published table (validation/published): '#' lines are comments, the others the convention's
// table; a bad row is named by its line in the file, comments counted.
TEST(ReportCsv, AnnotatedTableSkipsCommentsAndKeepsLineNumbers) {
  const fs::path f = freshDir("annotated") / "table.csv";
  std::ofstream(f) << "# Source: a paper\n# Columns (units): x [m]\nx,y\n1,2\r\n# a note\n3,4\n5,five\n";
  EXPECT_EQ(messageOf([&] { readAnnotatedCsvFile(f.string()); }),
            f.string() + ":7: column 'y' (column 2): expected a number, got 'five'");
  std::ofstream(f) << "# Source: a paper\nx,y\n1,2\n# a note\n3,4\n";
  const Table t = readAnnotatedCsvFile(f.string());
  EXPECT_EQ(t.columns, (std::vector<std::string>{"x", "y"}));
  EXPECT_EQ(t.rows, (std::vector<std::vector<double>>{{1, 2}, {3, 4}}));
}

TEST(ReportOutputFolder, ReadsWhatIsThere) {
  const fs::path d = freshDir("folder");
  EXPECT_NE(messageOf([&] { readOutputFolder(d.string()); }).find("holds none of timeseries.csv"),
            std::string::npos);
  EXPECT_NE(messageOf([&] { readOutputFolder((d / "missing").string()); }).find("is not a folder"),
            std::string::npos);
  { std::ofstream(d / "summary.json") << "{\"scene\": \"x\""; }
  EXPECT_NE(messageOf([&] { readOutputFolder(d.string()); }).find("summary.json: expected JSON"), std::string::npos);
  { std::ofstream(d / "summary.json") << "{\"scene\": \"x\"}"; }
  { std::ofstream(d / "comparison.csv") << "t,omega_crank_multibody,omega_crank_reduced\n0,1,1\n"; }
  const OutputFolder f = readOutputFolder(d.string());
  EXPECT_TRUE(f.has_summary);
  EXPECT_TRUE(f.has_comparison);
  EXPECT_FALSE(f.has_timeseries);
  EXPECT_FALSE(f.has_reactions);
  EXPECT_EQ(f.summary["scene"], "x");
  fs::remove_all(d);
}

}  // namespace
}  // namespace rollerdyn
