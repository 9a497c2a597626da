// The tool's one reader of its CSV convention (Table.h: a header row of `name[unit]` cells, then
// rows of numbers, "nan" and "inf" accepted), the counterpart of the writer toCsv() (AtomicFile.h).
// Every table the tool reads back is read here: its own output folders (report/OutputFolder.h),
// measured data (studies/MeasuredData.h), the published tables of the papers (validation/published).
#pragma once

#include <string>
#include <vector>

#include "io/Table.h"

namespace rollerdyn {

// Where parseCsv found what, for a reader that checks more than the table's shape (measured data:
// each header's unit, each row's time): the header cells as written and the file line of each row.
struct CsvLayout {
  std::vector<std::string> header;  // header cells as written, e.g. "omega_crank[rad/s]"
  int header_line = 0;              // file line (from 1) of the header
  std::vector<int> row_lines;       // file line (from 1) of each row of the table
};

// Parses CSV as written by toCsv(): a header row of column names (the units stripped), then rows
// of numbers; empty lines are skipped. Throws std::runtime_error naming file and line for a
// missing header, a row with the wrong number of fields or a field that is not a number (and its
// column). `layout` (optional) receives the header cells as written and each row's line.
Table parseCsv(const std::string& text, const std::string& file_label, CsvLayout* layout = nullptr);
Table readCsvFile(const std::string& path, CsvLayout* layout = nullptr);

// The same for a table annotated by hand (the published tables): lines starting with '#' are
// comments (the source, the units) and skipped; the lines keep their numbers in messages.
Table readAnnotatedCsvFile(const std::string& path, const std::string& what = "");

// The same for a table whose rows also hold text (the studies' joined tables: a sweep's motion and
// status, "..." quoted with commas inside; published cells left empty where the paper has no row):
// a comma inside "..." does not split a field, the quotes are dropped, and a text or empty cell
// reads as NaN instead of being an error.
Table readAnnotatedCsvFileWithText(const std::string& path, const std::string& what = "",
                                   CsvLayout* layout = nullptr);

}  // namespace rollerdyn
