// A CPU-time budget per sweep point (--point-budget S): the point runs in a fork()ed child
// process under a hard CPU limit (RLIMIT_CPU: SIGXCPU at the budget, rounded up to whole seconds
// as the kernel counts them, SIGKILL a second later), as `rollerdyn bench` does for its runs. An
// integrator stuck inside one output interval, which no progress check between rows can stop,
// thus becomes a `timeout` row instead of a hung sweep; a crash becomes an `error` row. The
// child sends its row back through a pipe as JSON (SweepProgress.h), so numbers are unchanged.
#pragma once

#include <string>
#include <vector>

#include "studies/Sweep.h"

namespace rollerdyn {

// runSweepPoint in a child process limited to budget_seconds of CPU [s] (> 0).
SweepPoint runSweepPointWithBudget(const SweepOptions& options, const std::vector<std::string>& texts,
                                   const std::vector<double>& values, double budget_seconds);

}  // namespace rollerdyn
