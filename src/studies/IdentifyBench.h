// `rollerdyn bench --study identify`: what one identification costs. The cases of the identify
// validation (a start of the scene with a softer, less damped coupling than its own, "measured"
// with 0.2 % Gaussian noise, both coupling values identified from the scene's): the reduced model
// on crank and motor speed, and the multibody model with the catalogue motor (motor.model: circuit)
// on crank speed, motor speed and stator current. Each timed `repeats` times (fixed noise seed, so
// every repetition does the same runs); medians of wall and process CPU time, the runs and
// iterations, and what came out (estimates and their σ).
#pragma once

#include <atomic>
#include <functional>
#include <string>
#include <vector>

namespace rollerdyn {

struct IdentifyBenchRow {
  std::string name;          // the case, in words
  std::string model;         // multibody | reduced
  std::string signals;       // the measured columns, comma-separated
  int samples = 0;           // measured times
  int repeats = 0;           // timed repetitions
  double wall = 0;           // median wall time of one identification [s]
  double cpu = 0;            // median CPU time of this process over one identification (all threads) [s]
  int runs = 0;              // model runs of one identification
  int iterations = 0;        // Levenberg–Marquardt iterations
  bool converged = false;
  double c = 0, c_std = 0;   // coupling.stiffness estimate and its standard uncertainty [N·m/rad]
  double k = 0, k_std = 0;   // coupling.damping estimate and its standard uncertainty [N·m·s/rad]
  double c_true = 0, k_true = 0;  // the values the measurements were made with
};

// `scene_path`: the scene the cases start from (its coupling must be elastic), with `overrides`
// (--set) applied before each case's own values.
std::vector<IdentifyBenchRow> runIdentifyBench(const std::string& scene_path, const std::vector<std::string>& overrides,
                                               int repeats,
                                               const std::atomic<bool>* interrupt,
                                               const std::function<void(const std::string&)>& log);

// identify.csv and identify.md in `out_dir`; returns the paths written.
std::vector<std::string> writeIdentifyBench(const std::string& out_dir, const std::string& scene_name,
                                            const std::vector<IdentifyBenchRow>& rows, const std::string& machine);

}  // namespace rollerdyn
