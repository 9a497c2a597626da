#include "report/HtmlReport.h"
#include "report/SizingSection.h"
#include "report/StartUpSection.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <sstream>
#include <stdexcept>

#include "io/ReadFile.h"
#include "report/PageData.h"
#include "io/FieldFormat.h"

namespace rollerdyn {

namespace {

using nlohmann::json;

// A JSON value at a dotted path ("omega_crank.mean"), null when absent.
std::string number(const json& v, const char* f = "%.6g") {
  if (v.is_boolean()) return v.get<bool>() ? "yes" : "no";
  if (!v.is_number()) return v.is_string() ? v.get<std::string>() : "n/a";
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v.get<double>());
  return buf;
}

// What a reactions.csv column is, for the table.
std::string reactionMeaning(const std::string& c) {
  auto cart = [&c](const std::string& prefix) { return c.substr(prefix.size()); };
  if (c.rfind("N_front_", 0) == 0) return "guide reaction, front guide roller, cart " + cart("N_front_");
  if (c.rfind("N_rear_", 0) == 0) return "guide reaction, rear guide roller, cart " + cart("N_rear_");
  if (c.rfind("F_rod_", 0) == 0) return "rod force (> 0 tension), cart " + cart("F_rod_");
  if (c.rfind("friction_", 0) == 0) return "guide friction force along x, cart " + cart("friction_");
  if (c.rfind("crankpin_x_", 0) == 0) return "rod force on crank pin, x, cart " + cart("crankpin_x_");
  if (c.rfind("crankpin_y_", 0) == 0) return "rod force on crank pin, y, cart " + cart("crankpin_y_");
  if (c == "bearing_x") return "main bearings, resultant on the crankshaft, x";
  if (c == "bearing_y") return "main bearings, resultant on the crankshaft, y";
  if (c == "coupling_torque") return "coupling torque at the crank axis";
  return "";
}

std::string reactionUnit(const std::string& c) { return c == "coupling_torque" ? "N·m" : "N"; }

const char* const kStyle = R"(
body{font-family:"DejaVu Sans",Arial,sans-serif;margin:24px auto;max-width:1100px;color:#222;line-height:1.35}
h1{font-size:1.6em;margin-bottom:4px}h2{font-size:1.25em;border-bottom:2px solid #1f77b4;padding-bottom:3px;margin-top:32px}
table{border-collapse:collapse;margin:8px 0;font-size:0.88em}
th,td{border:1px solid #ccc;padding:3px 8px;text-align:left;vertical-align:top}
th{background:#eef3f8;white-space:nowrap}td.n{text-align:right;font-family:"DejaVu Sans Mono",monospace;white-space:nowrap}
tr:nth-child(even) td:not(.ok):not(.bad):not(.warn):not(.na){background:#fafafa}
.status{padding:8px 12px;border-radius:4px;margin:10px 0;font-weight:bold}
.ok{background:#e3f4e3;border:1px solid #7bbf7b}.bad{background:#fde2e2;border:1px solid #d77}
.na{background:#ececec;border:1px solid #bbb;color:#555}
.warn{background:#fff4d6;border:1px solid #e0b040;font-weight:normal}.warn ul{margin:4px 0}
.chip{display:inline-block;background:#eef3f8;border:1px solid #b8cde2;border-radius:10px;padding:1px 9px;margin:2px;font-size:0.9em}
figure{margin:18px 0;page-break-inside:avoid}figure img{max-width:100%;border:1px solid #ddd}
figcaption{font-size:0.9em;color:#444;margin-top:4px}.small{font-size:0.85em;color:#555}
code{background:#f3f3f3;padding:0 3px}
.motion{display:grid;grid-template-columns:548px minmax(0,1fr);gap:14px;align-items:start}
.mech-controls{margin:2px 0 6px;font-size:0.9em}.mech-controls input[type=range]{width:250px;vertical-align:middle}
#mech-canvas{border:1px solid #ddd;display:block}
.plot{position:relative;height:205px;margin:4px 0 6px}
.cursor{position:absolute;width:0;border-left:2px solid rgba(214,39,40,0.75);pointer-events:none;display:none}
)";

// Script errors of the page are recorded on <html data-script-errors> (read by the browser test).
const char* const kErrorRecorder =
    "window.addEventListener('error', function (e) { var r = document.documentElement;"
    " r.setAttribute('data-script-errors', (r.getAttribute('data-script-errors') || '') + (e.message || 'error') + '; '); });";

// After loading, <body data-figures="loaded/total">: how many embedded figures decoded.
const char* const kFigureCounter =
    "window.addEventListener('load', function () { var imgs = document.querySelectorAll('figure img'), ok = 0;"
    " imgs.forEach(function (i) { if (i.complete && i.naturalWidth > 0) ok++; });"
    " document.body.setAttribute('data-figures', ok + '/' + imgs.length); });";

// After loading, <body data-verdict-cells="class rgb(...);...">: each verdict cell's class and the
// background the browser painted it with (the browser test checks that every row shows its
// verdict's colour: a striped-row rule once hid FAILs in even rows).
const char* const kVerdictColours =
    "window.addEventListener('load', function () { var out = [];"
    " document.querySelectorAll('td.ok, td.bad, td.na, td.warn').forEach(function (c) {"
    " out.push(c.className + ' ' + getComputedStyle(c).backgroundColor + ' ' + c.textContent.trim()); });"
    " document.body.setAttribute('data-verdict-cells', out.join(';')); });";

// The reducer's teeth over the steady window (summary.json backlash), for a scene with backlash.
std::string backlashHtml(const json& b);

}  // namespace

std::string htmlEscape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

namespace {

const char* const kBase64Alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

// The first `chars` base64 digits of the 24 bits v, padded with '=' to four.
void appendBase64Quantum(std::string& out, unsigned v, int chars) {
  for (int k = 0; k < 4; ++k) out += k < chars ? kBase64Alphabet[(v >> (18 - 6 * k)) & 63] : '=';
}

}  // namespace

std::string base64Encode(const std::string& bytes) {
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) |
                       (static_cast<unsigned char>(bytes[i + 1]) << 8) | static_cast<unsigned char>(bytes[i + 2]);
    appendBase64Quantum(out, v, 4);
  }
  if (i + 1 == bytes.size()) {
    appendBase64Quantum(out, static_cast<unsigned char>(bytes[i]) << 16, 2);
  } else if (i + 2 == bytes.size()) {
    const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) | (static_cast<unsigned char>(bytes[i + 1]) << 8);
    appendBase64Quantum(out, v, 3);
  }
  return out;
}

std::string embeddedPngHtml(const FigureFile& f) {
  if (f.png.empty()) return "";
  return "<img alt=\"" + htmlEscape(f.name) + "\" src=\"data:image/png;base64," +
         base64Encode(readFileContents(f.png, "figure")) + "\">";
}

namespace {

// A string member of a summary object, empty when absent.
std::string textOf(const json& o, const char* k) {
  return o.is_object() && o.contains(k) && o[k].is_string() ? o[k].get<std::string>() : std::string();
}

// The resonance verdict's banner: green for no resonance, yellow for a warning, none for n/a.
void resonanceBanner(std::ostringstream& h, const json& rv) {
  const std::string verdict = textOf(rv, "verdict");
  if (verdict == "no resonance")
    h << "<div class=\"status ok\">Resonance verdict (modal analysis about the steady motion): "
      << htmlEscape(textOf(rv, "reason")) << "</div>\n";
  else if (verdict == "not applicable")
    h << "<div class=\"status\">Resonance verdict: n/a (" << htmlEscape(textOf(rv, "reason")) << ")</div>\n";
  else if (!verdict.empty() && verdict != "no hit")
    h << "<div class=\"status warn\">Resonance verdict: " << htmlEscape(verdict) << " (see the warnings)</div>\n";
  const std::string first = textOf(rv, "line");
  if (!first.empty()) h << "<p class=\"small\">" << htmlEscape(first) << "</p>\n";
}

// The Floquet stability's banner: green when stable, red when not, none for n/a (with the reason).
void stabilityBanner(std::ostringstream& h, const json& st) {
  const std::string stability = textOf(st, "verdict");
  if (stability == "not applicable" || stability == "not assessed")
    h << "<div class=\"status\">Stability of the steady motion (Floquet): n/a (" << htmlEscape(textOf(st, "reason"))
      << ")</div>\n";
  else if (stability == "stable")
    h << "<div class=\"status ok\">Stability of the steady motion (Floquet): stable</div>\n";
  else if (!stability.empty())
    h << "<div class=\"status bad\">Stability of the steady motion (Floquet): " << htmlEscape(stability) << "</div>\n";
}

}  // namespace

std::string resonanceVerdictHtml(const nlohmann::json& s) {
  // The run's resonance and stability verdict as summary.json has it (studies/ResonanceCheck.h):
  // green where it found no resonance and a stable steady motion, yellow where it warns, no colour
  // where it does not apply (with the reason).
  std::ostringstream h;
  resonanceBanner(h, jsonAt(s, "resonance_verdict"));
  stabilityBanner(h, jsonAt(s, "stability"));
  return h.str();
}

std::string runStatusHtml(const nlohmann::json& s) {
  std::ostringstream h;
  const bool complete = jsonAt(s, "complete").is_boolean() && jsonAt(s, "complete").get<bool>();
  h << "<div class=\"status " << (complete ? "ok" : "bad") << "\">" << (complete ? "Run complete" : "Run INCOMPLETE")
    << ": " << htmlEscape(number(jsonAt(s, "status"))) << "</div>\n";
  const json warnings = jsonAt(s, "warnings");  // e.g. resonance warnings (summary.json)
  if (warnings.is_array() && !warnings.empty()) {
    h << "<div class=\"status warn\">Warnings:<ul>";
    for (const json& w : warnings) h << "<li>" << htmlEscape(w.is_string() ? w.get<std::string>() : w.dump()) << "</li>";
    h << "</ul></div>\n";
  }
  h << resonanceVerdictHtml(s);

  return h.str();
}

namespace {

// One row of the summary metrics: where summary.json has it, its words, unit and format.
struct Metric {
  const char* path;
  const char* label;
  const char* unit;
  const char* fmt;
};

// The rows in the order of the table.
const Metric kSummaryMetrics[] = {
    {"omega_crank.mean", "mean crank speed ω_mean", "rad/s", "%.6g"},
    {"omega_crank.min", "minimum crank speed ω_min", "rad/s", "%.6g"},
    {"omega_crank.max", "maximum crank speed ω_max", "rad/s", "%.6g"},
    {"delta", "speed fluctuation δ = (ω_max − ω_min)/ω_mean (Loveikin and Pochka (2007) eq. (12))", "-", "%.5g"},
    {"H", "H = |ε|_max/ω_mean² (Loveikin and Pochka (2007) eq. (13))", "-", "%.5g"},
    {"k_p", "k_p (Loveikin and Pochka (2007) eq. (14))", "-", "%.5g"},
    {"eps_crank_abs_max", "largest crank acceleration |ε|_max", "rad/s²", "%.5g"},
    {"coupling_torque_swing", "coupling torque swing (Loveikin, Pochka, Romasevych (2018) Table 1)", "N·m", "%.5g"},
    {"twist_swing", "twist swing", "rad", "%.4g"},
    {"twist_rate_swing", "twist rate swing", "rad/s", "%.4g"},
    {"twist_accel_swing", "twist acceleration swing", "rad/s²", "%.4g"},
    {"steady_state.reached", "steady state reached", "", "%g"},
    {"steady_state.t_begin", "steady window from", "s", "%.5g"},
    {"steady_state.t_end", "steady window to", "s", "%.5g"},
    {"steady_state.window_revolutions", "revolutions in the window", "", "%g"},
    {"simulated_time", "simulated time", "s", "%.5g"},
    {"energy_residual_rel", "energy audit residual (relative)", "-", "%.2e"},
    {"constraint_error_max", "largest constraint error", "-", "%.2e"},
    {"steps", "integrator steps", "", "%.0f"},
    {"rejected_steps", "steps rejected by the error test", "", "%.0f"},
    {"realizations", "right-hand-side evaluations", "", "%.0f"},
    {"cpu_seconds", "CPU time", "s", "%.3g"},
    {"real_time_factor", "simulated time / CPU time", "-", "%.3g"},
};

}  // namespace

std::string summaryMetricsHtml(const nlohmann::json& s) {
  std::ostringstream h;
  h << "<h2>Summary metrics</h2>\n<p class=\"small\">Over the steady-state window (summary.json).</p>\n";
  if (jsonAt(s, "steady_state.reached").is_boolean() && !jsonAt(s, "steady_state.reached").get<bool>())
    h << "<div class=\"status warn\">Steady state NOT reached: the metrics and reaction ranges below are "
         "taken over the last part of the run and include transients. "
      << htmlEscape(number(jsonAt(s, "steady_state.note"))) << "</div>\n";
  h << "<table>\n<tr><th>quantity</th><th>value</th><th>unit</th></tr>\n";
  for (const Metric& m : kSummaryMetrics)
    h << "<tr><td>" << htmlEscape(m.label) << "</td><td class=\"n\">" << htmlEscape(number(jsonAt(s, m.path), m.fmt))
      << "</td><td>" << m.unit << "</td></tr>\n";
  h << "</table>\n" << backlashHtml(jsonAt(s, "backlash"));

  return h.str();
}

namespace {

// The joints of the table: reactions.csv's column order first, then any other summary.json has.
std::vector<std::string> reactionOrder(const json& rx, const std::vector<std::string>& reaction_columns) {
  std::vector<std::string> order;
  for (const std::string& col : reaction_columns)
    if (rx.contains(col)) order.push_back(col);
  for (auto it = rx.begin(); it != rx.end(); ++it)
    if (std::find(order.begin(), order.end(), it.key()) == order.end()) order.push_back(it.key());
  return order;
}

// One joint quantity's row: name, meaning, unit, min, max, mean and |max|.
std::string reactionRowHtml(const std::string& col, const json& r) {
  std::ostringstream h;
  h << "<tr><td><code>" << htmlEscape(col) << "</code></td><td>" << htmlEscape(reactionMeaning(col))
    << "</td><td>" << reactionUnit(col) << "</td>";
  for (const char* k : {"min", "max", "mean", "abs_max"})
    h << "<td class=\"n\">" << htmlEscape(number(r.is_object() && r.contains(k) ? r[k] : json(nullptr), "%.6g"))
      << "</td>";
  h << "</tr>\n";
  return h.str();
}

}  // namespace

std::string reactionsTableHtml(const nlohmann::json& s, const std::vector<std::string>& reaction_columns) {
  std::ostringstream h;
  // Reactions
  const json rx = jsonAt(s, "reactions");
  h << "<h2>Joint reactions over the steady window</h2>\n";
  if (!rx.is_object() || rx.empty()) {
    h << "<p>No reactions in summary.json.</p>\n";
    return h.str();
  }
  h << "<p class=\"small\">N &gt; 0: the guide presses the guide roller down (Loveikin, Pochka, Romasevych (2018) fig. 3); "
       "F_rod &gt; 0 in tension. Min and max over the steady window.</p>\n"
    << "<table>\n<tr><th>joint quantity</th><th>meaning</th><th>unit</th><th>min</th><th>max</th>"
       "<th>mean</th><th>|max|</th></tr>\n";
  for (const std::string& col : reactionOrder(rx, reaction_columns)) h << reactionRowHtml(col, rx[col]);
  h << "</table>\n";
  return h.str();
}

std::string sceneParametersHtml(const std::vector<SceneParameterRow>& parameters,
                                const std::vector<SceneParameterRow>& derived) {
  std::ostringstream h;
  // Parameters
  h << "<h2>Scene parameters</h2>\n<p class=\"small\">Every key of the scene schema the run used: "
       "from the file, from a --set override, or the schema default.</p>\n"
    << "<table>\n<tr><th>key</th><th>value</th><th>unit</th><th>from</th><th>meaning</th></tr>\n";
  for (const SceneParameterRow& r : parameters)
    h << "<tr><td><code>" << htmlEscape(r.key) << "</code></td><td class=\"n\">" << htmlEscape(r.value) << "</td><td>"
      << htmlEscape(r.unit) << "</td><td>" << htmlEscape(r.origin) << "</td><td>" << htmlEscape(r.meaning)
      << "</td></tr>\n";
  h << "</table>\n";
  if (!derived.empty()) {
    h << "<h3>Derived quantities</h3>\n<table>\n<tr><th>quantity</th><th>value</th><th>unit</th><th>meaning</th></tr>\n";
    for (const SceneParameterRow& r : derived)
      h << "<tr><td>" << htmlEscape(r.key) << "</td><td class=\"n\">" << htmlEscape(r.value) << "</td><td>"
        << htmlEscape(r.unit) << "</td><td>" << htmlEscape(r.meaning) << "</td></tr>\n";
    h << "</table>\n";
  }
  return h.str();
}

namespace {

// The page's head (style, error recorder), its title and the line naming model and integrator.
std::string pageHeadHtml(const ReportContent& c) {
  const json& s = c.summary;
  std::ostringstream h;
  const std::string name = htmlEscape(c.scene_name);
  h << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
    << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
    << "<title>rollerdyn report: " << name << "</title>\n<style>" << kStyle << "</style>\n"
    << inlineScriptBlock(kErrorRecorder) << "</head>\n<body>\n";
  h << "<h1>rollerdyn report: " << name << "</h1>\n";
  h << "<div class=\"small\">Drive dynamics of a roller forming installation, " << htmlEscape(number(jsonAt(s, "model")))
    << " model, integrator " << htmlEscape(number(jsonAt(s, "integrator"))) << ".</div>\n";
  return h.str();
}

// The mechanism in motion beside the interactive time plots.
std::string motionSectionHtml(const ReportContent& c) {
  if (c.animation.empty() && c.time_plots.empty()) return "";
  const json t0 = jsonAt(c.summary, "steady_state.t_begin"), t1 = jsonAt(c.summary, "steady_state.t_end");
  std::ostringstream h;
  h << "<h2>Mechanism in motion</h2>\n<p class=\"small\">Drawn to scale from this run's time series (crank "
       "angle &phi;<sub>2</sub>, cart positions) and reactions, one lane per cart because the crank planes lie "
       "one behind the other along the shaft; cart j's crank is at &phi;<sub>2</sub> + (j&minus;1)&middot;&Delta;&phi;. "
       "Arrows: guide reactions at the guide rollers and the rod force at the hinge B, each kind scaled to "
       "its largest value over the run.</p>\n<div class=\"motion\"><div>"
    << mechanismAnimationHtml(c.animation) << "</div><div>"
    << timePlotsHtml(c.time_plots, c.chartjs_path, t0.is_number() ? t0.get<double>() : 0.0,
                     t1.is_number() ? t1.get<double>() : 0.0)
    << "</div></div>\n";
  return h.str();
}

// The scene: name, file, source, the --set overrides and the effects built.
std::string sceneSectionHtml(const ReportContent& c) {
  std::ostringstream h;
  h << "<h2>Scene</h2>\n<table>\n";
  h << "<tr><th>name</th><td>" << htmlEscape(c.scene_name) << "</td></tr>\n";
  h << "<tr><th>file</th><td><code>" << htmlEscape(c.scene_path) << "</code></td></tr>\n";
  h << "<tr><th>source</th><td>" << htmlEscape(c.scene_source) << "</td></tr>\n";
  h << "<tr><th>overrides (--set)</th><td>";
  if (c.overrides.empty()) h << "none";
  for (size_t i = 0; i < c.overrides.size(); ++i)
    h << (i ? "<br>" : "") << "#" << i + 1 << " <code>" << htmlEscape(c.overrides[i]) << "</code>";
  h << "</td></tr>\n<tr><th>effects built</th><td>";
  for (const std::string& e : c.effects) h << "<span class=\"chip\">" << htmlEscape(effectWords(e)) << "</span>";
  h << "</td></tr>\n</table>\n";
  return h.str();
}

// The figures, numbered, each PNG embedded as base64 so the page needs no files beside it.
std::string figuresSectionHtml(const std::vector<FigureFile>& figures) {
  std::ostringstream h;
  h << "<h2>Figures</h2>\n";
  if (figures.empty()) h << "<p>No figures.</p>\n";
  for (size_t i = 0; i < figures.size(); ++i) {
    const FigureFile& f = figures[i];
    h << "<figure id=\"" << htmlEscape(f.name) << "\">";
    h << embeddedPngHtml(f);
    h << "<figcaption><b>Figure " << i + 1 << "</b> (<code>" << htmlEscape(f.name) << "</code>). "
      << htmlEscape(f.caption) << "</figcaption></figure>\n";
  }
  return h.str();
}

std::string notesHtml(const std::vector<std::string>& notes) {
  if (notes.empty()) return "";
  std::ostringstream h;
  h << "<h2>Notes</h2>\n<ul>\n";
  for (const std::string& n : notes) h << "<li>" << htmlEscape(n) << "</li>\n";
  h << "</ul>\n";
  return h.str();
}

}  // namespace

std::string renderReportHtml(const ReportContent& c) {
  const json& s = c.summary;
  std::ostringstream h;
  h << pageHeadHtml(c);
  h << runStatusHtml(s);
  h << motionSectionHtml(c);
  h << sceneSectionHtml(c);
  h << summaryMetricsHtml(s);
  h << sizingSectionHtml(s);   // motion, stall cause, drive sizing (SizingSection.h)
  h << startUpSectionHtml(s);  // start-up and stopping (StartUpSection.h)
  h << reactionsTableHtml(s, c.reaction_columns);
  h << figuresSectionHtml(c.figures);
  for (const std::string& section : c.extra_sections_html) h << section;
  h << notesHtml(c.notes);
  h << sceneParametersHtml(c.parameters, c.derived);
  h << "<p class=\"small\">Generated by <code>" << htmlEscape(c.command)
    << "</code>. Files next to this page: timeseries.csv, reactions.csv, summary.json, figures/*.png|svg.</p>\n";
  h << inlineScriptBlock(kFigureCounter) << inlineScriptBlock(kVerdictColours) << "</body>\n</html>\n";
  return h.str();
}

namespace {

std::string backlashHtml(const json& b) {
  if (!b.is_object() || !(b.value("backlash", 0.0) > 0.0)) return "";
  std::ostringstream h;
  h << "<h3>Backlash of the reducer</h3>\n<p class=\"small\">Total backlash 2b = " << number(b["backlash"], "%.4g")
    << " rad at the crank axis; " << htmlEscape(number(b["verdict"]));
  if (b["reason"].is_string()) h << ": " << htmlEscape(b["reason"].get<std::string>());
  h << " (over the steady window; contacts shorter than the output step are not counted).</p>\n";
  if (b["verdict"] == "not applicable") return h.str();
  h << "<table>\n<tr><th>quantity</th><th>value</th><th>unit</th></tr>\n"
    << "<tr><td>impacts per crank revolution (teeth meeting again)</td><td class=\"n\">"
    << number(b["impacts_per_revolution"], "%.4g") << "</td><td>1/rev</td></tr>\n"
    << "<tr><td>share of the time with the teeth apart, |φ1 − φ2| ≤ b</td><td class=\"n\">"
    << number(b["out_of_contact_fraction"], "%.4g") << "</td><td>-</td></tr>\n"
    << "<tr><td>peak impact torque (largest |coupling torque| from an impact to the next parting)</td><td class=\"n\">"
    << number(b["peak_impact_torque"], "%.5g") << "</td><td>N·m</td></tr>\n</table>\n";
  return h.str();
}

}  // namespace

}  // namespace rollerdyn
