#include "report/SignOffSheetHtml.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "report/HtmlReport.h"
#include "io/FieldFormat.h"

namespace rollerdyn {

namespace {

constexpr const char* kStyle = R"(<style>
@page { size: A4; margin: 14mm 12mm 14mm 12mm; }
body { font-family: "DejaVu Sans", Arial, sans-serif; font-size: 9.5pt; color: #111; margin: 0 auto; max-width: 190mm; }
h1 { font-size: 15pt; margin: 0 0 2mm 0; }
h2 { font-size: 11pt; margin: 5mm 0 1.5mm 0; border-bottom: 1px solid #888; }
table { border-collapse: collapse; width: 100%; }
td, th { border: 1px solid #999; padding: 1.2mm 1.6mm; vertical-align: top; text-align: left; }
th { background: #eee; font-weight: 600; }
table.head td:first-child { width: 30mm; color: #444; }
td.n { text-align: right; white-space: nowrap; font-variant-numeric: tabular-nums; }
.mono { font-family: "DejaVu Sans Mono", monospace; font-size: 8.5pt; word-break: break-all; }
.overall { border: 2px solid #111; padding: 2.5mm 3mm; margin: 4mm 0; font-weight: 600; }
.overall.fail { border-color: #b00; color: #b00; }
.overall.ok { border-color: #070; }
tr.check { page-break-inside: avoid; break-inside: avoid; }
tbody.check { page-break-inside: avoid; break-inside: avoid; }
tbody.group { page-break-after: avoid; break-after: avoid; }
td.v { font-weight: 700; text-align: center; width: 12mm; }
td.pass { color: #070; } td.FAIL { color: #fff; background: #b00; } td.na { color: #555; background: #f2f2f2; }
td.detail { font-size: 8.3pt; color: #333; border-top: none; }
td.detail b { color: #111; font-weight: 600; }
ul.small { font-size: 8.5pt; margin: 1mm 0; padding-left: 5mm; }
table.sign td { height: 12mm; }
table.sign td:first-child { width: 40mm; color: #444; }
.small { font-size: 8.3pt; color: #333; }
</style>
)";

std::string esc(const std::string& s) { return htmlEscape(s); }

// A CSS string literal of `s` (quotes and backslashes escaped; HTML's < and > too, inside <style>).
std::string cssString(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '<' || c == '>' || c == '\n') {
      out += c == '<' ? "\\3c " : c == '>' ? "\\3e " : " ";
      continue;
    }
    out += c;
  }
  return out + "\"";
}

// Every printed page names the sheet and the scene's hash, and its number of the total.
std::string pageBoxes(const SignOffSheet& s) {
  const std::string left = "Sign-off sheet: " + s.source.scene_name + ", scene SHA-256 " + s.scene_sha256.substr(0, 16) +
                           "…, " + s.source.date;
  return "<style>\n@page { @bottom-left { content: " + cssString(left) +
         "; font: 7.5pt sans-serif; color: #555; } @bottom-right { content: \"page \" counter(page) \" of \" "
         "counter(pages); font: 7.5pt sans-serif; color: #555; } }\n</style>\n";
}

std::string number(double v) { return significantOr(v, 3, "—"); }

std::string limitText(const SizingCheck& c) {
  if (!std::isfinite(c.limit)) return "—";
  return esc(comparisonSymbol(c.passes_when)) + " " + significant(c.limit, 4);
}

void header(std::ostringstream& h, const SignOffSheet& s) {
  h << "<h1>Sign-off sheet: " << esc(s.source.scene_name) << "</h1>\n<table class=\"head\">\n";
  h << "<tr><td>scene file</td><td class=\"mono\">" << esc(s.source.scene_path) << "</td></tr>\n";
  h << "<tr><td>SHA-256 of its text</td><td class=\"mono\">" << s.scene_sha256 << "</td></tr>\n";
  h << "<tr><td>overrides (--set)</td><td class=\"mono\">";
  if (s.source.overrides.empty()) h << "none";
  for (std::size_t i = 0; i < s.source.overrides.size(); ++i) h << (i ? "<br>" : "") << esc(s.source.overrides[i]);
  h << "</td></tr>\n";
  h << "<tr><td>made by</td><td>" << esc(s.source.tool_version) << ", " << esc(s.model) << " model; " << esc(s.source.date)
    << "</td></tr>\n";
  h << "<tr><td>crank motion</td><td>" << esc(s.motion)
    << (s.run_status.empty() ? std::string(", run complete") : ", run incomplete: " + esc(s.run_status)) << "</td></tr>\n";
  h << "</table>\n";
}

// A check's second row: what decided it (or why it fails, why n/a), the scene keys a FAIL or n/a
// names, its method and what it rests on.
void checkDetailRow(std::ostringstream& h, const SignOffRow& r) {
  const SizingCheck& c = r.check;
  h << "<tr><td class=\"detail\" colspan=\"5\">";
  h << "<b>" << (r.verdict == "pass" ? "decided by" : r.verdict == "FAIL" ? "why it fails" : "why n/a") << ":</b> "
    << esc(r.reason);
  if (r.verdict != "pass" && !r.keys.empty()) {
    h << "<br><b>scene keys named:</b> <span class=\"mono\">";
    for (std::size_t i = 0; i < r.keys.size(); ++i) h << (i ? ", " : "") << esc(r.keys[i]);
    h << "</span>";
  }
  if (!c.method.empty()) h << "<br><b>method:</b> " << esc(c.method);
  if (!c.basis.empty()) h << "<br><b>rests on:</b> " << esc(c.basis);
  h << "</td></tr></tbody>\n";
}

void checkRows(std::ostringstream& h, const SignOffSheet& s) {
  h << "<h2>Checks</h2>\n<p class=\"small\">Value: the deciding figure of each check, dimensionless (a ratio to "
       "its rating, a damage sum or a margin); it passes when it stands to the limit as shown. n/a: the check was "
       "not made, for the reason given.</p>\n";
  h << "<table>\n<thead><tr><th>#</th><th>check</th><th>value</th><th>limit</th><th>verdict</th><th>window</th></tr>"
       "</thead>\n";
  int n = 0;
  std::string group;
  for (const SignOffRow& r : s.rows) {
    const SizingCheck& c = r.check;
    if (r.group != group) {
      group = r.group;
      h << "<tbody class=\"group\"><tr><th colspan=\"6\">" << esc(group) << "</th></tr></tbody>\n";
    }
    const std::string cls = r.verdict == "pass" ? "pass" : r.verdict == "FAIL" ? "FAIL" : "na";
    h << "<tbody class=\"check\"><tr><td class=\"n\" rowspan=\"2\">" << ++n << "</td><td>" << esc(c.what)
      << "</td><td class=\"n\">" << number(c.value) << "</td><td class=\"n\">" << limitText(c) << "</td><td class=\"v "
      << cls << "\">" << esc(shortVerdict(r.verdict)) << "</td><td>" << esc(c.window) << "</td></tr>\n";
    checkDetailRow(h, r);
  }
  h << "</table>\n";
}

void signature(std::ostringstream& h) {
  h << "<h2>Review</h2>\n<table class=\"sign\">\n"
       "<tr><td>decision</td><td>&#9744; signed off &nbsp;&nbsp;&nbsp; &#9744; not signed off</td></tr>\n"
       "<tr><td>reviewer's name</td><td></td></tr>\n"
       "<tr><td>date</td><td></td></tr>\n"
       "<tr><td>signature</td><td></td></tr>\n"
       "<tr><td>remarks (accepted n/a, conditions)</td><td style=\"height:24mm\"></td></tr>\n"
       "</table>\n";
}

}  // namespace

std::string signOffSheetHtml(const SignOffSheet& s) {
  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>Sign-off sheet: "
    << esc(s.source.scene_name) << "</title>\n"
    << kStyle << pageBoxes(s) << "</head>\n<body>\n";
  header(h, s);
  h << "<div class=\"overall " << (s.failed > 0 || !s.run_status.empty() ? "fail" : s.signable && s.not_applicable == 0 ? "ok" : "")
    << "\">" << esc(s.overall) << "</div>\n";
  checkRows(h, s);
  if (!s.warnings.empty()) {
    h << "<h2>Warnings of the run</h2>\n<ul class=\"small\">\n";
    for (const std::string& w : s.warnings) h << "<li>" << esc(w) << "</li>\n";
    h << "</ul>\n";
  }
  signature(h);
  h << "</body>\n</html>\n";
  return h.str();
}

}  // namespace rollerdyn
