#include "io/Table.h"

#include <stdexcept>

#include "io/OutputColumns.h"

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

std::string columnUnit(const std::string& name) {
  const std::string u = outputColumnUnit(name);
  if (!u.empty()) return u;
  for (const char* suffix : {"_reduced_kinetostatic", "_multibody", "_reduced"}) {
    const std::string sfx(suffix);
    if (name.size() > sfx.size() && name.compare(name.size() - sfx.size(), sfx.size(), sfx) == 0)
      return outputColumnUnit(name.substr(0, name.size() - sfx.size()));
  }
  return "";
}

std::string headerWithUnit(const std::string& name) {
  const std::string u = columnUnit(name);
  return u.empty() ? name : name + "[" + u + "]";
}

std::string stripUnit(const std::string& header) {
  const std::size_t open = header.find('[');
  if (open == std::string::npos || open == 0 || header.back() != ']') return header;
  return header.substr(0, open);
}

}  // namespace rollerdyn
