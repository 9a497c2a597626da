// Validation of the modal analysis (run by `rollerdyn validate`), each check against an
// independent reference:
//   1. constant inertia: frozen-angle frequency of both models = Dyomin's p0 (eq. (10)) through the
//      project's two-rotor closed form, ≤ 1e-8;
//   2. the Mathieu equation ẍ + (δ + ε cos t)x = 0 through the same Floquet code: transition
//      curves against δ = 1/4 ± ε/2 - ε²/8, δ = 1 - ε²/12, δ = 1 + 5ε²/12 - 0.2208ε⁴;
//   3. a damped constant-coefficient oscillator: multipliers = exp(λT), ≤ 1e-9;
//   4. multibody against reduced frozen-angle frequencies where both describe the same physics
//      (split rods, no guide friction), ≤ 1e-6;
//   5. a simulated run at a point the chart marks unstable grows by the predicted multiplier and
//      shows the predicted order; one at a stable point does not grow;
//   6. the papers' machine (Loveikin, Pochka, Romasevych (2018)): Floquet verdicts at the papers'
//      coupling (c = 200000 N·m/rad) with k = 0, 2000 and 8000 N·m·s/rad (a measurement, no claim).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace rollerdyn::modes {

struct ModesCheck {
  std::string name;
  std::string line;        // one line with the numbers, as printed
  bool is_claim = true;    // false: a measurement only
  bool pass = false;
};

struct ModesValidationResult {
  std::vector<ModesCheck> checks;
  nlohmann::json json;
  double cpu_seconds = 0;
  int failed() const;
};

ModesValidationResult runModesValidation(const std::string& model_dir,
                                         const std::function<void(const std::string&)>& log = {});

// Markdown page of the results.
std::string modesValidationMarkdown(const ModesValidationResult& r);

}  // namespace rollerdyn::modes
