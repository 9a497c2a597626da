#include "studies/MeasuredData.h"

#include <cmath>
#include <stdexcept>

#include "io/ReadFile.h"
#include "io/Table.h"
#include "io/CsvTable.h"

namespace rollerdyn {

const MeasuredSignal* MeasuredData::find(const std::string& name) const {
  for (const MeasuredSignal& s : signals)
    if (s.name == name) return &s;
  return nullptr;
}

namespace {

// "FILE:LINE: column 'NAME' (column N): " for messages about one cell of the header or of a row.
std::string where(const std::string& file, int line, const std::string& column, std::size_t index) {
  return file + ":" + std::to_string(line) + ": column '" + column + "' (column " + std::to_string(index + 1) +
         "): ";
}

// The header cell's unit as written ("rad/s" of "omega_crank[rad/s]"); "" when it has none.
std::string writtenUnit(const std::string& cell) {
  const std::string bare = stripUnit(cell);
  if (bare.size() == cell.size()) return "";
  return cell.substr(bare.size() + 1, cell.size() - bare.size() - 2);
}

// A header cell checked: a column given once, named as rollerdyn writes it, with its unit. Returns
// the unit.
std::string checkedHeaderCell(const Table& table, const CsvLayout& layout, std::size_t c, const std::string& file) {
  const std::string& name = table.columns[c];
  const std::string& cell = layout.header[c];
  for (std::size_t k = 0; k < c; ++k)
    if (table.columns[k] == name)
      throw std::invalid_argument(where(file, layout.header_line, name, c) + "expected each column once, got it again");
  const std::string unit = columnUnit(name);
  if (unit.empty())
    throw std::invalid_argument(where(file, layout.header_line, cell, c) +
                                "expected t or an output column of rollerdyn (omega_crank, omega_motor, "
                                "stator_current, coupling_torque, x_cart_1, ...; docs/outputs.md), got a name "
                                "rollerdyn does not write");
  const std::string written = writtenUnit(cell);
  if (written != unit)
    throw std::invalid_argument(where(file, layout.header_line, name, c) + "expected the header " +
                                headerWithUnit(name) + " (values in " + unit + "), got '" + cell + "'" +
                                (written.empty() ? " without a unit" : ""));
  return unit;
}

// The header: the signals into d (without values yet); returns the time column's index.
int readHeader(const Table& table, const CsvLayout& layout, MeasuredData& d) {
  int t_col = -1;
  for (std::size_t c = 0; c < table.columns.size(); ++c) {
    const std::string unit = checkedHeaderCell(table, layout, c, d.file);
    if (table.columns[c] == "t") {
      t_col = static_cast<int>(c);
      continue;
    }
    d.signals.push_back({table.columns[c], unit, {}});
  }
  const std::string at_header = d.file + ":" + std::to_string(layout.header_line);
  if (t_col < 0) throw std::invalid_argument(at_header + ": expected a time column t[s], got none");
  if (d.signals.empty())
    throw std::invalid_argument(at_header + ": expected at least one measured signal besides t, got none");
  if (table.rows.size() < 3)
    throw std::invalid_argument(d.file + ": expected at least 3 samples, got " + std::to_string(table.rows.size()));
  return t_col;
}

// Row i: finite values into the signals, its time after the previous one's.
void readSample(const Table& table, const CsvLayout& layout, std::size_t i, int t_col, MeasuredData& d) {
  const int line = layout.row_lines[i];
  std::size_t s = 0;
  for (std::size_t c = 0; c < table.columns.size(); ++c) {
    const double v = table.rows[i][c];
    if (!std::isfinite(v))
      throw std::invalid_argument(where(d.file, line, table.columns[c], c) + "expected a finite number, got " +
                                  (std::isnan(v) ? "nan" : "inf"));
    if (static_cast<int>(c) != t_col) d.signals[s++].values.push_back(v);
  }
  const double t = table.rows[i][t_col];
  if (t < 0)
    throw std::invalid_argument(where(d.file, line, "t", t_col) +
                                "expected a time >= 0 (the model starts at t = 0 from the scene's initial "
                                "state), got " + std::to_string(t));
  if (!d.t.empty() && !(t > d.t.back()))
    throw std::invalid_argument(where(d.file, line, "t", t_col) + "expected times increasing from row to row, got " +
                                std::to_string(t) + " after " + std::to_string(d.t.back()) + " (line " +
                                std::to_string(d.lines.back()) + ")");
  d.t.push_back(t);
  d.lines.push_back(line);
}

}  // namespace

MeasuredData parseMeasuredData(const std::string& text, const std::string& file_label) {
  CsvLayout layout;
  Table table;
  try {
    table = parseCsv(text, file_label, &layout);  // the tool's one CSV reader (io/CsvTable.h)
  } catch (const std::runtime_error& e) {
    throw std::invalid_argument(e.what());
  }
  MeasuredData d;
  d.file = file_label;
  const int t_col = readHeader(table, layout, d);
  for (std::size_t i = 0; i < table.rows.size(); ++i) readSample(table, layout, i, t_col, d);
  return d;
}

MeasuredData readMeasuredData(const std::string& path) {
  std::string text;
  try {
    text = readFileContents(path, "measured data");
  } catch (const std::runtime_error& e) {
    throw std::invalid_argument(e.what());
  }
  return parseMeasuredData(text, path);
}

}  // namespace rollerdyn
