// Data and scripts embedded in the self-contained report page: numbers rounded to the digits a
// reader or a drawing needs (the page stays small), JSON in a <script type="application/json">
// block and JavaScript in an inline <script>, both escaped so that no text inside can end the
// block early. Nothing is ever loaded from elsewhere.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace rollerdyn {

// `v` rounded to `digits` significant digits (NaN and infinities unchanged; JSON writes them as
// null). nlohmann::json then prints the short form, e.g. 0.123457 instead of 0.12345678901234.
double roundSignificant(double v, int digits);

// A JSON array of `values`, each rounded to `digits` significant digits.
nlohmann::json roundedArray(const std::vector<double>& values, int digits);

// <script type="application/json" id="ID">JSON</script>, with "</" written as "<\/" (the same
// JSON text, but it cannot close the block).
std::string jsonScriptBlock(const std::string& id, const nlohmann::json& data);

// <script>CODE</script>, with any "</script" inside written as "<\/script".
std::string inlineScriptBlock(const std::string& code);

}  // namespace rollerdyn
