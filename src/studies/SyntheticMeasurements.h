// Measurements made by the model itself, for the checks of `rollerdyn identify` (its tests and its
// validation claims): a run of a scene with known ("true") values, sampled on its output rows,
// plus Gaussian noise from a fixed seed (Box–Muller on SplitMix64, so every platform draws the
// same numbers; the std:: distributions are implementation-defined).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "analysis/RunResult.h"
#include "studies/Identify.h"
#include "studies/MeasuredData.h"

namespace rollerdyn {

// Standard normal draws from a 64-bit seed.
class GaussianNoise {
 public:
  explicit GaussianNoise(std::uint64_t seed) : state_(seed) {}
  double next();

 private:
  std::uint64_t bits();  // SplitMix64 (Steele, Lea and Flood 2014)
  std::uint64_t state_;
  double spare_ = 0;
  bool has_spare_ = false;
};

// The run of the scene file `scene` with `truth` (--set) over [0, t_end], rows every `step`, at
// integrator accuracy 1e-10 (far below any noise put on it), by `model` (multibody | reduced).
RunResult truthRun(const std::string& scene, std::vector<std::string> truth, double t_end, double step,
                   const std::string& model);

// Measurements of `columns` of the run's time series, each with Gaussian noise of standard
// deviation noise_fraction × the RMS value of that signal (a sensor's error relative to its
// reading level). Every row is kept, t = 0 too: the start from rest is measured.
MeasuredData measureRun(const RunResult& run, const std::vector<std::string>& columns, double noise_fraction,
                        std::uint64_t seed);

// The coupling case that identify's validation and its bench share: a start whose coupling is
// softer and less damped than balanced-4cart's own (200000 N·m/rad, 8000 N·m·s/rad), measured
// with Gaussian noise of 0.2 % of each signal's RMS value, both values identified from the scene's.
inline constexpr double kCouplingCaseStiffness = 150000.0;  // true coupling.stiffness [N·m/rad]
inline constexpr double kCouplingCaseDamping = 6000.0;      // true coupling.damping [N·m·s/rad]
inline constexpr double kCouplingCaseNoise = 0.002;         // noise, fraction of each signal's RMS value [-]

// `sets` and the case's true coupling values (--set), for truthRun().
std::vector<std::string> couplingCaseTruth(std::vector<std::string> sets);
// The identification of the case: coupling.stiffness in [2e4, 2e6] and coupling.damping in
// [500, 50000] free, `sets` applied to every run, by `model`, from the scene file `scene_path`.
IdentifyOptions couplingCaseFit(const std::string& scene_path, const std::string& model, std::vector<std::string> sets);

}  // namespace rollerdyn
