// The output folder of a command, made ready before any computation: created (with its
// parents) and tested writable by creating and removing a probe file, so a bad --out fails at
// once instead of after a long simulation or sweep whose work would then be lost. Files that
// rollerdyn wrote in an earlier run and that the new run would contradict (figures drawn from
// other data, a report page of another run) are removed; no other file is ever touched.
#pragma once

#include <string>
#include <vector>

namespace rollerdyn {

// Which files of an earlier run are stale once this command writes into the folder.
enum class StaleOutputs {
  Keep,                 // none (sweep, bench, validate, cam-profile, chain: fixed file names, overwritten)
  RunFigures,           // figures/<name>.png|.svg of `plot` (plot, compare: drawn from the new data or not at all)
  RunFiguresAndReport,  // those, report.html and its screenshot report.png (simulate, report)
};

// Creates `dir` and checks that a file can be created in it; then removes the stale files.
// Returns the paths removed. Throws std::runtime_error naming `label` (e.g. "--out") and the
// folder, with the system's reason, when the folder cannot be created or written.
std::vector<std::string> prepareOutputDir(const std::string& dir, StaleOutputs stale = StaleOutputs::Keep,
                                          const std::string& label = "--out");

}  // namespace rollerdyn
