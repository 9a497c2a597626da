#include "io/Table.h"

#include <cctype>
#include <stdexcept>
#include <utility>

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

namespace {

// Column name -> unit, the single table behind every CSV header.
const std::vector<std::pair<std::string, std::string>>& exactUnits() {
  static const std::vector<std::pair<std::string, std::string>> u = {
      {"t", "s"},
      {"phi_motor", "rad"}, {"phi_crank", "rad"},
      {"omega_motor", "rad/s"}, {"omega_crank", "rad/s"},
      {"eps_crank", "rad/s^2"}, {"eps_motor", "rad/s^2"},
      {"twist", "rad"}, {"twist_rate", "rad/s"}, {"twist_accel", "rad/s^2"},
      {"coupling_torque", "N*m at the crank axis"}, {"motor_torque", "N*m at the crank axis"},
      {"load_torque", "N*m at the crank axis"}, {"reducer_loss_torque", "N*m at the crank axis"},
      {"bearing_x", "N"}, {"bearing_y", "N"},
      {"stator_current", "A"}, {"supply_voltage_ratio", "-"}, {"supply_frequency_ratio", "-"},
      {"brake_torque", "N*m"},
      {"tooth_contact", "1 drive flank/0 teeth apart/-1 reverse flank"},
  };
  return u;
}

// Per-cart prefixes: name_<j> (and the main bearings' name_<k>).
const std::vector<std::pair<std::string, std::string>>& cartUnits() {
  static const std::vector<std::pair<std::string, std::string>> u = {
      {"x_cart", "m"}, {"v_cart", "m/s"}, {"a_cart", "m/s^2"},
      {"N_front", "N"}, {"N_rear", "N"}, {"F_rod", "N"}, {"friction", "N"},
      {"crankpin_x", "N"}, {"crankpin_y", "N"},
      {"bearing_x", "N"}, {"bearing_y", "N"},  // per main bearing k: bearing_x_k, bearing_y_k
      {"shaft_torque", "N*m"},                  // per crankshaft segment k of a torsional chain
  };
  return u;
}

std::string unitOfBase(const std::string& name) {
  for (const auto& [n, u] : exactUnits())
    if (n == name) return u;
  const std::size_t us = name.rfind('_');
  if (us == std::string::npos || us + 1 == name.size()) return "";
  for (std::size_t i = us + 1; i < name.size(); ++i)
    if (!std::isdigit(static_cast<unsigned char>(name[i]))) return "";
  const std::string prefix = name.substr(0, us);
  for (const auto& [n, u] : cartUnits())
    if (n == prefix) return u;
  return "";
}

}  // namespace

std::string columnUnit(const std::string& name) {
  const std::string u = unitOfBase(name);
  if (!u.empty()) return u;
  for (const char* suffix : {"_reduced_kinetostatic", "_multibody", "_reduced"}) {
    const std::string sfx(suffix);
    if (name.size() > sfx.size() && name.compare(name.size() - sfx.size(), sfx.size(), sfx) == 0)
      return unitOfBase(name.substr(0, name.size() - sfx.size()));
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
