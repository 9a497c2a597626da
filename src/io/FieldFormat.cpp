#include "io/FieldFormat.h"

#include <cmath>
#include <cstdio>

namespace rollerdyn {

std::string csvNumber(double v) {
  if (!std::isfinite(v)) return "nan";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.12g", v);
  return buf;
}

const nlohmann::json& jsonMember(const nlohmann::json& j, const char* k) {
  static const nlohmann::json null_json;
  return j.is_object() && j.contains(k) ? j.at(k) : null_json;
}

bool jsonFlag(const nlohmann::json& j, const char* k) {
  const nlohmann::json& v = jsonMember(j, k);
  return v.is_boolean() && v.get<bool>();
}

std::string jsonText(const nlohmann::json& v) { return v.is_string() ? v.get<std::string>() : std::string(); }

std::string jsonNumberText(const nlohmann::json& v, const char* format, double scale) {
  if (!v.is_number()) return "n/a";
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v.get<double>() * scale);
  return buf;
}

std::string significant(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

std::string significantOr(double v, int digits, const char* absent) {
  return std::isfinite(v) ? significant(v, digits) : std::string(absent);
}

std::string csvText(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += (c == '"') ? std::string("\"\"") : std::string(1, c == '\n' || c == '\r' ? ' ' : c);
  return q + "\"";
}

nlohmann::json jsonNumber(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

}  // namespace rollerdyn
