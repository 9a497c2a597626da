#include "report/OutputFolder.h"

#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "io/AtomicFile.h"
#include "io/ReadFile.h"

namespace rollerdyn {

namespace {

// The CSV file at `path` into `table`, when it exists (`present` says whether it did).
void readCsvIfPresent(const std::string& path, Table& table, bool& present) {
  if (!std::filesystem::exists(path)) return;
  table = readCsvFile(path);
  present = true;
}

// summary.json at `path`: a JSON object, or an error naming the file.
nlohmann::json readSummary(const std::string& path) {
  nlohmann::json summary;
  try {
    summary = nlohmann::json::parse(readFileContents(path));
  } catch (const nlohmann::json::parse_error& e) {
    throw std::runtime_error(path + ": expected JSON, got a parse error: " + e.what());
  }
  if (!summary.is_object()) throw std::runtime_error(path + ": expected a JSON object");
  return summary;
}

}  // namespace

OutputFolder readOutputFolder(const std::string& dir) {
  namespace fs = std::filesystem;
  if (!fs::is_directory(dir)) throw std::runtime_error("'" + dir + "' is not a folder");
  OutputFolder out;
  out.dir = dir;
  const auto file = [&dir](const char* name) { return (fs::path(dir) / name).string(); };
  readCsvIfPresent(file("timeseries.csv"), out.timeseries, out.has_timeseries);
  readCsvIfPresent(file("reactions.csv"), out.reactions, out.has_reactions);
  readCsvIfPresent(file("comparison.csv"), out.comparison, out.has_comparison);
  if (fs::exists(file("summary.json"))) {
    out.summary = readSummary(file("summary.json"));
    out.has_summary = true;
  }
  if (!out.has_timeseries && !out.has_reactions && !out.has_comparison && !out.has_summary)
    throw std::runtime_error("'" + dir +
                             "' holds none of timeseries.csv, reactions.csv, summary.json, "
                             "comparison.csv (an output folder of simulate or compare)");
  return out;
}

void writeRunTables(const std::string& dir, const RunResult& run) {
  namespace fs = std::filesystem;
  writeCsvAtomic(dir + "/timeseries.csv", run.timeseries);
  writeCsvAtomic(dir + "/crank_speed_extrema.csv", crankSpeedExtremaTable(run.crank_speed_extrema));
  const std::string reactions = (fs::path(dir) / "reactions.csv").string();
  if (!run.reactions.columns.empty()) {
    writeCsvAtomic(reactions, run.reactions);
  } else {
    std::error_code ec;
    fs::remove(reactions, ec);
    if (ec) throw std::runtime_error("cannot remove the earlier run's '" + reactions + "': " + ec.message());
  }
}

OutputFolder outputFolderOf(const std::string& dir, const RunResult& run, const nlohmann::json& summary) {
  namespace fs = std::filesystem;
  OutputFolder out;
  out.dir = dir;
  out.timeseries = run.timeseries;
  out.reactions = run.reactions;
  out.summary = summary;
  out.has_timeseries = out.has_summary = true;
  out.has_reactions = !run.reactions.columns.empty();
  const std::string comparison = (fs::path(dir) / "comparison.csv").string();
  if (fs::exists(comparison)) {
    out.comparison = readCsvFile(comparison);
    out.has_comparison = true;
  }
  return out;
}

}  // namespace rollerdyn
