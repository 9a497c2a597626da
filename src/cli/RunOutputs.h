// What `simulate` and `report` share around one run: the multibody model with the console's
// progress line, and the run's files in its output folder.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "analysis/RunResult.h"
#include "modes/RunModes.h"
#include "scene/Scene.h"
#include "studies/RunSummary.h"

namespace rollerdyn::cli {

// `model` ("multibody" or "reduced") on `scene`, printing its progress and stopping at the next
// output row on Ctrl-C (g_interrupted, Commands.h).
RunResult runWithProgress(const Scene& scene, const std::string& model);

// The modal analysis beside the run (`simulate --modes`, `report`): modes/RunModes.h.
using modes::analyseRunModes;
using modes::RunModal;

// Summarizes the run (studies/RunSummary.h, the summary every caller of a run shares) and writes
// its files into out_dir: the tables, summary.json with the scene file's absolute path so `plot
// DIR` finds it from anywhere, and with `modal` the modal analysis' files (modes.json, frozen.csv,
// campbell.csv, stability.csv, spectrum.csv). Prints the warnings on stderr: the load's and the
// scene's plausibility, the two-mass resonance check (Dyomin (two rotors) eq. (10)) as the first
// estimate, then the verdict of the modal analysis. Returns the summary. `overrides`: the user's
// --set options, kept in summary.json ("overrides") so that commands the console suggests (the
// flywheel search) repeat them.
nlohmann::json writeRunOutputs(const Scene& scene, const RunResult& run, const std::string& scene_path,
                               const std::string& out_dir, const std::vector<std::string>& overrides = {},
                               const RunModal* modal = nullptr);

// Exit codes of a run's command: 0 the crank turns; 4 the drive stalls or rocks (a valid run of a
// drive that does not work); 3 the run did not complete for another reason (numerical failure,
// interrupted).
inline constexpr int kExitDriveDoesNotTurn = 4;
inline constexpr int kExitRunFailed = 3;
// `signoff`: the sheet written as JSON and HTML, but no PDF (Chromium missing or failing).
inline constexpr int kExitSignOffWithoutPdf = 5;
int runExitCode(const RunResult& run, const nlohmann::json& summary);

}  // namespace rollerdyn::cli
