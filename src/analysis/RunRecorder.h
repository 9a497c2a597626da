// How every run ends: one recorder for every model and integrator (the multibody model in both
// formulations, the reduced model with CVODE or Baranov's scheme), so that the same scene ends
// at the same time for the same reason in each of them, whatever loop produced its rows.
//
// Each output row is appended to the run's tables and then checked, in this order:
//  1. a non-finite value in the row: a numerical failure;
//  2. the drive is hopeless (StallDetector.h: held, driven backwards, rocking without gain),
//     judged only while the motor gets its rated supply (a star stage or a ramp may be slow);
//  3. a soft starter that gave up (motor/Supply.h: tripped): a failed start;
//  4. the machine came to rest with the motor off (RestDetector.h);
//  5. the caller stopped the run (RunControl::interrupt, after its progress report), from the
//     first row the integration produced on: the first row is the scene's initial state, no
//     progress yet (a Ctrl-C before the first step stops at the next row, as in every model).
// The first that applies ends the run: complete = false and the status line says why. Causes the
// model itself finds (an integrator failure, a guide-friction loop without solution) end the run
// through fail().
#pragma once

#include <string>
#include <vector>

#include "analysis/RestDetector.h"
#include "analysis/RunControl.h"
#include "analysis/RunResult.h"
#include "analysis/StallDetector.h"

namespace rollerdyn {

class Supply;
struct Scene;
struct SupplyPhase;

// What the stop rules read of one output row.
struct RowMotion {
  double phi_crank = 0;    // crank angle [rad]
  double omega_crank = 0;  // crank speed [rad/s]
  double omega_motor = 0;  // motor speed reduced to the crank axis [rad/s]
  const std::vector<double>* cart_speeds = nullptr;  // v_j of every cart [m/s]
  const SupplyPhase* phase = nullptr;  // the supply's phase at the row; nullptr: no motor, or a
                                       // supply that never switches (always rated, never trips)
};

class RunRecorder {
 public:
  // supply: the motor's starting method (nullptr without a motor); prescribed_crank_speed: the
  // crank's speed is imposed (then the machine cannot come to rest). The run's status line and
  // tables live in `run`, which must outlive the recorder.
  RunRecorder(const Scene& scene, const Supply* supply, bool prescribed_crank_speed, RunResult& run,
              const RunControl& control = {});

  // Appends the row to the time series (and `reactions`, when given, to the reactions table),
  // then applies the stop rules. False when the run ends at this row.
  bool record(double t, std::vector<double> timeseries, std::vector<double>* reactions, const RowMotion& motion);
  // Applies the stop rules to a row already appended (for loops that fill the tables
  // themselves). False when the run ends at this row.
  bool check(double t, bool row_finite, const RowMotion& motion);
  // Ends the run for a cause the model found itself: complete = false, status = `status`.
  void fail(std::string status);
  bool ended() const { return !run_.stats.complete; }

 private:
  bool end(std::string status);

  const Supply* supply_;
  RunResult& run_;
  RunControl control_;
  double t_end_;
  bool initial_row_ = true;  // the next row checked is the run's first (its initial state)
  StallDetector stall_;
  RestDetector rest_;
};

}  // namespace rollerdyn
