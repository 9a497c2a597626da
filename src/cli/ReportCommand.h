// `rollerdyn report` with its phases timed (`rollerdyn bench --study setup`).
#pragma once

#include <string>

#include "cli/Commands.h"
#include "io/PhaseClock.h"

namespace rollerdyn::cli {

// runReport() marking its phases on `clock` (null: not timed); `quiet`: nothing on stdout.
int runReport(const SceneArgs& args, const std::string& out_dir, PhaseClock* clock, bool quiet);

}  // namespace rollerdyn::cli
