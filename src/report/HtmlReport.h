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

// The page as one string. Every text from the scene or the run is HTML-escaped. Throws
// std::runtime_error if a figure's PNG cannot be read.
std::string renderReportHtml(const ReportContent& content);

// Standard base64 (RFC 4648, with padding).
std::string base64Encode(const std::string& bytes);

// Escapes & < > " ' for HTML text and attribute values.
std::string htmlEscape(const std::string& text);

}  // namespace rollerdyn
