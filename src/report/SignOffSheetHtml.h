// signoff.html: the sign-off sheet (analysis/SignOffSheet.h) as one self-contained A4 page for
// print (headless Chromium prints it to signoff.pdf): header with the scene, its SHA-256, the
// overrides, the tool's version and the date; the overall line; one block per check; the run's
// warnings; the reviewer's name, date and signature as empty fields. Renders the sheet only.
#pragma once

#include <string>

#include "analysis/SignOffSheet.h"

namespace rollerdyn {

std::string signOffSheetHtml(const SignOffSheet& sheet);

}  // namespace rollerdyn
