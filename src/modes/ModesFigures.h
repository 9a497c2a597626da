// Figures of the modal analysis (gnuplot, report/Gnuplot.h: PNG and SVG) and its section of the
// HTML report.
#pragma once

#include <string>

#include "modes/ModalAnalysis.h"
#include "modes/OrderSpectrum.h"
#include "report/RunFigures.h"

namespace rollerdyn::modes {

// frozen_frequencies, campbell, stability_N: into `dir`. Without gnuplot: none, with a note.
FigureSet drawModesFigures(const ModesReport& r, const std::string& dir);
// order_spectrum: the spectra of a run's signals (coupling torque, then reactions by groups).
FigureSet drawSpectrumFigures(const OrderSpectrum& s, const std::string& dir);

// <h2>Torsional modes and stability</h2> with the tables and the figures embedded (PNG base64).
// `run_summary`: the summary.json of the run beside which the analysis was made; the section
// renders the run's stability verdict (n/a for a drive without a steady motion) and resonance
// warnings from it.
std::string modesHtmlSection(const ModesReport& r, const FigureSet& figures, const OrderSpectrum* spectrum,
                             const nlohmann::json& run_summary);

}  // namespace rollerdyn::modes
