// The findings printed beside each paper's table in the validation report: every sentence is a
// comparison made on the numbers of that run (our sweep, the published table, the sensitivity
// rows, the scene's inputs), stated with those numbers and with its outcome (Finding::Verdict),
// so a claim that the run does not support is printed as failed.
#pragma once

#include <vector>

#include "compare/ValidationSuite.h"
#include "scene/Scene.h"

namespace rollerdyn::validation {

// Loveikin and Pochka (2007): two carts on opposite sides, δ/H/k_p against the crank offset Δφ.
std::vector<Finding> findingsLoveikin2007(const PaperSweep& p, const std::vector<SensitivityRow>& sensitivity);

// The energy-balanced drive paper: three carts at 120°, δ/H/k_p against the flywheel inertia.
// `scene`: the shipped scene (reducer ratio for the flywheel-location argument).
std::vector<Finding> findingsEnergyBalanced(const PaperSweep& p, const std::vector<SensitivityRow>& sensitivity,
                                            const Scene& scene);

// Loveikin, Pochka, Romasevych (2018) Table 1: coupling swings against Δφ and the damping k.
// `scene`: the shipped scene (roller forces, crank radius, motor, reducer).
std::vector<Finding> findingsLoveikin2018(const PaperSweep& p, const std::vector<SensitivityRow>& sensitivity,
                                          const Scene& scene);

}  // namespace rollerdyn::validation
