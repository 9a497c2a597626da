// The markdown pages of validation/studies/, written from the tables that
// validation/studies/run.sh leaves there (`rollerdyn sweep`, `cam-profile --compare`, `chain`
// outputs and the joined "ours beside published" CSVs), so that every number on those pages comes
// out of that command: `rollerdyn validate --studies validation/studies` (run.sh calls it last).
// Nothing here runs a simulation; a table that is missing is reported as missing.
#pragma once

#include <string>
#include <vector>

namespace rollerdyn::validation {

struct StudiesPage {
  std::string file;      // file name inside the studies folder, e.g. "loveikin2007_dphi.md"
  std::string markdown;  // its content
};

// Reads the study outputs under `dir` and returns the pages (README.md first). Throws
// std::runtime_error naming the file when a table exists but cannot be parsed.
std::vector<StudiesPage> buildStudiesPages(const std::string& dir);

// A table of the studies folder, read by the tool's CSV reader (io/CsvTable.h,
// readAnnotatedCsvFileWithText: '#' lines skipped, text and empty cells NaN; the joined tables leave
// the published columns empty where the paper has no row), its columns named by the header cells
// as written. Throws std::runtime_error naming the file and line on a row with the wrong number
// of fields.
struct StudyTable {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  int index(const std::string& column) const;  // -1 when absent
  double at(std::size_t row, const std::string& column) const;  // NaN when absent
};
StudyTable readStudyTable(const std::string& path);

// startup.md: the papers' machines started from rest with each motor law, and Table 1's offsets
// from rest (StartUpStudyPage.cpp), from the startup_*/sweep.json under `dir`.
StudiesPage startUpStudyPage(const std::string& dir);

}  // namespace rollerdyn::validation
