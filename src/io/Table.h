// A column-named table of doubles: the one output container both models fill (time series,
// reactions, comparisons), so analysis and writers never depend on which model produced it.
#pragma once

#include <string>
#include <vector>

namespace rollerdyn {

struct Table {
  std::vector<std::string> columns;          // column names, e.g. "t", "omega_crank"
  std::vector<std::vector<double>> rows;     // one row per output time; rows[i].size() == columns.size()

  // Index of a column; throws std::out_of_range naming the column when absent.
  int index(const std::string& name) const;
  bool has(const std::string& name) const;
  // A copy of one column.
  std::vector<double> column(const std::string& name) const;
};

}  // namespace rollerdyn
