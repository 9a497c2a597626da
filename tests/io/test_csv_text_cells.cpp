// The CSV reader (io/CsvTable.h) on a table whose rows also hold text, as the studies' joined
// tables do: a text or empty cell reads as NaN, a comma inside "..." does not split a field, '#'
// lines are comments and the other lines keep their numbers; the reader of the tool's own tables
// still refuses such a cell.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "io/CsvTable.h"

using namespace rollerdyn;

namespace {

std::string writeTable(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / name;
  std::ofstream(path) << text;
  return path.string();
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace

TEST(CsvTextCells, TextAndEmptyCellsReadAsNaNBesideTheNumbers) {
  const std::string path = writeTable("rollerdyn_csv_text_cells.csv",
                                      "# a comment\nx[m],status,published\n1,\"stalled, at rest\",\n2.5,completed,7\n");
  CsvLayout layout;
  const Table t = readAnnotatedCsvFileWithText(path, "table", &layout);
  ASSERT_EQ(t.columns, (std::vector<std::string>{"x", "status", "published"}));
  EXPECT_EQ(layout.header, (std::vector<std::string>{"x[m]", "status", "published"}));
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.rows[0][0], 1.0);
  EXPECT_TRUE(std::isnan(t.rows[0][1]));  // the quoted comma did not split the status
  EXPECT_TRUE(std::isnan(t.rows[0][2]));
  EXPECT_EQ(t.rows[1][0], 2.5);
  EXPECT_TRUE(std::isnan(t.rows[1][1]));
  EXPECT_EQ(t.rows[1][2], 7.0);
  EXPECT_EQ(layout.row_lines, (std::vector<int>{3, 4}));
  std::filesystem::remove(path);
}

TEST(CsvTextCells, ARowWithTheWrongNumberOfFieldsNamesItsLineAfterComments) {
  const std::string path = writeTable("rollerdyn_csv_text_short.csv", "# comment\na,b\n1,2\n3\n");
  try {
    readAnnotatedCsvFileWithText(path);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_TRUE(contains(e.what(), "rollerdyn_csv_text_short.csv:4: expected 2 fields, got 1")) << e.what();
  }
  std::filesystem::remove(path);
}

TEST(CsvTextCells, TheToolsOwnTablesStillRefuseAText) {
  try {
    parseCsv("a,b\n1,\"x, y\"\n", "t.csv");
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    // Without text cells every comma splits, quotes included.
    EXPECT_TRUE(contains(e.what(), "t.csv:2: expected 2 fields, got 3")) << e.what();
  }
  try {
    parseCsv("a,b\n1,completed\n", "t.csv");
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_TRUE(contains(e.what(), "t.csv:2: column 'b' (column 2): expected a number, got 'completed'")) << e.what();
  }
}
