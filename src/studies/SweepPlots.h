// Figures of a sweep: each metric against the parameter (one parameter) or a heat map over the
// grid (two parameters). Only points where the crank turns at steady state set the scale:
//   - turning, steady state reached: drawn normally (line, coloured cell);
//   - turning, steady state not reached: separate orange markers / a hatched coloured cell;
//   - rocking, stalled or failed: no value drawn; grey hatched bands / grey hatched cells.
// Heat-map cells end halfway to the neighbouring grid value and at the first and last grid
// values, so no cell runs past the grid (e.g. to a negative damping).
#pragma once

#include <string>
#include <vector>

#include "studies/Sweep.h"

namespace rollerdyn {

// How a sweep point is drawn.
enum class SweepPointClass { Steady, Unsteady, NoValue };
SweepPointClass classifySweepPoint(const SweepPoint& p);

// Cell edges along one axis for grid values `v` (any order): edges[k] = {lo, hi} of value k.
std::vector<std::pair<double, double>> heatMapCellEdges(const std::vector<double>& v);

// Draws the plots into out_dir (plot_<metric> / heatmap_<metric>, PNG and SVG); returns the PNG
// paths. `note` says why nothing was drawn (more than two parameters, words, no gnuplot).
std::vector<std::string> drawSweepPlots(const SweepOptions& options, const SweepResult& result,
                                        const std::string& out_dir, std::string* note);

// Axis label of a scene key: "key [unit]" with the schema unit, the bare key when the key has no
// unit or is dimensionless ("-").
std::string sweepParamLabel(const std::string& key);
// Label of a sweep metric with its unit and, for the papers' coefficients, the equation.
std::string sweepMetricLabel(const std::string& metric);
// Unit of a sweep metric in the ASCII CSV convention (io/Table.h), "-" when dimensionless.
std::string sweepMetricUnit(const std::string& metric);

}  // namespace rollerdyn
