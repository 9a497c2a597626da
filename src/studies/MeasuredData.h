// Measurements for `rollerdyn identify`: a CSV with a time column t and any of rollerdyn's own
// output columns (omega_crank, omega_motor, stator_current, coupling_torque, x_cart_1, ...), in the
// tool's one CSV convention (io/Table.h: a header cell `name[unit]`, read by parseCsv of
// io/CsvTable.h). Every header must carry the unit rollerdyn writes for that column, so a
// current in mA or a speed in rpm is refused instead of being fitted.
#pragma once

#include <string>
#include <vector>

namespace rollerdyn {

struct MeasuredSignal {
  std::string name;            // column name as the model writes it, e.g. "omega_crank"
  std::string unit;            // its unit (io/Table.h columnUnit), e.g. "rad/s"
  std::vector<double> values;  // one per sample [unit]
};

struct MeasuredData {
  std::string file;                     // the file as given (or the label of text in memory)
  std::vector<double> t;                // sample times, strictly increasing, >= 0 [s]
  std::vector<int> lines;               // file line of each sample (for messages)
  std::vector<MeasuredSignal> signals;  // every column but t, in file order

  // The signal called `name`; nullptr when absent.
  const MeasuredSignal* find(const std::string& name) const;
};

// Parses measured data. Throws std::invalid_argument naming FILE:LINE and the column for: no t
// column, a column rollerdyn does not write (with a did-you-mean hint), a header without the unit
// or with another unit than rollerdyn's, a repeated column, a value that is not finite, a time
// below 0 or not above the previous row's, fewer than 3 samples or no signal besides t.
MeasuredData parseMeasuredData(const std::string& text, const std::string& file_label);
MeasuredData readMeasuredData(const std::string& path);

}  // namespace rollerdyn
