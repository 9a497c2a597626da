// The reduced model's run with CVODE (Adams, or BDF for a stiff motor law) through the project's
// one CVODE driver (numerics/CvodeIntegrator.h), with the starting method's switching events.
#pragma once

#include "analysis/RunControl.h"
#include "analysis/RunResult.h"
#include "reduced/ReducedModel.h"

namespace rollerdyn {

// Integrates m over the scene's time span into res (its tables' columns already set).
RunResult runCvode(const ReducedModel& m, RunResult res, const RunControl& control);

}  // namespace rollerdyn
