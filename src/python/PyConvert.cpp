#include "python/PyConvert.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <sstream>

#include <yaml-cpp/yaml.h>

namespace rollerdyn::python {

namespace {

bool looksLikeNumber(const std::string& s) {
  double v = 0;
  return YAML::convert<double>::decode(YAML::Node(s), v);
}

// Words YAML 1.1 or 1.2 reads as booleans or null.
bool specialWord(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const char* w : {"true", "false", "yes", "no", "on", "off", "y", "n", "null", "~"})
    if (s == w) return true;
  return false;
}

std::string quoted(const std::string& s) {
  std::string q = "\"";
  for (unsigned char c : s) {
    if (c == '"' || c == '\\') {
      q += '\\';
      q += static_cast<char>(c);
    } else if (c < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", c);
      q += buf;
    } else {
      q += static_cast<char>(c);
    }
  }
  return q + "\"";
}

std::string textScalar(const std::string& s) {
  const bool plain = !s.empty() && s.find_first_of(":#[]{},&*!|>'\"%@`\n\t") == std::string::npos &&
                     s.front() != ' ' && s.back() != ' ' && s.front() != '-' && s.front() != '?' &&
                     !looksLikeNumber(s) && !specialWord(s);
  return plain ? s : quoted(s);
}

std::string floatText(double v) {
  if (std::isnan(v)) return ".nan";
  if (std::isinf(v)) return v > 0 ? ".inf" : "-.inf";
  return py::repr(py::float_(v)).cast<std::string>();
}

}  // namespace

py::object toPython(const nlohmann::json& j) {
  switch (j.type()) {
    case nlohmann::json::value_t::null: return py::none();
    case nlohmann::json::value_t::boolean: return py::bool_(j.get<bool>());
    case nlohmann::json::value_t::number_integer: return py::int_(j.get<long long>());
    case nlohmann::json::value_t::number_unsigned: return py::int_(j.get<unsigned long long>());
    case nlohmann::json::value_t::number_float: return py::float_(j.get<double>());
    case nlohmann::json::value_t::string: return py::str(j.get<std::string>());
    case nlohmann::json::value_t::array: {
      py::list l;
      for (const auto& e : j) l.append(toPython(e));
      return std::move(l);
    }
    case nlohmann::json::value_t::object: {
      py::dict d;
      for (auto it = j.begin(); it != j.end(); ++it) d[py::str(it.key())] = toPython(it.value());
      return std::move(d);
    }
    default: return py::none();
  }
}

namespace {

// A dict as a YAML flow mapping; its keys must be text.
std::string yamlMapText(py::handle v) {
  std::string s = "{";
  bool first = true;
  for (auto item : v.cast<py::dict>()) {
    if (!py::isinstance<py::str>(item.first))
      throw py::type_error("scene keys are text, got a key of type " +
                           py::str(py::type::handle_of(item.first).attr("__name__")).cast<std::string>());
    s += (first ? "" : ", ") + textScalar(item.first.cast<std::string>()) + ": " + yamlValueText(item.second);
    first = false;
  }
  return s + "}";
}

// A list or tuple as a YAML flow sequence.
std::string yamlListText(py::handle v) {
  std::string s = "[";
  bool first = true;
  for (auto item : v) {
    s += (first ? "" : ", ") + yamlValueText(item);
    first = false;
  }
  return s + "]";
}

}  // namespace

std::string yamlValueText(py::handle v) {
  if (v.is_none()) return "null";
  if (py::isinstance<py::bool_>(v)) return v.cast<bool>() ? "true" : "false";
  if (py::hasattr(v, "dtype") && py::hasattr(v, "item") && py::getattr(v, "ndim", py::int_(1)).cast<int>() == 0)
    return yamlValueText(v.attr("item")());  // a NumPy scalar: as the Python value it stands for
  if (py::isinstance<py::int_>(v)) return py::str(v).cast<std::string>();
  if (py::isinstance<py::float_>(v)) return floatText(v.cast<double>());
  if (py::isinstance<py::str>(v)) return textScalar(v.cast<std::string>());
  if (py::isinstance<py::dict>(v)) return yamlMapText(v);
  if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v)) return yamlListText(v);
  throw py::type_error("a scene value must be a number, text, true/false, None, a list or a dict, got " +
                       py::str(py::type::handle_of(v).attr("__name__")).cast<std::string>());
}

namespace {

// The table's values as a rows × columns float array.
py::array_t<double> valuesArray(const Table& t) {
  const py::ssize_t rows = static_cast<py::ssize_t>(t.rows.size());
  const py::ssize_t cols = static_cast<py::ssize_t>(t.columns.size());
  py::array_t<double> values({rows, cols});
  auto m = values.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < rows; ++i) {
    const std::vector<double>& row = t.rows[static_cast<std::size_t>(i)];
    for (py::ssize_t k = 0; k < cols; ++k) m(i, k) = row[static_cast<std::size_t>(k)];
  }
  return values;
}

}  // namespace

py::dict tableToPython(const Table& t) {
  py::array_t<double> values = valuesArray(t);
  py::list names, units;
  for (const std::string& c : t.columns) {
    // A column that carries its unit ("slip[-]", as the motor's and the modes' tables do): bare
    // name and that unit, as the CSV reader splits them.
    const std::size_t open = c.find('[');
    if (open != std::string::npos && c.back() == ']') {
      names.append(c.substr(0, open));
      units.append(c.substr(open + 1, c.size() - open - 2));
    } else {
      names.append(c);
      units.append(columnUnit(c));
    }
  }
  py::dict d;
  d["columns"] = names;
  d["units"] = units;
  d["values"] = values;
  return d;
}

py::dict studyTableToPython(const std::vector<StudyColumn>& table) {
  py::list names, units;
  py::dict data;
  for (const StudyColumn& c : table) {
    names.append(c.name);
    units.append(c.unit);
    if (c.is_text) {
      data[py::str(c.name)] = py::cast(c.texts);
    } else {
      py::array_t<double> a(static_cast<py::ssize_t>(c.numbers.size()));
      auto m = a.mutable_unchecked<1>();
      for (std::size_t i = 0; i < c.numbers.size(); ++i) m(static_cast<py::ssize_t>(i)) = c.numbers[i];
      data[py::str(c.name)] = a;
    }
  }
  py::dict d;
  d["columns"] = names;
  d["units"] = units;
  d["data"] = data;
  return d;
}

}  // namespace rollerdyn::python
