// The modal analysis beside a simulated run (`simulate --modes`, `report`) and the resonance
// verdict every run's summary carries.
//
// Resonance verdict of a run (writeResonanceVerdict): the two-mass check (Dyomin (two rotors)
// eq. (10) with the mean crank-side inertia, the check rollerdyn had first) stays as the first,
// cheap estimate and its warnings are labelled so; the verdict then rests on the analysis of the
// drive linearized about its steady motion (frozen-angle band of the coupling mode against the
// layout's excitation orders, and the Floquet multipliers): its warnings follow, and when the first
// estimate warned but the analysis does not, the summary says why.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/RunResult.h"
#include "modes/ModalAnalysis.h"
#include "modes/OrderSpectrum.h"
#include "scene/Scene.h"

namespace rollerdyn::modes {

// `first_estimate`: the warnings the two-mass check appended to summary["warnings"]. Relabels
// them in place, adds summary["resonance"]["method"], summary["resonance_modal"] and the
// analysis' warnings. `analysis`: a full analysis already made for this scene, or nullptr (a
// light one is made: reduced model, no Campbell or charts; tens of milliseconds). Returns the
// lines to print, in order.
std::vector<std::string> writeResonanceVerdict(const Scene& scene, nlohmann::json& summary,
                                               const std::vector<std::string>& first_estimate,
                                               const ModesReport* analysis = nullptr);

// Order spectrum of a run's coupling and motor torque and of every joint reaction over its steady
// window (the scene's simulation.steady_window_revolutions).
OrderSpectrum runSpectrum(const Scene& scene, const RunResult& run);

// The modal analysis of a scene beside one of its runs (`simulate --modes`, `report`, Python's
// simulate(modes=True)): the analysis and the run's order spectrum.
struct RunModal {
  ModesReport report;
  OrderSpectrum spectrum;
};
// `charts`: also the stability charts, coarse (12 stiffnesses x 8 speeds or dampings), as the
// report shows them.
RunModal analyseRunModes(const Scene& scene, const RunResult& run, bool charts);

// Puts the analysis under summary["modes"] (as modes.json) and the spectrum's strongest orders
// under summary["order_spectrum"].
void addRunModes(const RunModal& modal, nlohmann::json& summary);

// Writes modes.json, frozen.csv, campbell.csv, stability.csv (when charts were made) and
// spectrum.csv (when the spectrum was computed) into out_dir.
void writeRunModesFiles(const std::string& out_dir, const RunModal& modal);

}  // namespace rollerdyn::modes
