// Reading back an output folder of `rollerdyn simulate` (timeseries.csv, reactions.csv,
// summary.json) and/or `rollerdyn compare` (comparison.csv), for `plot` and `report`.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "analysis/RunResult.h"
#include "io/Table.h"

namespace rollerdyn {

// Where parseCsv found what, for a reader that checks more than the table's shape (measured data:
// each header's unit, each row's time): the header cells as written and the file line of each row.
struct CsvLayout {
  std::vector<std::string> header;  // header cells as written, e.g. "omega_crank[rad/s]"
  int header_line = 0;              // file line (from 1) of the header
  std::vector<int> row_lines;       // file line (from 1) of each row of the table
};

// Parses CSV as written by toCsv() (src/io/AtomicFile.h): a header row of column names, then
// rows of numbers ("nan", "inf" accepted). Throws std::runtime_error naming file and line for a
// missing header, a row with the wrong number of fields or a field that is not a number (and its column).
// `layout` (optional) receives the header cells as written and each row's line.
Table parseCsv(const std::string& text, const std::string& file_label, CsvLayout* layout = nullptr);
Table readCsvFile(const std::string& path, CsvLayout* layout = nullptr);

struct OutputFolder {
  std::string dir;
  bool has_timeseries = false, has_reactions = false, has_summary = false, has_comparison = false;
  Table timeseries;          // timeseries.csv
  Table reactions;           // reactions.csv
  Table comparison;          // comparison.csv (from `rollerdyn compare`)
  nlohmann::json summary;    // summary.json (null when absent)
};

// Reads whichever of the four files exist in `dir`. Throws std::runtime_error if `dir` is not a
// folder, holds none of them, or one of them is malformed (the message names the file).
OutputFolder readOutputFolder(const std::string& dir);

// Writes a run's tables into `dir` atomically: timeseries.csv, and reactions.csv when the run
// computed reactions; otherwise a reactions.csv left by an earlier run is removed, so the folder
// never mixes two runs.
void writeRunTables(const std::string& dir, const RunResult& run);

// The folder a run has just been written to, from the tables still in memory (simulate --plot,
// report); comparison.csv is read from `dir` if a `compare` run left one there.
OutputFolder outputFolderOf(const std::string& dir, const RunResult& run, const nlohmann::json& summary);

}  // namespace rollerdyn
