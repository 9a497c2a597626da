#include "io/CsvTable.h"

#include <cerrno>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "io/ReadFile.h"

namespace rollerdyn {

namespace {

// What a cell that is not a number means: in the tool's own tables and measured data, an error
// (naming file, line and column); in the studies' joined tables, text (a status, a motion) or a
// published value the paper does not give, read as NaN.
enum class TextCells { Rejected, AsNaN };

// The fields of one line. Text cells may hold commas inside "..." (a status text); the quotes are
// dropped. Without text cells every comma splits.
std::vector<std::string> splitFields(const std::string& line, TextCells text) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (char ch : line) {
    if (text == TextCells::AsNaN && ch == '"') quoted = !quoted;
    else if (ch == ',' && !quoted) out.emplace_back();
    else out.back() += ch;
  }
  return out;
}

std::string where(const std::string& file_label, int line_no) {
  return file_label + ":" + std::to_string(line_no) + ": ";
}

// The header's column names (units stripped) into table, and the header itself and its line into
// layout when one is asked for.
void readHeader(const std::vector<std::string>& fields, const std::string& file_label, int line_no, Table& table,
                CsvLayout* layout) {
  for (const std::string& f : fields)
    if (f.empty())
      throw std::runtime_error(where(file_label, line_no) + "expected a header of column names, got an empty name");
  for (const std::string& f : fields) table.columns.push_back(stripUnit(f));  // io/Table.h
  if (layout) {
    layout->header = fields;
    layout->header_line = line_no;
  }
}

std::vector<double> readRow(const std::vector<std::string>& fields, const std::string& file_label, int line_no,
                            const Table& table, TextCells text) {
  if (fields.size() != table.columns.size())
    throw std::runtime_error(where(file_label, line_no) + "expected " + std::to_string(table.columns.size()) +
                             " fields, got " + std::to_string(fields.size()));
  std::vector<double> row;
  row.reserve(fields.size());
  for (std::size_t c = 0; c < fields.size(); ++c) {
    const std::string& f = fields[c];
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(f.c_str(), &end);
    const bool number = !f.empty() && end == f.c_str() + f.size();
    if (!number && text == TextCells::Rejected)
      throw std::runtime_error(where(file_label, line_no) + "column '" + table.columns[c] + "' (column " +
                               std::to_string(c + 1) + "): expected a number, got '" + f + "'");
    row.push_back(number ? v : std::numeric_limits<double>::quiet_NaN());
  }
  return row;
}

Table parseTable(const std::string& text, const std::string& file_label, CsvLayout* layout, TextCells cells) {
  Table table;
  std::istringstream in(text);
  std::string line;
  int line_no = 0;
  bool header = true;
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    const std::vector<std::string> fields = splitFields(line, cells);
    if (header) {
      readHeader(fields, file_label, line_no, table, layout);
      header = false;
      continue;
    }
    table.rows.push_back(readRow(fields, file_label, line_no, table, cells));
    if (layout) layout->row_lines.push_back(line_no);
  }
  if (header) throw std::runtime_error(file_label + ": expected a header row, got an empty file");
  return table;
}

// The text of an annotated table with its '#' lines blanked: parsing skips them and the other
// lines keep their numbers.
std::string withoutComments(const std::string& path, const std::string& what) {
  std::istringstream in(readFileContents(path, what));
  std::string text, line;
  while (std::getline(in, line)) text += (line.compare(0, 1, "#") == 0 ? std::string() : line) + "\n";
  return text;
}

}  // namespace

Table parseCsv(const std::string& text, const std::string& file_label, CsvLayout* layout) {
  return parseTable(text, file_label, layout, TextCells::Rejected);
}

Table readCsvFile(const std::string& path, CsvLayout* layout) {
  return parseCsv(readFileContents(path), path, layout);
}

Table readAnnotatedCsvFile(const std::string& path, const std::string& what) {
  return parseCsv(withoutComments(path, what), path);
}

Table readAnnotatedCsvFileWithText(const std::string& path, const std::string& what, CsvLayout* layout) {
  return parseTable(withoutComments(path, what), path, layout, TextCells::AsNaN);
}

}  // namespace rollerdyn
