// How a run of the reduced model fills its tables, whichever integrator produced the state: the
// column lists, one row of each table from a model evaluation, and the stop rules every run
// shares (analysis/RunRecorder.h) applied to it. Used by its CVODE run and Baranov's scheme.
#pragma once

#include <vector>

#include "analysis/RunRecorder.h"
#include "analysis/RunResult.h"
#include "reduced/ReducedModel.h"

namespace rollerdyn {

// The reducer's losses of a run [J]: the integrated state under power_flow; under the papers'
// constant η, (1/η − 1) times the work passed on (no state).
double reducerLossesOf(const ReducedModel& m, double motor_work, double integrated);
// The time series' and (with simulation.reactions) the reactions' column names.
void setupTables(const ReducedModel& m, RunResult& res);
// One output row of both tables from an evaluation (its eps/coupling fields may have been
// replaced by the Baranov scheme's own values).
void appendRows(const ReducedModel& m, double t, const ModelEvaluation& e, RunResult& res);
// Appends the output rows of evaluation e at time t and applies the stop rules; false when the
// run ends there. cart_speeds: storage for the carts' v.
bool recordRows(const ReducedModel& m, double t, const ModelEvaluation& e, const SupplyPhase& phase,
                RunRecorder& recorder, RunResult& res, std::vector<double>& cart_speeds);

}  // namespace rollerdyn
