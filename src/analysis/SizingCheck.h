// One check a drive is signed off with (DriveSizing::checks, the modal analysis' separation
// margins): what it compares, against which limit, by which method or standard, over which window,
// and its verdict with the reason. Made once where the check is computed; summary.json, the
// console, the report, the sign-off sheet and Python only render it.
#pragma once

#include <limits>
#include <string>

namespace rollerdyn {

struct SizingCheck {
  std::string name;     // identifier: start, motor_heating, motor_breakdown, coupling, ...
  std::string what;     // in words, with the limit
  double value = 0;     // the deciding figure (NaN when not computable)
  std::string verdict;  // "pass", "FAIL", "not applicable" or "" (nothing to compare with)
  std::string window;   // "whole run" or "steady window": where the deciding value comes from
  std::string reason;   // why FAIL or not applicable; what decided
  // The limit `value` is held against, in value's unit (NaN: no limit given, verdict "").
  double limit = std::numeric_limits<double>::quiet_NaN();
  // How value passes against limit: "<=", "<" or ">=".
  std::string passes_when = {};
  // The method or standard the check follows, by name (DIN 740-2, ISO 281, IEC 60034-1, ...).
  std::string method = {};
  // The inputs (scene keys) and approximations the check rests on, in words.
  std::string basis = {};
};

}  // namespace rollerdyn
