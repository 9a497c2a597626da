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

// CSV header convention, applied in ONE place (the CSV writer, io/AtomicFile.h, and the CSV
// reader): a column is written as `name[unit]`, e.g. `omega_crank[rad/s]`, `F_rod_2[N]`, with
// ASCII units (N*m, rad/s^2); code and tables use the bare name. Unknown names stay bare.
// The unit of a column name: exact names (t, omega_crank, coupling_torque, ...), per-cart names
// with a numeric suffix (v_cart_3, N_front_1, ...), comparison names with a model suffix
// (omega_crank_multibody, ..._reduced, ..._reduced_kinetostatic); "" when unknown.
std::string columnUnit(const std::string& name);
// "name[unit]", or "name" when the unit is unknown.
std::string headerWithUnit(const std::string& name);
// The bare name of a header cell: "omega_crank[rad/s]" -> "omega_crank".
std::string stripUnit(const std::string& header);

}  // namespace rollerdyn
