// The figures of one output folder (`rollerdyn plot`, `simulate --plot`, `report`), drawn with
// gnuplot through renderPlot() (src/report/Gnuplot.h) as <name>.png and <name>.svg:
//
//   crank_speed_vs_angle, crank_accel_vs_angle   ω_2, ε_2 against φ_2 mod 2π over the steady
//                                                window, one curve per revolution
//   crank_speed_vs_time, crank_accel_vs_time     the whole run; the steady window is marked
//   coupling_torque_vs_time                      torque transmitted by the coupling
//   motor_operating_point                        the Kloss curve M(ω) reduced to the crank axis
//                                                (scene motor data, Loveikin, Pochka, Romasevych (2018) eq. (37)) with the
//                                                run's (omega_motor, motor_torque) trajectory
//   motor_operating_point_steady                 the same, zoomed on the steady-state cycle
//   guide_reactions_vs_angle, rod_forces_vs_angle  N_front_j, N_rear_j and F_rod_j per cart
//                                                against φ_2 mod 2π, steady window
//   twist_phase_rate, twist_phase_rate_accel,    phase portraits of the coupling twist ψ over
//   twist_phase_accel                            the steady window (Loveikin, Pochka, Romasevych (2018) figs. 8-10):
//                                                (ψ, ψ'), (ψ', ψ''), (ψ, ψ'')
//   comparison_<quantity>                        multibody vs reduced (and the reduced model's
//                                                kinetostatic reactions) from comparison.csv
//
// A figure whose data are absent (no reactions.csv, rigid coupling, motor disabled, no scene
// for the Kloss curve, ...) is left out and a note says why, so a partial folder (an
// interrupted run, a compare folder) still gets every figure it can.
#pragma once

#include <string>
#include <vector>

#include "report/Gnuplot.h"
#include "report/OutputFolder.h"
#include "scene/Scene.h"

namespace rollerdyn {

struct FigurePlan {
  std::string name;     // file stem, e.g. "crank_speed_vs_angle"
  std::string caption;  // one sentence for the report
  PlotSpec spec;
};

struct FigureFile {
  std::string name, caption;
  std::string png, svg;  // paths written (empty if that format was not asked for)
};

struct FigureSet {
  std::vector<FigureFile> figures;
  std::vector<std::string> notes;  // figures left out and why, consistency warnings
};

// The steady-state window [t_begin, t_end] used for the angle plots: summary.json's
// steady_state.t_begin/t_end when present, else detected from the time series
// (src/analysis/SteadyState.h, 5 revolutions). found = false when neither gives one.
struct TimeWindow {
  double t_begin = 0, t_end = 0;
  bool found = false;
  std::string source;  // "summary.json" | "detected" | ""
};
TimeWindow steadyWindow(const OutputFolder& out);

// Crank angle folded into [0, 2π) with a NaN inserted wherever it wraps, so a curve drawn with
// PlotSeries::break_at_nonfinite restarts at each revolution instead of jumping back across the
// plot. `index` receives, for each output element, the source row (or -1 for an inserted NaN).
std::vector<double> foldedAngle(const std::vector<double>& phi, std::vector<long>* index);

// Every figure the folder's files allow (pure: draws nothing). `scene` may be null (then the
// motor operating point is drawn without its Kloss curve); `notes` receives the reasons for
// figures left out and warnings, e.g. when the scene's motor data do not reproduce the run's
// motor_torque (run made with --set motor.* that the plot did not get).
std::vector<FigurePlan> planRunFigures(const OutputFolder& out, const Scene* scene,
                                       std::vector<std::string>& notes);

struct FigureOptions {
  bool png = true, svg = true;
};

// Plans and draws the figures into `fig_dir` (created if missing). Throws std::runtime_error if
// gnuplot is missing or fails (the message names the figure).
FigureSet drawRunFigures(const OutputFolder& out, const Scene* scene, const std::string& fig_dir,
                         const FigureOptions& options = {});

// Whether `stem` is the name of a figure planRunFigures() can draw (the fixed names above or
// comparison_<quantity>): the files of ours that a new run may remove.
bool isRunFigureName(const std::string& stem);

// For the terminal: "12 figures in DIR/ (png and svg): name name ..." and one line per note.
std::string figureSetText(const FigureSet& set, const std::string& fig_dir);

}  // namespace rollerdyn
