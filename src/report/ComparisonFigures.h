// The comparison figures of one output folder (RunFigures.h): comparison_<quantity>, the
// multibody model against the reduced model (and the reduced model's kinetostatic reactions) for
// every <quantity>_multibody column of comparison.csv (`rollerdyn compare`), over the steady
// window or else the last quarter of the compared span. Left out, with a note, when
// comparison.csv comes from another run than the folder's timeseries.csv.
#pragma once

#include <string>
#include <vector>

#include "report/RunFigures.h"

namespace rollerdyn {

void planComparisonFigures(const OutputFolder& out, const TimeWindow& window, const std::string& scene_label,
                           std::vector<FigurePlan>& plans, std::vector<std::string>& notes);

}  // namespace rollerdyn
