// The flywheel that meets the target unevenness δ*, found by runs rather than estimated: the
// estimate (DriveSizing.h: J* = ΔA/(δ*·ω̄²), rigid drive, motor slip and coupling elasticity
// neglected) is the first guess, each run gives the δ it really yields, and the next guess follows
// δ ∝ J^(-p) through the last two runs. A generated machine showed why: 876 kg·m² proposed for
// δ* = 0.039 gave δ = 0.056 (1.44 δ*), its coupling's natural frequency with that flywheel falling
// near the fourth order of the crank speed, which no rigid estimate sees.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/Scene.h"

namespace rollerdyn {

struct FlywheelByRuns {
  bool found = false;         // a run met δ* within kAccept (inertia and delta are that run's)
  double inertia = 0;         // flywheel.inertia of the best run: the smallest that met δ*, else the
                              // last tried [kg·m² about its own shaft]
  double delta = 0;           // δ of that run [-]
  std::vector<std::pair<double, double>> tried;  // (flywheel.inertia, δ) of every run, in order
  std::string note;           // why the search stopped short, "" when found
};

// At most kMaxRuns runs of `model` ("multibody" | "reduced") on `scene` with flywheel.inertia set
// (at the scene's flywheel.location) and started at `omega_mean` (the run's steady mean crank
// speed: the flywheel is sized for steady running), beginning with `first_guess`. Met: δ within
// [kAccept·δ*, δ*]. Each run's δ is the summary's (steady state reached, crank turning).
// `inertia_now`: the drive's inertia at the crank in the scene's own run, its flywheel included
// (FlywheelSizing::inertia_effective) [kg·m²]: the guesses scale the whole inertia, not the flywheel alone.
// A run that turns without a steady state yet is repeated at 2 and 4 times simulation.t_end: a
// flywheel that adds inertia slows the settling of the coupling's mode (seed 738 of the harness:
// with 876 kg·m² the revolutions repeat from t = 1.2 s, and the five the window needs end past
// the scene's t_end = 4 s).
constexpr int kFlywheelMaxRuns = 5;
constexpr double kFlywheelAccept = 0.97;
constexpr double kFlywheelRunLengthening = 4.0;
FlywheelByRuns flywheelByRuns(const Scene& scene, const std::string& model, double first_guess, double omega_mean,
                              double target_delta, double inertia_now);

nlohmann::json toJson(const FlywheelByRuns& f);

}  // namespace rollerdyn
