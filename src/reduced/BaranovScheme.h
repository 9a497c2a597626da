// Baranov's fixed-step scheme in crank angle for the rigid drive (Loveikin and Pochka (2007)
// eq. (2)-(4), (10), (11)): the papers' own integrator of the one-mass model.
#pragma once

#include "analysis/RunControl.h"
#include "analysis/RunResult.h"
#include "reduced/ReducedModel.h"

namespace rollerdyn {

// Marches m from the scene's initial state in steps of reduced.baranov_step into res (its
// tables' columns already set). Throws std::invalid_argument where the scheme does not apply
// (an elastic coupling, a switching supply, a motor law with states).
RunResult runBaranov(const ReducedModel& m, RunResult res, const RunControl& control);

}  // namespace rollerdyn
