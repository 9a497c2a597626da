#include "report/TimePlots.h"

#include <algorithm>
#include <stdexcept>

#include "io/ReadFile.h"
#include "report/FigureSupport.h"
#include "report/HtmlReport.h"
#include "report/PageData.h"

namespace rollerdyn {

const char* const kChartJsPath = "/usr/share/javascript/chart.js/chart.min.js";

namespace {

using figures::cartColor;  // the figures' colour of each cart (FigureSupport.h)

// The chart script: one Chart.js line chart per plot (linear time axis, no animation, hover
// values), a cursor line per chart moved on "rollerdyn-time", a click sends "rollerdyn-seek",
// and the view buttons set the time axis to the whole run or the steady window.
const char* const kScript = R"JS((function () {
  'use strict';
  var P = JSON.parse(document.getElementById('plots-data').textContent);
  var sec = document.getElementById('time-plots');
  var charts = [], cursors = [];
  P.plots.forEach(function (p) {
    var canvas = document.getElementById('plot-' + p.id);
    var datasets = p.lines.map(function (l) {
      return {label: l.label, borderColor: l.color, backgroundColor: l.color, borderWidth: 1.2, pointRadius: 0,
              borderDash: l.dashed ? [5, 3] : [],
              pointHoverRadius: 3, data: p.t.map(function (t, i) { return {x: t, y: l.y[i]}; })};
    });
    var chart = new Chart(canvas, {
      type: 'line', data: {datasets: datasets},
      options: {
        animation: false, parsing: false, normalized: true, spanGaps: false,
        responsive: true, maintainAspectRatio: false,
        interaction: {mode: 'nearest', axis: 'x', intersect: false},
        plugins: {
          title: {display: true, text: p.title},
          legend: {labels: {boxWidth: 10, font: {size: 11}}},
          tooltip: {callbacks: {
            title: function (items) { return items.length ? 't = ' + items[0].parsed.x.toFixed(3) + ' s' : ''; },
            label: function (c) { return c.dataset.label + ': ' + c.parsed.y.toPrecision(5) + ' ' + p.unit; }}}
        },
        scales: {x: {type: 'linear', min: P.t_min, max: P.t_max, title: {display: true, text: 't [s]'}},
                 y: {title: {display: true, text: p.y_label}}},
        onClick: function (e) {
          var t = chart.scales.x.getValueForPixel(e.x);
          document.dispatchEvent(new CustomEvent('rollerdyn-seek', {detail: {t: t}}));
        }
      }
    });
    var cur = document.createElement('div');
    cur.className = 'cursor';
    canvas.parentNode.appendChild(cur);
    charts.push(chart); cursors.push(cur);
  });
  var lastT = null;
  function place(t) {
    lastT = t;
    charts.forEach(function (chart, i) {
      var a = chart.chartArea, x = chart.scales.x.getPixelForValue(t), c = cursors[i];
      if (!a || !(x >= a.left && x <= a.right)) { c.style.display = 'none'; return; }
      c.style.display = 'block'; c.style.left = x + 'px'; c.style.top = a.top + 'px'; c.style.height = (a.bottom - a.top) + 'px';
    });
  }
  document.addEventListener('rollerdyn-time', function (e) { place(e.detail.t); });
  var mech = document.getElementById('mechanism');      // the time shown before these charts existed
  if (mech && mech.hasAttribute('data-t')) place(parseFloat(mech.getAttribute('data-t')));
  function view(lo, hi) {
    charts.forEach(function (c) { c.options.scales.x.min = lo; c.options.scales.x.max = hi; c.update('none'); });
    if (lastT !== null) place(lastT);
  }
  document.getElementById('view-all').addEventListener('click', function () { view(P.t_min, P.t_max); });
  var steady = document.getElementById('view-steady');
  if (P.steady_end > P.steady_begin) steady.addEventListener('click', function () { view(P.steady_begin, P.steady_end); });
  else steady.disabled = true;
  sec.setAttribute('data-charts', String(charts.length));
  // For tests: how many charts put pixels on their canvas.
  var painted = 0;
  charts.forEach(function (c) {
    var d = c.ctx.getImageData(0, 0, c.canvas.width, c.canvas.height).data;
    for (var i = 3; i < d.length; i += 4) if (d[i] !== 0) { painted++; break; }
  });
  sec.setAttribute('data-painted', String(painted));
})();)JS";

}  // namespace

namespace {

// Every stride-th row of the time series (and of the reactions sampled on its rows), and the
// plots made of them along the sampled times.
struct TimePlotSampler {
  std::size_t stride;
  std::vector<double> t;
  std::vector<TimePlot> plots;

  std::vector<double> sampled(const Table& table, const std::string& column) const {
    std::vector<double> out;
    const int c = table.index(column);
    for (std::size_t i = 0; i < table.rows.size(); i += stride) out.push_back(table.rows[i][c]);
    return out;
  }
  void plot(const std::string& id, const std::string& title, const std::string& y_label, const std::string& unit,
            const std::vector<TimePlotLine>& lines) {
    if (!lines.empty()) plots.push_back({id, title, y_label, unit, t, lines});
  }
};

// Crank and motor speed, coupling and motor torque.
void speedAndTorquePlots(TimePlotSampler& p, const Table& ts) {
  std::vector<TimePlotLine> speed, torque;
  if (ts.has("omega_crank")) speed.push_back({"crank ω₂", "#1f77b4", p.sampled(ts, "omega_crank")});
  if (ts.has("omega_motor")) speed.push_back({"motor ω₁ (at the crank axis)", "#ff7f0e", p.sampled(ts, "omega_motor")});
  p.plot("speed", "Crank and motor speed", "ω [rad/s]", "rad/s", speed);
  if (ts.has("coupling_torque")) torque.push_back({"coupling torque", "#1f77b4", p.sampled(ts, "coupling_torque")});
  if (ts.has("motor_torque")) torque.push_back({"motor torque (at the crank axis)", "#ff7f0e", p.sampled(ts, "motor_torque")});
  p.plot("torque", "Coupling and motor torque", "M [N·m]", "N·m", torque);
}

// Rod forces and guide reactions per cart (front solid, rear dashed).
void reactionPlots(TimePlotSampler& p, const Table& rx) {
  std::vector<TimePlotLine> rod, guide;
  for (int j = 1; rx.has("F_rod_" + std::to_string(j)); ++j)
    rod.push_back({"F_rod_" + std::to_string(j), cartColor(j), p.sampled(rx, "F_rod_" + std::to_string(j))});
  p.plot("rod_forces", "Rod forces (> 0 tension)", "F_rod [N]", "N", rod);
  for (int j = 1; rx.has("N_front_" + std::to_string(j)); ++j) {
    guide.push_back({"N_front_" + std::to_string(j), cartColor(j), p.sampled(rx, "N_front_" + std::to_string(j))});
    if (rx.has("N_rear_" + std::to_string(j)))
      guide.push_back({"N_rear_" + std::to_string(j), cartColor(j), p.sampled(rx, "N_rear_" + std::to_string(j)), true});
  }
  p.plot("guide_reactions", "Guide reactions (> 0: the guide presses the roller down)", "N [N]", "N", guide);
}

}  // namespace

std::vector<TimePlot> mainTimePlots(const Table& ts, const Table& rx, std::size_t max_points) {
  if (!ts.has("t") || ts.rows.empty()) return {};
  TimePlotSampler p{std::max<std::size_t>(1, (ts.rows.size() + max_points - 1) / std::max<std::size_t>(1, max_points)),
                    {}, {}};
  p.t = p.sampled(ts, "t");
  speedAndTorquePlots(p, ts);
  // Reactions: only when they are sampled on the time series' rows.
  if (rx.rows.size() == ts.rows.size()) reactionPlots(p, rx);
  return p.plots;
}

nlohmann::json timePlotsJson(const std::vector<TimePlot>& plots, double steady_begin, double steady_end) {
  using nlohmann::json;
  json j;
  double t_min = 0, t_max = 0;
  j["plots"] = json::array();
  for (const TimePlot& p : plots) {
    if (!p.t.empty()) {
      t_min = j["plots"].empty() ? p.t.front() : std::min(t_min, p.t.front());
      t_max = j["plots"].empty() ? p.t.back() : std::max(t_max, p.t.back());
    }
    json pj = {{"id", p.id}, {"title", p.title}, {"y_label", p.y_label}, {"unit", p.unit}, {"t", roundedArray(p.t, 7)}};
    pj["lines"] = json::array();
    for (const TimePlotLine& l : p.lines)
      pj["lines"].push_back({{"label", l.label}, {"color", l.color}, {"dashed", l.dashed}, {"y", roundedArray(l.y, 6)}});
    j["plots"].push_back(std::move(pj));
  }
  j["t_min"] = t_min;
  j["t_max"] = t_max;
  j["steady_begin"] = steady_begin;
  j["steady_end"] = steady_end;
  return j;
}

std::string timePlotsHtml(const std::vector<TimePlot>& plots, const std::string& chartjs_path, double steady_begin,
                          double steady_end) {
  if (plots.empty()) return "";
  std::string library;
  try {
    library = readFileContents(chartjs_path, "Chart.js");
  } catch (const std::runtime_error&) {
    return "<section id=\"time-plots\" class=\"plots\" data-charts=\"0\"><p class=\"status warn\">Interactive time "
           "plots left out: Chart.js (Debian package libjs-chart.js, <code>" + htmlEscape(chartjs_path) +
           "</code>) was not found when this report was written. The figures below show the same quantities "
           "as PNG images.</p></section>\n";
  }
  std::string h = "<section id=\"time-plots\" class=\"plots\" data-charts=\"0\">\n";
  h += "<div class=\"small\">Hover for values; click a plot to move the animation there. View: "
       "<button id=\"view-all\" type=\"button\">whole run</button> "
       "<button id=\"view-steady\" type=\"button\">steady window</button></div>\n";
  for (const TimePlot& p : plots)
    h += "<div class=\"plot\"><canvas id=\"plot-" + htmlEscape(p.id) + "\" aria-label=\"" + htmlEscape(p.title) +
         "\"></canvas></div>\n";
  h += inlineScriptBlock(library);
  h += jsonScriptBlock("plots-data", timePlotsJson(plots, steady_begin, steady_end));
  h += inlineScriptBlock(kScript);
  h += "</section>\n";
  return h;
}

}  // namespace rollerdyn
