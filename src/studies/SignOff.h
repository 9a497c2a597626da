// `rollerdyn signoff` and Python's signoff(): the sign-off sheet (analysis/SignOffSheet.h) of a
// run summarized with its modal analysis, and its files: signoff.json, signoff.html and
// signoff.pdf, the page printed by headless Chromium (Debian package chromium). Where Chromium is
// missing or fails, the JSON and the HTML are still written and the PDF's absence is said.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/SignOffSheet.h"

namespace rollerdyn {

// The sheet of a run's summary. `scene_file`: the scene file as given ("" for a scene that is not
// a file: no path and the hash of nothing); its text is read here and hashed.
SignOffSheet signOffSheetOf(const nlohmann::json& summary, const std::string& scene_name, const std::string& scene_file,
                            const std::vector<std::string>& overrides);

struct SignOffFiles {
  std::string json, html, pdf;  // the paths written ("" for pdf when it was not)
  std::string pdf_not_written;  // why the PDF is missing, in words; "" when written
};

// Writes signoff.json and signoff.html into `out_dir` (which must exist), then prints the page to
// signoff.pdf with Chromium: $ROLLERDYN_CHROMIUM when set (empty: none), else chromium or
// chromium-browser on PATH. A signoff.pdf of an earlier sheet is removed first.
SignOffFiles writeSignOffFiles(const SignOffSheet& sheet, const std::string& out_dir);

// The Chromium executable to print with, or "" (see writeSignOffFiles).
std::string findChromium();

}  // namespace rollerdyn
