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
  std::string style = "lines";  // gnuplot style: "lines", "linespoints", "points", "dots"
  // false (default): non-finite points are skipped and the line joins their neighbours.
  // true: a non-finite point breaks the line there, e.g. one curve per crank revolution when a
  // quantity is drawn against the crank angle mod 2π (put a NaN between revolutions).
  bool break_at_nonfinite = false;
  std::string color = "";       // gnuplot colour, e.g. "#1f77b4"; empty = gnuplot's sequence
  double line_width = 1.0;
  int dash = 0;                 // gnuplot dash type: 0 = solid (default), 2 = dashed, 3 = dotted
};

struct PlotSpec {
  std::string title;
  std::string xlabel, ylabel;  // with units, e.g. "t [s]"
  bool logx = false, logy = false;
  std::vector<PlotSeries> series;
  int width = 960, height = 560;   // pixels (PNG) / points (SVG)
  // Extra gnuplot commands run before `plot` (ranges, tics, arrows, key position), e.g.
  // "set xrange [0:2*pi]\nset xtics ('0' 0, 'π' pi, '2π' 2*pi)". Titles and labels use gnuplot's
  // enhanced text: "ω_{crank}" sets a subscript; write "\\_" for a literal underscore.
  std::string preamble;
};

// `text` for a title or label in enhanced mode with every "_" escaped, so a key path such as
// crank.offset_deg prints as written instead of starting a subscript. Only "_" is escaped: "^"
// and braces keep their enhanced meaning.
std::string escapeUnderscores(const std::string& text);

// True when a gnuplot executable is on PATH.
bool gnuplotAvailable();

// Writes <base>.png and/or <base>.svg. Each file is drawn to a temporary name and renamed, so a
// failed gnuplot run never leaves a partial figure. Throws std::runtime_error (naming the file)
// if gnuplot is missing or fails. Non-finite points are skipped (gnuplot would abort on them).
void renderPlot(const PlotSpec& spec, const std::string& base, bool png = true, bool svg = true);

// One figure to draw: the gnuplot commands of renderPlot() or renderHeatMap() and its files.
struct PlotJob {
  std::string script;   // commands that draw the figure (terminal and output are set around them)
  int width = 960, height = 560;
  std::string base;     // <base>.png and/or <base>.svg
  bool png = true, svg = true;
};
PlotJob plotJob(const PlotSpec& spec, const std::string& base, bool png = true, bool svg = true);
PlotJob heatMapJob(const std::string& title, const std::string& xlabel, const std::string& ylabel,
                   const std::string& zlabel, const std::vector<double>& x, const std::vector<double>& y,
                   const std::vector<std::vector<double>>& z, const std::string& base, bool png = true,
                   bool svg = true, const std::string& preamble = "");

// Draws every job, the same files as renderPlot() one by one, in fewer gnuplot starts: the jobs are
// shared among up to `processes` gnuplot processes running at once (0: one per processor), each
// drawing its share in one run with `reset session` between the figures (each figure drawn as
// by a fresh gnuplot). Each file is drawn to a temporary name and renamed. When a process fails,
// its figures are drawn again one process each, so the error names the figure that fails
// (std::runtime_error, as renderPlot()).
void renderPlots(const std::vector<PlotJob>& jobs, int processes = 0);

// Heat map of z over a grid (rows follow y, columns follow x), same files and guarantees.
// `preamble`: extra gnuplot commands run before `plot` (tics, a marked point, lines), as PlotSpec's.
void renderHeatMap(const std::string& title, const std::string& xlabel, const std::string& ylabel,
                   const std::string& zlabel, const std::vector<double>& x, const std::vector<double>& y,
                   const std::vector<std::vector<double>>& z, const std::string& base, bool png = true,
                   bool svg = true, const std::string& preamble = "");

}  // namespace rollerdyn
