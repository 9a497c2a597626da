// The one-page HTML report of `rollerdyn report`: scene name and source, effects built, the
// mechanism in motion beside interactive time plots (src/report/MechanismAnimation.h,
// TimePlots.h), the scene's parameters, the summary metrics, a reactions table (min/max per
// joint over the steady window, from summary.json) and the figures embedded as base64 PNG. The
// page is self-contained: inline CSS and inline scripts (Chart.js copied in from Debian's
// libjs-chart.js when the page is written), no script, font, image or style sheet from anywhere
// else, so it opens offline and can be mailed or archived as one file.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "report/MechanismAnimation.h"
#include "report/RunFigures.h"
#include "report/SceneTable.h"
#include "report/TimePlots.h"

namespace rollerdyn {

struct ReportContent {
  std::string scene_name;
  std::string scene_source;               // citation (scene `source` key)
  std::string scene_path;                 // file as given
  std::vector<std::string> overrides;     // --set arguments, in order
  std::vector<std::string> effects;       // Scene::effects()
  std::vector<SceneParameterRow> parameters, derived;
  nlohmann::json summary;                 // summary.json of the run
  std::vector<std::string> reaction_columns;  // reactions.csv column order (for the table)
  std::vector<FigureFile> figures;        // PNGs are read and embedded
  std::vector<std::string> notes;         // figures left out, warnings
  std::string command;                    // command line that produced the report
  MechanismFrames animation;              // the mechanism in motion (empty: section left out)
  std::vector<TimePlot> time_plots;       // interactive time plots beside the animation
  // Further sections, whole HTML fragments written by their own modules (each escapes its own
  // text and embeds its own figures), placed after the figures: e.g. the torsional modes.
  std::vector<std::string> extra_sections_html;
  std::string chartjs_path = kChartJsPath;  // Chart.js file inlined for them (missing: a note, PNGs only)
};

// The report's parts for one run as HTML fragments (no page around them), each text escaped; the
// Python interface shows the same tables in Jupyter.
// "Run complete/INCOMPLETE: status" and the run's warnings (summary.json `warnings`).
std::string runStatusHtml(const nlohmann::json& summary);
// The run's resonance and stability verdict (summary "resonance_verdict", "stability"), rendered.
std::string resonanceVerdictHtml(const nlohmann::json& summary);
// "Summary metrics": speed, δ, H, k_p, torque swings, steady window, energy audit, cost.
std::string summaryMetricsHtml(const nlohmann::json& summary);
// "Joint reactions over the steady window": min, max, mean, |max| per reactions column.
std::string reactionsTableHtml(const nlohmann::json& summary, const std::vector<std::string>& reaction_columns);
// "Scene parameters": every key with its value, unit, origin and meaning, and the derived quantities.
std::string sceneParametersHtml(const std::vector<SceneParameterRow>& parameters,
                                const std::vector<SceneParameterRow>& derived);

// The page as one string. Every text from the scene or the run is HTML-escaped. Throws
// std::runtime_error if a figure's PNG cannot be read.
std::string renderReportHtml(const ReportContent& content);

// Standard base64 (RFC 4648, with padding).
std::string base64Encode(const std::string& bytes);

// A figure's PNG as an <img> with its bytes inline (base64), empty when the figure has no PNG.
// Throws std::runtime_error if the PNG cannot be read.
std::string embeddedPngHtml(const FigureFile& figure);

// Escapes & < > " ' for HTML text and attribute values.
std::string htmlEscape(const std::string& text);

}  // namespace rollerdyn
