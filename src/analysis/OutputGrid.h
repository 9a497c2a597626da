// The output time grid both models write their rows on, so their tables line up row by row.
#pragma once

#include <vector>

#include "scene/Scene.h"

namespace rollerdyn {

// 0, h, 2h, ... up to t_end (h = simulation.output_step), plus t_end itself when h does not
// divide it [s]. Throws std::invalid_argument unless t_end > 0 and output_step > 0.
std::vector<double> outputTimes(const SimulationSettings& settings);

}  // namespace rollerdyn
