#include "io/Table.h"

#include <stdexcept>

namespace rollerdyn {

int Table::index(const std::string& name) const {
  for (size_t i = 0; i < columns.size(); ++i)
    if (columns[i] == name) return static_cast<int>(i);
  throw std::out_of_range("table has no column '" + name + "'");
}

bool Table::has(const std::string& name) const {
  for (const auto& c : columns)
    if (c == name) return true;
  return false;
}

std::vector<double> Table::column(const std::string& name) const {
  const int k = index(name);
  std::vector<double> out;
  out.reserve(rows.size());
  for (const auto& r : rows) out.push_back(r[k]);
  return out;
}

}  // namespace rollerdyn
