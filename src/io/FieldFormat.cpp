#include "io/FieldFormat.h"

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <limits>

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

const nlohmann::json& jsonAt(const nlohmann::json& j, const std::string& dotted_path) {
  const nlohmann::json* node = &j;
  for (std::size_t start = 0;;) {
    const std::size_t dot = dotted_path.find('.', start);
    const std::string key = dotted_path.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    node = &jsonMember(*node, key.c_str());
    if (dot == std::string::npos) return *node;
    start = dot + 1;
  }
}

double jsonDouble(const nlohmann::json& v) {
  return v.is_number() ? v.get<double>() : std::numeric_limits<double>::quiet_NaN();
}

bool jsonFlag(const nlohmann::json& j, const char* k) {
  const nlohmann::json& v = jsonMember(j, k);
  return v.is_boolean() && v.get<bool>();
}

std::string jsonText(const nlohmann::json& v, const char* absent) {
  return v.is_string() ? v.get<std::string>() : std::string(absent);
}

std::string printfNumber(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

std::string printfNumberOr(const char* format, double v, const char* absent) {
  return std::isfinite(v) ? printfNumber(format, v) : std::string(absent);
}

std::string printfText(const char* format, ...) {
  va_list args;
  va_start(args, format);
  char buf[1024];
  const int n = std::vsnprintf(buf, sizeof buf, format, args);
  va_end(args);
  if (n < 0) return "";
  if (static_cast<std::size_t>(n) < sizeof buf) return buf;
  std::string big(static_cast<std::size_t>(n) + 1, '\0');  // longer than the buffer: once more, sized
  va_start(args, format);
  std::vsnprintf(big.data(), big.size(), format, args);
  va_end(args);
  big.resize(static_cast<std::size_t>(n));
  return big;
}

std::string jsonNumberText(const nlohmann::json& v, const char* format, double scale) {
  return v.is_number() ? printfNumber(format, v.get<double>() * scale) : "n/a";
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
