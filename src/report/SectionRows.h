// The tables of the report's sizing, sign-off and duty sections, written from summary.json's
// members only.
#pragma once

#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "io/FieldFormat.h"
#include "report/HtmlReport.h"

namespace rollerdyn::section_rows {

// A JSON text, escaped for HTML; "n/a" where it is not a text.
inline std::string text(const nlohmann::json& v) { return v.is_string() ? htmlEscape(v.get<std::string>()) : "n/a"; }

// The head of a table of such rows.
inline constexpr const char* kRowsHead = "<table>\n<tr><th>quantity</th><th>value</th><th>unit</th><th>note</th></tr>\n";

// One row: what, value, unit, note (value and note already HTML).
inline void row(std::ostringstream& h, const std::string& what, const std::string& value, const char* unit,
                const std::string& note = "") {
  h << "<tr><td>" << htmlEscape(what) << "</td><td class=\"n\">" << value << "</td><td>" << unit << "</td><td>" << note
    << "</td></tr>\n";
}

// A window's "applies" member is true.
inline bool applies(const nlohmann::json& w) { return jsonFlag(w, "applies"); }

}  // namespace rollerdyn::section_rows
