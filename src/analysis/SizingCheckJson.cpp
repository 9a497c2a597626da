#include "analysis/SizingCheckJson.h"
#include "io/FieldFormat.h"

#include <cmath>
#include <limits>

namespace rollerdyn {

using nlohmann::json;

namespace {

std::string text(const json& j, const char* key) { return jsonText(jsonMember(j, key)); }

double number(const json& j, const char* key) { return jsonDouble(jsonMember(j, key)); }

}  // namespace

json sizingCheckJson(const SizingCheck& c) {
  return {{"check", c.name},
          {"what", c.what},
          {"value", jsonNumber(c.value)},
          {"verdict", c.verdict.empty() ? json(nullptr) : json(c.verdict)},
          {"window", c.window},
          {"reason", c.reason},
          {"limit", jsonNumber(c.limit)},
          {"passes_when", c.passes_when},
          {"method", c.method},
          {"basis", c.basis}};
}

SizingCheck sizingCheckFromJson(const json& j) {
  SizingCheck c;
  if (!j.is_object()) return c;
  c.name = text(j, "check");
  c.what = text(j, "what");
  c.value = number(j, "value");
  c.verdict = text(j, "verdict");
  c.window = text(j, "window");
  c.reason = text(j, "reason");
  c.limit = number(j, "limit");
  c.passes_when = text(j, "passes_when");
  c.method = text(j, "method");
  c.basis = text(j, "basis");
  return c;
}

}  // namespace rollerdyn
