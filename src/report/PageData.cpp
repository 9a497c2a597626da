#include "report/PageData.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace rollerdyn {

namespace {

// Every occurrence of `from` in `text` replaced by `to`.
std::string replaceAll(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = 0; (at = text.find(from, at)) != std::string::npos; at += to.size())
    text.replace(at, from.size(), to);
  return text;
}

}  // namespace

double roundSignificant(double v, int digits) {
  if (!std::isfinite(v) || v == 0.0) return v;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*e", digits - 1, v);
  return std::strtod(buf, nullptr);
}

nlohmann::json roundedArray(const std::vector<double>& values, int digits) {
  nlohmann::json a = nlohmann::json::array();
  for (double v : values) a.push_back(roundSignificant(v, digits));
  return a;
}

std::string jsonScriptBlock(const std::string& id, const nlohmann::json& data) {
  return "<script type=\"application/json\" id=\"" + id + "\">" + replaceAll(data.dump(), "</", "<\\/") +
         "</script>\n";
}

std::string inlineScriptBlock(const std::string& code) {
  // HTML ends a script at "</script" in any letter case.
  std::string safe;
  safe.reserve(code.size());
  for (std::size_t i = 0; i < code.size(); ++i) {
    if (code[i] == '<' && i + 1 < code.size() && code[i + 1] == '/' && i + 8 <= code.size()) {
      std::string word = code.substr(i + 2, 6);
      for (char& ch : word) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
      if (word == "script") {
        safe += "<\\/";
        ++i;
        continue;
      }
    }
    safe += code[i];
  }
  return "<script>\n" + safe + "\n</script>\n";
}

}  // namespace rollerdyn
