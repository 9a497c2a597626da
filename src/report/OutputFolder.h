// Reading back an output folder of `rollerdyn simulate` (timeseries.csv, reactions.csv,
// summary.json) and/or `rollerdyn compare` (comparison.csv), for `plot` and `report`.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "analysis/RunResult.h"
#include "io/CsvTable.h"  // parseCsv, readCsvFile: the reader of the tables read back here
#include "io/Table.h"

namespace rollerdyn {

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
