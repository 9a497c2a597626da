// The interactive time plots: which plots the tables give, sampling, and the section with the
// library inlined or, without it, a note instead of charts.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "report/TimePlots.h"

namespace rollerdyn {
namespace {

namespace fs = std::filesystem;

Table table(std::vector<std::string> columns, size_t rows) {
  Table t;
  t.columns = std::move(columns);
  for (size_t i = 0; i < rows; ++i) {
    std::vector<double> row;
    for (size_t c = 0; c < t.columns.size(); ++c) row.push_back(c == 0 ? 0.01 * i : 100.0 * c + i);
    t.rows.push_back(row);
  }
  return t;
}

const std::vector<std::string> kSeries = {"t", "omega_crank", "omega_motor", "coupling_torque", "motor_torque", "x_cart_1"};
const std::vector<std::string> kReactions = {"t", "N_front_1", "N_rear_1", "F_rod_1", "N_front_2", "N_rear_2", "F_rod_2"};

TEST(TimePlots, FourPlotsSampledFromTheTables) {
  const auto plots = mainTimePlots(table(kSeries, 10), table(kReactions, 10), 4);
  ASSERT_EQ(plots.size(), 4u);
  EXPECT_EQ(plots[0].id, "speed");
  EXPECT_EQ(plots[1].id, "torque");
  EXPECT_EQ(plots[2].id, "rod_forces");
  EXPECT_EQ(plots[3].id, "guide_reactions");
  // 10 rows, at most 4 points: every 3rd row.
  EXPECT_EQ(plots[0].t, (std::vector<double>{0.0, 0.03, 0.06, 0.09}));
  EXPECT_EQ(plots[0].lines[0].y, (std::vector<double>{100, 103, 106, 109}));  // omega_crank = 100 + row
  ASSERT_EQ(plots[2].lines.size(), 2u);
  EXPECT_EQ(plots[2].lines[1].label, "F_rod_2");
  EXPECT_EQ(plots[2].lines[1].y.front(), 600.0);
  ASSERT_EQ(plots[3].lines.size(), 4u);
  EXPECT_FALSE(plots[3].lines[0].dashed);
  EXPECT_TRUE(plots[3].lines[1].dashed) << "N_rear dashed beside N_front of the same colour";
}

TEST(TimePlots, ReactionsOnOtherRowsOrMissingColumnsAreLeftOut) {
  EXPECT_EQ(mainTimePlots(table(kSeries, 10), table(kReactions, 9)).size(), 2u);
  EXPECT_EQ(mainTimePlots(table({"t", "omega_crank"}, 5), Table{}).size(), 1u);
  EXPECT_TRUE(mainTimePlots(Table{}, Table{}).empty());
}

TEST(TimePlots, SectionInlinesTheLibraryOrSaysItIsMissing) {
  const auto plots = mainTimePlots(table(kSeries, 10), table(kReactions, 10));
  const fs::path lib = fs::temp_directory_path() / ("rollerdyn-fake-chart-" + std::to_string(::getpid()) + ".js");
  { std::ofstream(lib) << "window.FakeChartLibrary = '</script>';"; }
  const std::string h = timePlotsHtml(plots, lib.string(), 0.02, 0.08);
  fs::remove(lib);
  EXPECT_NE(h.find("window.FakeChartLibrary = '<\\/script>';"), std::string::npos);
  for (const char* id : {"plot-speed", "plot-torque", "plot-rod_forces", "plot-guide_reactions", "plots-data", "view-steady"})
    EXPECT_NE(h.find(id), std::string::npos) << id;
  EXPECT_NE(h.find("\"steady_begin\":0.02"), std::string::npos);

  const std::string none = timePlotsHtml(plots, "/nonexistent/chart.min.js", 0, 0);
  EXPECT_NE(none.find("Interactive time plots left out"), std::string::npos);
  EXPECT_NE(none.find("libjs-chart.js"), std::string::npos);
  EXPECT_EQ(none.find("<canvas"), std::string::npos);
  EXPECT_EQ(none.find("<script"), std::string::npos);
}

}  // namespace
}  // namespace rollerdyn
