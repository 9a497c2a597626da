// What every caller of one run writes or returns about it, in one place, so that `simulate`,
// `report`, the sweep points and the Python interface give the same summary.json and files:
//   - the summary (analysis/Summary.h) with the load at the start that explains a stall
//     (StartLoad.h), the resonance warnings of Dyomin (two rotors) eq. (10) (ResonanceCheck.h)
//     and the scene file's absolute path, so `rollerdyn plot DIR` finds it from any folder;
//   - the run's files in an output folder: timeseries.csv, reactions.csv (when computed) and
//     summary.json, each written to a temporary name and renamed.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/RunResult.h"
#include "scene/Scene.h"

namespace rollerdyn {

// summary.json of `run` on `scene`. `scene_file`: the scene file as given (made absolute and
// normalised in `scene_path`), or "" for a scene that is not a file (then scene_path is null).
// `warnings` (may be null) receives the resonance warnings added, to print on a terminal.
nlohmann::json summarizeRun(const Scene& scene, const RunResult& run, const std::string& scene_file,
                            std::vector<std::string>* warnings = nullptr);

// Writes the run's tables and `summary` into `out_dir` (which must exist), atomically.
void writeRunFiles(const std::string& out_dir, const RunResult& run, const nlohmann::json& summary);

}  // namespace rollerdyn
