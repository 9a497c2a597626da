#include "analysis/SignOffSheet.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <regex>
#include <sstream>

#include "analysis/SizingCheckJson.h"
#include "io/Sha256.h"
#include "scene/SceneSchema.h"
#include "io/FieldFormat.h"

namespace rollerdyn {

using nlohmann::json;

namespace {

std::string text(const json& j, const char* key) { return jsonText(jsonMember(j, key)); }

// The scene keys a reason names (sizing.coupling_rated_torque, initial.crank_speed, a map such as
// sizing.fatigue.coupling_torque.*), each once, in order; only keys of the scene schema.
std::vector<std::string> sceneKeysIn(const std::string& words) {
  static const std::regex key(R"(\b[a-z][a-z_0-9]*(\.[a-z_0-9]+)+(\.\*)?)");
  std::vector<std::string> out;
  for (auto it = std::sregex_iterator(words.begin(), words.end(), key); it != std::sregex_iterator(); ++it) {
    std::string k = it->str();
    const std::string bare = k.size() > 2 && k.compare(k.size() - 2, 2, ".*") == 0 ? k.substr(0, k.size() - 2) : k;
    if (!findSceneKeyOrElement(bare) && !isSceneMap(bare)) continue;
    if (std::find(out.begin(), out.end(), k) == out.end()) out.push_back(k);
  }
  return out;
}

SignOffRow rowOf(const std::string& group, const json& j) {
  SignOffRow r;
  r.group = group;
  r.check = sizingCheckFromJson(j);
  r.reason = r.check.reason;
  if (r.check.verdict == "pass" || r.check.verdict == "FAIL") {
    r.verdict = r.check.verdict;
  } else {
    r.verdict = "not applicable";
    if (r.check.verdict.empty())
      r.reason = "no verdict" + (r.reason.empty() ? std::string() : ": " + r.reason);
    else if (r.reason.empty())
      r.reason = "not applicable (" + r.check.verdict + "), no reason given";
  }
  r.keys = sceneKeysIn(r.reason + " " + r.check.basis);
  return r;
}

std::string plural(int n, const char* one, const char* many) { return std::to_string(n) + " " + (n == 1 ? one : many); }

std::string overallLine(const SignOffSheet& s) {
  const int total = int(s.rows.size());
  std::string counts = plural(s.passed, "check passes", "checks pass") + ", " + std::to_string(s.failed) +
                       " FAIL, " + std::to_string(s.not_applicable) + " n/a (of " + std::to_string(total) + ")";
  if (total == 0)
    return "NOT SIGNED OFF: the run gives no check to sign the drive off with (no motor, coupling or sizing data in "
           "the scene).";
  if (s.failed > 0)
    return "NOT SIGNED OFF: " + counts + ". The drive is not signed off while any check FAILs: change the design "
           "or its duty until every FAIL passes, then make the sheet again.";
  if (!s.run_status.empty())
    return "NOT SIGNED OFF: the run did not complete (" + s.run_status + "); " + counts + ".";
  if (s.not_applicable > 0)
    return "No check FAILs: " + counts + ". Each n/a is a check not made; the reviewer signs off only having "
           "accepted its reason or supplied what it names.";
  return "All checks pass: " + counts + ". Ready for the reviewer's signature.";
}

// `text` right-aligned in `width` characters (UTF-8: ≤ and ≥ are one character of three bytes).
std::string padded(const std::string& text, int width) {
  int chars = 0;
  for (unsigned char c : text) chars += (c & 0xC0) != 0x80;
  return std::string(std::max(0, width - chars), ' ') + text;
}

}  // namespace

std::string shortVerdict(const std::string& verdict) { return verdict == "not applicable" ? "n/a" : verdict; }

std::string comparisonSymbol(const std::string& passes_when) {
  if (passes_when == "<=") return "≤";
  if (passes_when == "<") return "<";
  if (passes_when == ">=") return "≥";
  if (passes_when == ">") return ">";
  return "";
}

namespace {

// The torsional modes' rows: the separation margins of the modal analysis, or one row saying it
// was not made with this run.
void addModesRows(SignOffSheet& s, const json& summary) {
  const json& modes = jsonMember(summary, "modes");
  if (modes.is_object()) {
    for (const json& c : jsonMember(jsonMember(modes, "separation_margins"), "checks"))
      s.rows.push_back(rowOf("torsional modes", c));
    return;
  }
  SizingCheck c;
  c.name = "separation_margin";
  c.what = "separation margin of the coupling's torsional mode from the excitation orders, ≥ 10 %";
  c.value = NAN;
  c.verdict = "not applicable";
  c.reason = "the modal analysis was not made with this run";
  s.rows.push_back(rowOf("torsional modes", sizingCheckJson(c)));
}

// The pass / FAIL / n/a counts, whether the sheet can be signed, and the line that says so.
void concludeSheet(SignOffSheet& s) {
  for (const SignOffRow& r : s.rows) {
    s.passed += r.verdict == "pass";
    s.failed += r.verdict == "FAIL";
    s.not_applicable += r.verdict == "not applicable";
  }
  s.signable = s.failed == 0 && s.run_status.empty() && !s.rows.empty();
  s.overall = overallLine(s);
}

}  // namespace

SignOffSheet buildSignOffSheet(const json& summary, const SignOffSource& source) {
  SignOffSheet s;
  s.source = source;
  s.scene_sha256 = sha256Hex(source.scene_text);
  s.model = text(summary, "model");
  s.motion = text(summary, "motion");
  const json& complete = jsonMember(summary, "complete");
  if (complete.is_boolean() && !complete.get<bool>()) s.run_status = text(summary, "status");
  for (const json& w : jsonMember(summary, "warnings"))
    if (w.is_string()) s.warnings.push_back(w.get<std::string>());
  for (const json& c : jsonMember(jsonMember(summary, "sizing"), "checks")) s.rows.push_back(rowOf("drive sizing", c));
  addModesRows(s, summary);
  concludeSheet(s);
  return s;
}

json signOffJson(const SignOffSheet& s) {
  json rows = json::array();
  for (const SignOffRow& r : s.rows) {
    json j = sizingCheckJson(r.check);
    j["group"] = r.group;
    j["sheet_verdict"] = r.verdict;
    j["sheet_reason"] = r.reason;
    j["keys"] = r.keys;
    rows.push_back(j);
  }
  return {{"scene", s.source.scene_name},
          {"scene_path", s.source.scene_path},
          {"scene_sha256", s.scene_sha256},
          {"overrides", s.source.overrides},
          {"tool_version", s.source.tool_version},
          {"date", s.source.date},
          {"model", s.model},
          {"run_status", s.run_status.empty() ? json(nullptr) : json(s.run_status)},
          {"motion", s.motion},
          {"warnings", s.warnings},
          {"counts", {{"pass", s.passed}, {"FAIL", s.failed}, {"not_applicable", s.not_applicable}, {"total", s.rows.size()}}},
          {"signable", s.signable},
          {"overall", s.overall},
          {"checks", rows}};
}

std::string signOffSheetText(const SignOffSheet& s) {
  std::ostringstream o;
  o << "sign-off sheet: " << s.source.scene_name << " (" << s.source.scene_path << ", SHA-256 "
    << s.scene_sha256.substr(0, 16) << "...)\n";
  for (const SignOffRow& r : s.rows) {
    const std::string value = significantOr(r.check.value, 3, "");
    char limit[40] = "";
    if (std::isfinite(r.check.limit))
      std::snprintf(limit, sizeof limit, "%s %.4g", comparisonSymbol(r.check.passes_when).c_str(), r.check.limit);
    char line[160];
    std::snprintf(line, sizeof line, "  %-5s %-30s %9s ", shortVerdict(r.verdict).c_str(), r.check.name.c_str(), value.c_str());
    o << line << padded(limit, 10) << "  " << (r.verdict == "pass" ? r.check.window : r.reason) << "\n";
  }
  o << s.overall << "\n";
  return o.str();
}

}  // namespace rollerdyn
