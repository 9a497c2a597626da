#include "report/OutputFolder.h"

#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "io/AtomicFile.h"
#include "io/ReadFile.h"

namespace rollerdyn {

OutputFolder readOutputFolder(const std::string& dir) {
  namespace fs = std::filesystem;
  if (!fs::is_directory(dir)) throw std::runtime_error("'" + dir + "' is not a folder");
  OutputFolder out;
  out.dir = dir;
  const auto file = [&dir](const char* name) { return (fs::path(dir) / name).string(); };
  if (fs::exists(file("timeseries.csv"))) {
    out.timeseries = readCsvFile(file("timeseries.csv"));
    out.has_timeseries = true;
  }
  if (fs::exists(file("reactions.csv"))) {
    out.reactions = readCsvFile(file("reactions.csv"));
    out.has_reactions = true;
  }
  if (fs::exists(file("comparison.csv"))) {
    out.comparison = readCsvFile(file("comparison.csv"));
    out.has_comparison = true;
  }
  if (fs::exists(file("summary.json"))) {
    try {
      out.summary = nlohmann::json::parse(readFileContents(file("summary.json")));
    } catch (const nlohmann::json::parse_error& e) {
      throw std::runtime_error(file("summary.json") + ": expected JSON, got a parse error: " + e.what());
    }
    if (!out.summary.is_object())
      throw std::runtime_error(file("summary.json") + ": expected a JSON object");
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
