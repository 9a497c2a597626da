// Figures through gnuplot (Debian package gnuplot-nox): a well-kept plotting program with PNG
// (pngcairo) and SVG terminals, so rollerdyn draws nothing by hand and needs no Python stack.
// Every figure of plot, report, compare, bench, sweep and validation goes through renderPlot().
#pragma once

#include <string>
#include <vector>

namespace rollerdyn {

struct PlotSeries {
  std::string title;          // legend entry
  std::vector<double> x, y;   // same length
  std::string style = "lines";  // gnuplot style: "lines", "linespoints", "points"
};

struct PlotSpec {
  std::string title;
  std::string xlabel, ylabel;  // with units, e.g. "t [s]"
  bool logx = false, logy = false;
  std::vector<PlotSeries> series;
  int width = 960, height = 560;   // pixels (PNG) / points (SVG)
};

// True when a gnuplot executable is on PATH.
bool gnuplotAvailable();

// Writes <base>.png and/or <base>.svg. Each file is drawn to a temporary name and renamed, so a
// failed gnuplot run never leaves a partial figure. Throws std::runtime_error (naming the file)
// if gnuplot is missing or fails. Non-finite points are skipped (gnuplot would abort on them).
void renderPlot(const PlotSpec& spec, const std::string& base, bool png = true, bool svg = true);

// Heat map of z over a grid (rows follow y, columns follow x), same files and guarantees.
void renderHeatMap(const std::string& title, const std::string& xlabel, const std::string& ylabel,
                   const std::string& zlabel, const std::vector<double>& x, const std::vector<double>& y,
                   const std::vector<std::vector<double>>& z, const std::string& base, bool png = true,
                   bool svg = true);

}  // namespace rollerdyn
