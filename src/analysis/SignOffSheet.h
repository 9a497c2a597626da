// The sign-off sheet of a drive (`rollerdyn signoff`, Python's signoff()): every check the run's
// summary holds (summary.json's sizing.checks and, with the modal analysis, the separation margins
// of modes' separation_margins.checks), whatever checks exist, each with its value, limit, method
// or standard, window, verdict and the inputs and approximations it rests on; the scene file it was
// made from (path and SHA-256 of its text), the --set overrides, the tool's version and the date;
// the counts of pass / FAIL / n/a and the overall line. Built once here; signoff.json, the
// console, signoff.html (report/SignOffSheetHtml.h) and Python render it.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/SizingCheck.h"

namespace rollerdyn {

// What the sheet states about where it comes from.
struct SignOffSource {
  std::string scene_name;
  std::string scene_path;              // the scene file, absolute
  std::string scene_text;              // its text as read (hashed on the sheet)
  std::vector<std::string> overrides;  // --set key=value, in order
  std::string tool_version;            // "rollerdyn 0.1 (commit 0123abcd)"
  std::string date;                    // when the sheet was made, ISO 8601 UTC
};

// One line of the sheet: a check as computed, and its verdict in three words.
struct SignOffRow {
  std::string group;    // "drive sizing" | "torsional modes"
  SizingCheck check;    // as the run wrote it
  std::string verdict;  // "pass" | "FAIL" | "not applicable" (also where no limit is given to compare with)
  std::string reason;   // for n/a: why, and what to give or do; else what decided
  std::vector<std::string> keys;  // the scene keys the reason names (what to set or check)
};

struct SignOffSheet {
  SignOffSource source;
  std::string scene_sha256;
  std::string model;             // the model the run was made with
  std::string run_status;        // the run's status; "" when it completed
  std::string motion;            // the crank's motion
  std::vector<std::string> warnings;  // the run's warnings, as summary.json gives them
  std::vector<SignOffRow> rows;
  int passed = 0, failed = 0, not_applicable = 0;
  bool signable = false;         // no check FAILs and the run completed
  std::string overall;           // the overall line, in words
};

// From a run's summary.json (summarizeRun, with the modal analysis under "modes" when made).
SignOffSheet buildSignOffSheet(const nlohmann::json& summary, const SignOffSource& source);

// signoff.json.
nlohmann::json signOffJson(const SignOffSheet& sheet);
// The console's lines: the overall line, the counts and one line per check.
std::string signOffSheetText(const SignOffSheet& sheet);

// "n/a" for "not applicable", else the verdict: the sheet's word.
std::string shortVerdict(const std::string& verdict);
// "≤", "<", "≥" for a check's passes_when ("<=", "<", ">="); "" otherwise.
std::string comparisonSymbol(const std::string& passes_when);

}  // namespace rollerdyn
