// One SizingCheck as a JSON object (summary.json's sizing.checks, modes.json's
// separation_margins.checks), and back, so the sign-off sheet reads the checks the run wrote.
#pragma once

#include <nlohmann/json.hpp>

#include "analysis/SizingCheck.h"

namespace rollerdyn {

// {check, what, value, verdict, window, reason, limit, passes_when, method, basis}; NaN numbers as
// null, an empty verdict (nothing to compare with) as null.
nlohmann::json sizingCheckJson(const SizingCheck& c);
// The inverse; members missing or of the wrong type read as empty (NaN for numbers).
SizingCheck sizingCheckFromJson(const nlohmann::json& j);

}  // namespace rollerdyn
