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
std::string modesHtmlSection(const ModesReport& r, const FigureSet& figures, const OrderSpectrum* spectrum);

}  // namespace rollerdyn::modes
