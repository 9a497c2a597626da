// The model runs of `rollerdyn identify` (Identify.h): the free keys and their map to scaled
// parameters in [0, 1], the runs of a candidate (each free key applied as --set, the run to a
// measured time, its output interpolated linearly onto the measured times) and the residuals.
// Internal to the identification (Identify.cpp, tests); the numerics are in IdentifyFit.h.
#pragma once

#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "report/SceneTable.h"
#include "studies/Identify.h"

namespace rollerdyn {
struct RunResult;
}

namespace rollerdyn::identify {

// One free key and its map to the scaled parameter u in [0, 1].
struct KeyMap {
  IdentifiedKey info;  // key, unit, bounds, log scale, start (the rest filled at the end)
  double toValue(double u) const;   // the key's value at u [key's unit]
  double toScaled(double x) const;  // u of the value x, clamped to [0, 1]
  double slope(double x) const;     // dx/du at x [key's unit]
};

// The free keys of `o` with their bounds (--bounds, else the schema's finite range), scales and
// starting values (the scene's `rows`, else the middle of the bounds). Throws std::invalid_argument
// for an unknown key, a key that is not a number, a key without bounds, bad bounds, a scene value
// outside them, a key given twice, --bounds of a key that is not free.
std::vector<KeyMap> resolveKeys(const IdentifyOptions& o, const std::vector<SceneParameterRow>& rows);

// The data with only the chosen signals (all when none are chosen); throws for one not measured.
MeasuredData selectSignals(const MeasuredData& data, const std::vector<std::string>& chosen);

// The model runs of one identification: the scene with the free keys applied, over a span, on the
// measured times.
class ModelRuns {
 public:
  ModelRuns(const IdentifyOptions& o, const MeasuredData& data, const SceneInput& input,
            const std::vector<KeyMap>& keys, double accuracy, double output_step)
      : o_(o), data_(data), input_(input), keys_(keys), accuracy_(accuracy), output_step_(output_step) {}

  struct Trial {
    bool ok = false;                         // the run reached the last measured time asked for
    std::string reason;                      // why not ok
    std::vector<std::vector<double>> model;  // per signal, at the first n measured times [signal's unit]
  };

  // A measured column the model does not write: bad input, thrown by run() and runAll().
  struct MissingColumn : std::invalid_argument {
    using std::invalid_argument::invalid_argument;
  };

  // The model at scaled point u on the first n measured times (at `accuracy`, 0: the runs' own).
  Trial run(const std::vector<double>& u, std::size_t n, double accuracy = 0);
  // Several points side by side on up to o.threads threads.
  std::vector<Trial> runAll(const std::vector<std::vector<double>>& points, std::size_t n);

  int runs() const { return runs_.load(); }      // runs started
  int failed() const { return failed_.load(); }  // runs that failed or ended early

 private:
  // The scene's overrides of a run at u: the base ones, the span to the n-th measured time, the
  // accuracy and output step, and the free keys' values.
  std::vector<std::string> overridesAt(const std::vector<double>& u, std::size_t n, double accuracy) const;
  // One run of the scene under these overrides: its signals on the first n measured times when it
  // reached the end, else (counted as failed) its status as the reason.
  Trial runScene(const std::vector<std::string>& overrides, std::size_t n);
  // The points' runs into out on `workers` threads, each taking the next point not yet taken; the
  // first MissingColumn is raised once all have stopped.
  void runOnThreads(const std::vector<std::vector<double>>& points, std::size_t n, std::size_t workers,
                    std::vector<Trial>& out);
  // Each measured signal of a finished run on the first n measured times (throws MissingColumn).
  std::vector<std::vector<double>> signalsOf(const RunResult& result, std::size_t n) const;

  const IdentifyOptions& o_;
  const MeasuredData& data_;
  const SceneInput& input_;
  const std::vector<KeyMap>& keys_;
  double accuracy_, output_step_;  // integrator accuracy [-] and output step [s] of the runs
  std::atomic<int> runs_{0}, failed_{0};
};

// Weighted residuals (model − data)/σ_s over the first n samples, signal after signal.
std::vector<double> weightedResiduals(const MeasuredData& d, const std::vector<std::vector<double>>& model,
                                      const std::vector<double>& sigma, std::size_t n);

// RMS of v[from, to); NaN when empty.
double rmsOf(const std::vector<double>& v, std::size_t from, std::size_t to);
// The median of v (v not empty).
double median(std::vector<double> v);
// "a, b, c".
std::string joinList(const std::vector<std::string>& v);

}  // namespace rollerdyn::identify
