// How one value of a study output is written: a CSV field (number or text) or a JSON number.
// Shared by the sweep and optimize writers so their sweep.csv/history.csv and JSON files print
// values the same way. (Tables of doubles go through toCsv, io/AtomicFile.h.)
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace rollerdyn {

// 12 significant digits (%.12g, as toCsv); "nan" for any non-finite value, so a CSV reader
// sees one token for "no value".
std::string csvNumber(double v);
// Text as one CSV field: quoted (RFC 4180, inner quotes doubled) when it holds a comma, quote or
// line break; line breaks become spaces so each record stays on one line.
std::string csvText(const std::string& s);
// A JSON number, or null when v is not finite (JSON has no NaN or infinity).
nlohmann::json jsonNumber(double v);
// Member k of a JSON object; null when j is not an object or has no such member (summary.json
// readers of the console and the report).
const nlohmann::json& jsonMember(const nlohmann::json& j, const char* k);
// Member k of j is the boolean true (false when it is missing or not a boolean), e.g. a
// window's "applies".
bool jsonFlag(const nlohmann::json& j, const char* k);
// The member at a dotted path of keys ("omega_crank.mean", "sizing.motor.torque_shaft.rms"); null
// where any part is missing or not an object.
const nlohmann::json& jsonAt(const nlohmann::json& j, const std::string& dotted_path);
// A JSON number as a double; NaN where v is not a number (missing, null, text): the reverse of
// jsonNumber.
double jsonDouble(const nlohmann::json& v);
// A JSON text as it is; `absent` ("" unless a console line wants "n/a") where v is not a text.
std::string jsonText(const nlohmann::json& v, const char* absent = "");
// A JSON number as printf's `format` of v·scale; "n/a" when v is not a number (null, text).
std::string jsonNumberText(const nlohmann::json& v, const char* format = "%.4g", double scale = 1.0);
// v in printf's `format` ("%.1f", "%.0f %%"): a fixed layout where a column or a sentence wants
// one, rather than significant digits.
std::string printfNumber(const char* format, double v);
// The same, with `absent` written instead of a value that is not finite ("–" in a table).
std::string printfNumberOr(const char* format, double v, const char* absent);
// A sentence printf writes (the validation lines, the models' differences, the friction checks),
// whatever its length.
std::string printfText(const char* format, ...) __attribute__((format(printf, 1, 2)));
// `digits` significant digits (%.*g), as numbers read in validation lines and study pages: the
// one number formatter of the console, the pages and the figures (files written for programs use
// csvNumber, 12 digits).
std::string significant(double v, int digits = 3);
// The same, with `absent` written instead of a value that is not finite ("n/a", "–" in a table).
std::string significantOr(double v, int digits, const char* absent);

}  // namespace rollerdyn
