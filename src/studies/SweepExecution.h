// How the points of a sweep are computed: on the threads of this process, or over MPI ranks
// (SweepMpi.h); each point optionally in a CPU-limited child process (SweepPointBudget.h); every
// finished point saved to the progress file (SweepProgress.h) and, with --resume, the saved
// points taken from there instead of computed again.
#pragma once

#include <vector>

#include "studies/Sweep.h"
#include "studies/SweepDesigns.h"

namespace rollerdyn {

// The points of all designs, in design order. Sets result.output_rank (false on MPI workers,
// whose points are empty) and result.execution: ranks, points_per_rank (computed in this run by
// each rank), threads_per_rank, points_computed, points_resumed, wall_seconds, progress_file,
// point_budget_cpu_seconds, and under MPI dispatcher_busy_seconds (SweepMpi.h).
// Throws std::invalid_argument when --resume finds rows of a different sweep.
std::vector<SweepPoint> executeSweep(const SweepOptions& options, const SweepDesigns& designs, SweepResult& result);

}  // namespace rollerdyn
