// The claims of `rollerdyn validate` and their verdicts: one mechanism for every validation item,
// so that what report.md prints, what the closing summary counts and what the exit status says
// are the same thing. A verdict printed in the report is a Claim; `validate` exits 1 when any
// claim is FAILED (validationExitStatus, ValidationSuite.h).
//
// Adding a validation item (a new file, e.g. src/compare/ValidationStartup.cpp):
//   ValidationSection startupChecks(const ItemContext& ctx) {       // ValidationItems.h
//     ValidationSection s("startup", "Start-up against its closed forms");
//     const RunResult run = runReducedModel(ctx.load("balanced-4cart.yaml", {...}));
//     s.text() << "What is compared, with symbols and units ...\n\n";
//     s.claim(err <= tol, "Start-up time within " + ... + " of the closed form t = J·ω/M ...");
//     return s;
//   }
// then declare it in ValidationItems.h and add one line to validationItems() in
// ValidationItems.cpp. Its section appears in report.md, its claims in results.json, the
// summary and the exit status. Each claim's sentence carries the numbers compared and the
// tolerance, argued from physics or numerics in the code beside it.
#pragma once

#include <sstream>
#include <string>
#include <vector>

namespace rollerdyn::validation {

enum class Verdict {
  Measurement,   // numbers reported, no claim made
  Holds,         // a comparison made in this run, and it held
  Fails,         // a comparison made in this run, and it did not hold: validate exits 1
  GapExplained,  // a known difference from a published table that the papers' own inputs cannot
                 // reproduce, printed with its numbers and its reason; "explained" is itself
                 // computed (the reason's claims hold), else the verdict is Fails
};

// As report.md prints it: "**holds**", "**FAILED**", "**gap, explained**"; "" for a measurement.
std::string verdictText(Verdict v);
// As results.json writes it: "holds", "failed", "gap_explained", "measurement".
const char* verdictKey(Verdict v);

struct Claim {
  std::string id;       // unique within one report, e.g. "D3", "sizing.4"
  std::string section;  // the report section it is printed in
  std::string text;     // the sentence with its numbers (a gap: what differs, and why)
  Verdict verdict = Verdict::Measurement;
};

struct ClaimCount {
  int holds = 0, failed = 0, gaps = 0;
  int total() const { return holds + failed + gaps; }
};
ClaimCount countClaims(const std::vector<Claim>& claims);

// One section of report.md written by a validation item: markdown and claims in the order they
// are added. Claim ids are "<key>.<n>", n counting from 1 in the section.
class ValidationSection {
 public:
  ValidationSection(std::string key, std::string title);
  ValidationSection(const ValidationSection& o);
  ValidationSection& operator=(const ValidationSection& o);
  ValidationSection(ValidationSection&&) = default;
  ValidationSection& operator=(ValidationSection&&) = default;

  // Free markdown: the set-up, tables, measurements (no verdict).
  std::ostringstream& text() { return md_; }

  // A comparison made in this run: Holds when `holds`, else Fails. Printed as a list item,
  // "- <sentence> **holds**". Returns the claim's id.
  std::string claim(bool holds, const std::string& sentence);

  // A difference from a published source that the inputs cannot reproduce: `numbers` says what
  // differs by how much, `reason` why. `explained`: the reason's own claims hold; when false the
  // verdict is Fails ("gap not explained").
  std::string gap(bool explained, const std::string& numbers, const std::string& reason);

  const std::string& key() const { return key_; }
  const std::string& title() const { return title_; }
  std::string markdown() const { return md_.str(); }
  const std::vector<Claim>& claims() const { return claims_; }

 private:
  std::string add(Verdict v, const std::string& sentence);
  std::string key_, title_;
  std::ostringstream md_;
  std::vector<Claim> claims_;
};

}  // namespace rollerdyn::validation
