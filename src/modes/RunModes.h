// The modal analysis beside a simulated run (`simulate --modes`, `report`). The run's resonance and
// stability verdict rests on it and is made in studies/ResonanceCheck.h.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/RunResult.h"
#include "modes/ModalAnalysis.h"
#include "modes/OrderSpectrum.h"
#include "scene/Scene.h"

namespace rollerdyn::modes {

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
// report shows them. `clock`: times the analysis' phases (bench); null: not timed.
RunModal analyseRunModes(const Scene& scene, const RunResult& run, bool charts, PhaseClock* clock = nullptr);

// The reason the run's stability verdict is not applicable (summary["stability"], made by the run's
// verdict: a drive that does not turn has no steady motion), or "" when it applies.
std::string runStabilityNotApplicable(const nlohmann::json& summary);

// Puts the analysis under summary["modes"] (as modes.json) and the spectrum's strongest orders
// under summary["order_spectrum"]. Call after the run's verdict: where it says the stability is
// not applicable, the analysis' steady-motion verdict is replaced by that and its warnings dropped.
void addRunModes(const RunModal& modal, nlohmann::json& summary);

// Writes modes.json (`modes_json`, the summary's "modes"; empty: the analysis' own), frozen.csv,
// campbell.csv, stability.csv (when charts were made) and spectrum.csv (when the spectrum was
// computed) into out_dir.
void writeRunModesFiles(const std::string& out_dir, const RunModal& modal, const nlohmann::json& modes_json = {});

}  // namespace rollerdyn::modes
