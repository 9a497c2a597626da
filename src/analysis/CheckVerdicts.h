// The words every sign-off check is written with (SignOffChecks.cpp, DutyChecks.cpp): a ratio's
// verdict against its limit 1, the "not applicable" of a check whose inputs or window are missing,
// and numbers in its reason to four significant digits.
#pragma once

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "analysis/SizingCheck.h"
#include "io/FieldFormat.h"

namespace rollerdyn::check_words {

inline constexpr const char* kNotApplicable = "not applicable";

inline std::string g4(double v) { return significant(v, 4); }

// "pass" for a ratio ≤ 1, "FAIL" above, "" when it is not a number.
inline std::string verdictOf(double ratio) {
  if (!std::isfinite(ratio)) return "";
  return ratio <= 1.0 ? "pass" : "FAIL";
}

// Marks a check not applicable with why (and what to give); its value is then no number.
inline void notApplicable(SizingCheck& c, const std::string& why) {
  c.verdict = kNotApplicable;
  c.reason = why;
  c.value = std::numeric_limits<double>::quiet_NaN();
}

}  // namespace rollerdyn::check_words
