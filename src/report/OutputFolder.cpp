#include "report/OutputFolder.h"

#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "io/AtomicFile.h"
#include "io/ReadFile.h"

namespace rollerdyn {

namespace {

std::vector<std::string> splitFields(const std::string& line) {
  std::vector<std::string> out;
  size_t start = 0;
  while (true) {
    const size_t comma = line.find(',', start);
    out.push_back(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

}  // namespace

Table parseCsv(const std::string& text, const std::string& file_label, CsvLayout* layout) {
  Table table;
  std::istringstream in(text);
  std::string line;
  int line_no = 0;
  bool header = true;
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    const std::vector<std::string> fields = splitFields(line);
    if (header) {
      for (const std::string& f : fields)
        if (f.empty())
          throw std::runtime_error(file_label + ":" + std::to_string(line_no) +
                                   ": expected a header of column names, got an empty name");
      for (const std::string& f : fields) table.columns.push_back(stripUnit(f));  // io/Table.h
      if (layout) {
        layout->header = fields;
        layout->header_line = line_no;
      }
      header = false;
      continue;
    }
    if (fields.size() != table.columns.size())
      throw std::runtime_error(file_label + ":" + std::to_string(line_no) + ": expected " +
                               std::to_string(table.columns.size()) + " fields, got " +
                               std::to_string(fields.size()));
    std::vector<double> row;
    row.reserve(fields.size());
    for (std::size_t c = 0; c < fields.size(); ++c) {
      const std::string& f = fields[c];
      char* end = nullptr;
      errno = 0;
      const double v = std::strtod(f.c_str(), &end);
      if (f.empty() || end != f.c_str() + f.size())
        throw std::runtime_error(file_label + ":" + std::to_string(line_no) + ": column '" + table.columns[c] +
                                 "' (column " + std::to_string(c + 1) + "): expected a number, got '" + f + "'");
      row.push_back(v);
    }
    table.rows.push_back(std::move(row));
    if (layout) layout->row_lines.push_back(line_no);
  }
  if (header) throw std::runtime_error(file_label + ": expected a header row, got an empty file");
  return table;
}

Table readCsvFile(const std::string& path, CsvLayout* layout) {
  return parseCsv(readFileContents(path), path, layout);
}

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
