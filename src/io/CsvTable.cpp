#include "io/CsvTable.h"

#include <cerrno>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

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

Table readAnnotatedCsvFile(const std::string& path, const std::string& what) {
  std::istringstream in(readFileContents(path, what));
  std::string text, line;
  while (std::getline(in, line)) text += (line.compare(0, 1, "#") == 0 ? std::string() : line) + "\n";
  return parseCsv(text, path);
}

}  // namespace rollerdyn
