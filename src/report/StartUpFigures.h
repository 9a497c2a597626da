// The start-up figures of one output folder (RunFigures.h), from the time series and
// summary.json's start_up (analysis/StartUp.h), each over the whole run with the steady window
// shaded and the switching times marked:
//   start_up_speed    crank and motor speed (reduced to the crank), the 95 % run-up level
//   start_up_torque   motor torque M·u·η and coupling torque at the crank axis
//   start_up_current  RMS stator phase current and the supply voltage ratio ×100 (laws with a current)
// Drawn where the start needs them (StartUpSummary.h, startUpHasOwnFigures): a static Kloss start
// direct on line is shown by the run's time figures already.
#pragma once

#include <string>
#include <vector>

#include "report/RunFigures.h"

namespace rollerdyn {

void planStartUpFigures(const OutputFolder& out, const TimeWindow& window, const std::string& scene_label,
                        std::vector<FigurePlan>& plans, std::vector<std::string>& notes);

// The names planStartUpFigures() can draw.
const std::vector<std::string>& startUpFigureNames();

}  // namespace rollerdyn
