// The modal analysis' section of the HTML report: its key figures, Campbell crossings,
// separation margins, the run's order spectrum and the figures embedded.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "modes/ModalAnalysis.h"
#include "modes/OrderSpectrum.h"
#include "report/RunFigures.h"

namespace rollerdyn::modes {

// <h2>Torsional modes and stability</h2> with the tables and the figures embedded (PNG base64).
// `run_summary`: the summary.json of the run beside which the analysis was made; the section
// renders the run's stability verdict (n/a for a drive without a steady motion) and resonance
// warnings from it.
std::string modesHtmlSection(const ModesReport& r, const FigureSet& figures, const OrderSpectrum* spectrum,
                             const nlohmann::json& run_summary);

}  // namespace rollerdyn::modes
