// Figures of the modal analysis (gnuplot, report/Gnuplot.h: PNG and SVG); its section of the HTML
// report is modes/ModesHtml.h.
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

}  // namespace rollerdyn::modes
