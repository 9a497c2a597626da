#include "compare/ValidationClaims.h"

namespace rollerdyn::validation {

std::string verdictText(Verdict v) {
  switch (v) {
    case Verdict::Holds: return "**holds**";
    case Verdict::Fails: return "**FAILED**";
    case Verdict::GapExplained: return "**gap, explained**";
    default: return "";
  }
}

const char* verdictKey(Verdict v) {
  switch (v) {
    case Verdict::Holds: return "holds";
    case Verdict::Fails: return "failed";
    case Verdict::GapExplained: return "gap_explained";
    default: return "measurement";
  }
}

ClaimCount countClaims(const std::vector<Claim>& claims) {
  ClaimCount c;
  for (const Claim& x : claims) {
    if (x.verdict == Verdict::Holds) ++c.holds;
    if (x.verdict == Verdict::Fails) ++c.failed;
    if (x.verdict == Verdict::GapExplained) ++c.gaps;
  }
  return c;
}

ValidationSection::ValidationSection(std::string key, std::string title)
    : key_(std::move(key)), title_(std::move(title)) {}

ValidationSection::ValidationSection(const ValidationSection& o)
    : key_(o.key_), title_(o.title_), claims_(o.claims_) {
  md_ << o.md_.str();
}

ValidationSection& ValidationSection::operator=(const ValidationSection& o) {
  if (this != &o) {
    key_ = o.key_;
    title_ = o.title_;
    claims_ = o.claims_;
    md_.str("");
    md_.clear();
    md_ << o.md_.str();
  }
  return *this;
}

std::string ValidationSection::add(Verdict v, const std::string& sentence) {
  Claim c;
  c.id = key_ + "." + std::to_string(claims_.size() + 1);
  c.section = title_;
  c.text = sentence;
  c.verdict = v;
  claims_.push_back(c);
  md_ << "- **" << c.id << "** " << sentence << " " << verdictText(v) << "\n";
  return c.id;
}

std::string ValidationSection::claim(bool holds, const std::string& sentence) {
  return add(holds ? Verdict::Holds : Verdict::Fails, sentence);
}

std::string ValidationSection::gap(bool explained, const std::string& numbers, const std::string& reason) {
  return add(explained ? Verdict::GapExplained : Verdict::Fails,
             numbers + (explained ? " Why: " : " Not explained: the reason given fails its own checks: ") + reason);
}

}  // namespace rollerdyn::validation
