// The main time plots of the HTML report as interactive charts (values on hover, a click moves
// the mechanism animation to that time, a cursor follows the animation, whole run / steady
// window view), drawn by Chart.js from Debian's libjs-chart.js, whose file is inlined into the
// page when the report is written so that the page still needs no network. Without that file
// the section says so and the PNG figures of the report remain the plots.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/Table.h"

namespace rollerdyn {

// Chart.js 3 as Debian's libjs-chart.js installs it (scripts/setup.sh).
extern const char* const kChartJsPath;

struct TimePlotLine {
  std::string label;       // legend text, e.g. "F_rod_1"
  std::string color;       // CSS colour
  std::vector<double> y;   // one value per entry of TimePlot::t
  bool dashed = false;     // drawn dashed (second quantity of the same cart)
};

struct TimePlot {
  std::string id;          // element id suffix, e.g. "crank_speed"
  std::string title;       // chart title
  std::string y_label;     // axis title with unit, e.g. "ω [rad/s]"
  std::string unit;        // unit for hover values, e.g. "rad/s"
  std::vector<double> t;   // times [s]
  std::vector<TimePlotLine> lines;
};

// Crank and motor speed, coupling and motor torque, rod forces and guide reactions against
// time, from every `stride`-th row (at most `max_points` per line). Plots whose columns are
// absent are left out.
std::vector<TimePlot> mainTimePlots(const Table& timeseries, const Table& reactions, std::size_t max_points = 2000);

// The plots as the page reads them (rounded to 6 significant digits), with the steady window.
nlohmann::json timePlotsJson(const std::vector<TimePlot>& plots, double steady_begin, double steady_end);

// The report section: one canvas per plot, Chart.js read from `chartjs_path` and inlined, the
// plot data and the script. If the file cannot be read: a note that the PNG figures below show
// these quantities, and no canvases. The section element carries data-charts (charts made) and,
// once drawn, data-painted (charts whose canvas has pixels) for tests.
std::string timePlotsHtml(const std::vector<TimePlot>& plots, const std::string& chartjs_path, double steady_begin,
                          double steady_end);

}  // namespace rollerdyn
