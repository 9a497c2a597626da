// What `rollerdyn identify` writes and prints, all rendered from one IdentifyResult (Identify.h):
// identify.json, the figures fit_<signal> (data and model against t) and residual_<signal>, and
// the console table.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "studies/Identify.h"

namespace rollerdyn {

// identify.json without its figures: scene, model, data file, overrides, keys (value, std,
// relative_std, bounds, start, log_scale, at_bound), correlation (keys and matrix), signals (σ,
// where it came from, RMS residual of the fit and of the held-out part, the integration's own
// error, samples), warnings, the
// fit's statistics (N, RSS, σ̂², condition, weakest direction) and convergence (converged, reason,
// iterations, runs, failed runs, accuracy, output step, wall time).
nlohmann::json identifyJson(const IdentifyOptions& options, const IdentifyResult& result);

// identify.json and the figures. Returns the files written; `plot_note` receives why figures are
// missing ("" when all were drawn).
std::vector<std::string> writeIdentifyOutputs(const IdentifyOptions& options, const IdentifyResult& result,
                                              const std::string& out_dir, std::string* plot_note = nullptr);

// The console text: a table of the keys (estimate ± std, relative std, start, bounds), one of the
// signals (σ, RMS residual fitted and held out), the correlations above 0.5, the warnings and
// the convergence line.
std::string describeIdentify(const IdentifyResult& result);

}  // namespace rollerdyn
