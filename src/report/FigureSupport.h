// Helpers shared by the figures of one output folder (RunFigures.cpp, MotorFigures.cpp): columns,
// the steady window, angle folding, series and labels. Internal to src/report.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "io/Table.h"
#include "report/Gnuplot.h"
#include "report/RunFigures.h"
#include "io/FieldFormat.h"

namespace rollerdyn::figures {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Colours of the two models and of the highlighted part of a trajectory.
inline const char* const kBlue = "#1f77b4";
inline const char* const kOrange = "#ff7f0e";
inline const char* const kGreen = "#2ca02c";
inline const char* const kRed = "#d62728";
inline const char* const kGrey = "#9a9a9a";
// One colour per cart (front/rear or several quantities of one cart share it).
inline const char* const kCartColors[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e",
                                   "#17becf", "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22"};
inline const char* cartColor(int j) { return kCartColors[(j - 1) % 10]; }

// Text for gnuplot's enhanced mode taken literally (scene names, file stems).
inline std::string literal(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '_' || c == '^' || c == '{' || c == '}' || c == '@' || c == '&' || c == '~') out += '\\';
    out += c;
  }
  return out;
}

// A figure's title with the scene's label in front ("balanced-4cart: what"), `what` alone without one.
inline std::string sceneTitle(const std::string& scene_label, const std::string& what) {
  return scene_label.empty() ? what : scene_label + ": " + what;
}

inline std::string capitalized(std::string s) {
  if (!s.empty() && s[0] >= 'a' && s[0] <= 'z') s[0] = static_cast<char>(s[0] - 'a' + 'A');
  return s;
}

// Column `name` of `table`, or an empty vector when absent.
inline std::vector<double> col(const Table& table, const std::string& name) {
  return table.has(name) ? table.column(name) : std::vector<double>{};
}

inline bool anyFinite(const std::vector<double>& v) {
  return std::any_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
}

inline double absMax(const std::vector<double>& v) {
  double m = 0;
  for (double x : v)
    if (std::isfinite(x)) m = std::max(m, std::abs(x));
  return m;
}

// Linear interpolation of y(t) at `at` (t ascending); NaN outside [t.front(), t.back()].
inline double interp(const std::vector<double>& t, const std::vector<double>& y, double at) {
  if (t.empty() || !(at >= t.front() && at <= t.back())) return kNaN;
  const auto hi = std::lower_bound(t.begin(), t.end(), at);
  const size_t k = static_cast<size_t>(hi - t.begin());
  if (k == 0 || t[k] == at) return y[k];
  const double w = (at - t[k - 1]) / (t[k] - t[k - 1]);
  return y[k - 1] + w * (y[k] - y[k - 1]);
}

// Rows of `t` inside [w.t_begin, w.t_end] (all rows when the window is not found).
inline std::vector<size_t> windowRows(const std::vector<double>& t, const TimeWindow& w) {
  std::vector<size_t> rows;
  for (size_t i = 0; i < t.size(); ++i)
    if (!w.found || (t[i] >= w.t_begin && t[i] <= w.t_end)) rows.push_back(i);
  return rows;
}

inline std::vector<double> pick(const std::vector<double>& v, const std::vector<size_t>& rows) {
  std::vector<double> out;
  out.reserve(rows.size());
  for (size_t r : rows) out.push_back(r < v.size() ? v[r] : kNaN);
  return out;
}

// Values of y at the positions of a folded-angle index (NaN at the wrap markers).
inline std::vector<double> alongFold(const std::vector<double>& y, const std::vector<long>& index) {
  std::vector<double> out;
  out.reserve(index.size());
  for (long i : index) out.push_back(i < 0 || static_cast<size_t>(i) >= y.size() ? kNaN : y[i]);
  return out;
}

// The rows of the steady window with their crank angle folded to [0, 2π): one curve per
// revolution, a NaN between revolutions.
struct FoldedWindow {
  std::vector<size_t> rows;
  std::vector<long> fold;
  std::vector<double> theta;

  FoldedWindow(const std::vector<double>& t, const std::vector<double>& phi, const TimeWindow& window)
      : rows(windowRows(t, window)), theta(foldedAngle(pick(phi, rows), &fold)) {}

  // A column of the same rows along the folded angle.
  std::vector<double> along(const std::vector<double>& y) const { return alongFold(pick(y, rows), fold); }
};

inline const char* const kAnglePreamble =
    "set xrange [0:2*pi]\n"
    "set xtics ('0' 0, 'π/2' pi/2, 'π' pi, '3π/2' 3*pi/2, '2π' 2*pi)";
inline const char* const kAngleLabel = "crank angle φ_2 mod 2π [rad]";

// A dashed vertical line at time t with a label, marking where the steady window starts.
inline std::string windowMarker(const TimeWindow& w) {
  if (!w.found) return "";
  return "set arrow from " + printfNumber("%.9g", w.t_begin) + ", graph 0 to " + printfNumber("%.9g", w.t_begin) +
         ", graph 1 nohead dt 2 lc rgb '#555555'\nset label 'steady window' at " +
         printfNumber("%.9g", w.t_begin) + ", graph 0.95 offset 0.5,0 font ',9' tc rgb '#555555'";
}

inline std::string windowText(const TimeWindow& w) {
  if (!w.found) return "whole run";
  return "t = " + printfNumber("%.4g", w.t_begin) + " … " + printfNumber("%.4g", w.t_end) + " s";
}

inline PlotSeries series(std::string title, std::vector<double> x, std::vector<double> y,
                  const std::string& color = "", double lw = 1.0) {
  PlotSeries s;
  s.title = std::move(title);
  s.x = std::move(x);
  s.y = std::move(y);
  s.color = color;
  s.line_width = lw;
  return s;
}


}  // namespace rollerdyn::figures
