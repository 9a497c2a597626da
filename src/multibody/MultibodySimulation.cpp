#include "multibody/MultibodySimulation.h"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <sstream>
#include <stdexcept>

#include "analysis/CrankSpeedExtrema.h"
#include "analysis/CrankshaftBearings.h"
#include "analysis/OutputGrid.h"
#include "analysis/RunRecorder.h"
#include "multibody/IntegratorFactory.h"
#include "multibody/MinimalSimulation.h"
#include "multibody/MultibodyModel.h"
#include "multibody/MotorForce.h"
#include "multibody/StopRuleMotion.h"

namespace rollerdyn {
namespace {

// The state at time t inside the step from (t0, y0, ẏ0) to `end` by cubic Hermite
// interpolation of y (Simbody's own interpolant), with prescribed motion applied and projected
// onto the constraints to `tol`, written into `sample` and realized to Velocity.
void sampleWithinStep(const SimTK::System& system, double t0, const SimTK::Vector& y0,
                      const SimTK::Vector& ydot0, const SimTK::State& end, double t, double tol,
                      SimTK::State& sample) {
  const double h = end.getTime() - t0, th = (t - t0) / h;
  const double h00 = (1 + 2 * th) * (1 - th) * (1 - th), h10 = th * (1 - th) * (1 - th);
  const double h01 = th * th * (3 - 2 * th), h11 = th * th * (th - 1);
  sample.updY() = h00 * y0 + (h10 * h) * ydot0 + h01 * end.getY() + (h11 * h) * end.getYDot();
  sample.updTime() = t;
  system.realize(sample, SimTK::Stage::Time);
  system.prescribeQ(sample);
  system.realize(sample, SimTK::Stage::Position);
  system.projectQ(sample, tol);
  system.prescribeU(sample);
  system.realize(sample, SimTK::Stage::Velocity);
  system.projectU(sample, tol);
}

// Where, inside the step from (t0, y0, ẏ0) to `end`, the rotor speed first reaches `trigger`
// (it is below at t0 and not below at the end): bisection on the same cubic Hermite interpolant
// Simbody uses for its own event localization, to a time tolerance of 1e-12 of the step's scale.
// Leaves the state at that time in `sample`.
double locateSpeedTrigger(const MultibodyModel& model, double t0, const SimTK::Vector& y0, const SimTK::Vector& ydot0,
                          const SimTK::State& end, double trigger, double tol, SimTK::State& sample) {
  const MotorForce& motor = *model.motorForce();
  double lo = t0, hi = end.getTime();
  while (hi - lo > 1e-12 * std::max(1.0, hi)) {
    const double mid = 0.5 * (lo + hi);
    sampleWithinStep(model.system(), t0, y0, ydot0, end, mid, tol, sample);
    (motor.rotorSpeed(sample) < trigger ? lo : hi) = mid;
  }
  sampleWithinStep(model.system(), t0, y0, ydot0, end, hi, tol, sample);
  return hi;
}

// simulation.constraint_tolerance bounds the LARGEST position-constraint error, but Simbody
// projects when the RMS of its m constraint errors exceeds its tolerance; the largest error
// can then be √m times the RMS (seen: 1.7e-6 at a 1e-6 tolerance on recuperative-2cart), so
// Simbody gets tol/√m.
double simbodyConstraintTolerance(const Scene& sc, const SimTK::State& s0) {
  const int n_constraint_eqs = std::max(1, s0.getNQErr());
  return sc.simulation.constraint_tolerance / std::sqrt(double(n_constraint_eqs));
}

// The run's tables and descriptions before the first row.
RunResult emptyRun(const MultibodyModel& model) {
  const Scene& sc = model.scene();
  RunResult run;
  run.model = "multibody";
  run.integrator = sc.simulation.integrator;
  run.effects = sc.effects();
  run.guide_normals = model.guideNormalsDescription();
  run.timeseries.columns = model.timeseriesColumns();
  if (sc.simulation.reactions) run.reactions.columns = model.reactionColumns();
  return run;
}

// Where a step began: the interpolant's left end.
struct StepStart {
  double t = 0;
  SimTK::Vector y, ydot;
  void at(const SimTK::State& s) {
    t = s.getTime();
    y = s.getY();
    ydot = s.getYDot();
  }
};

// Switching events of the starting method (motor/Supply.h): a timed one is the integrator's
// advance limit, so no step crosses it; a speed-triggered one (the star-delta changeover by
// speed) is found after the step that crosses it, on the step's interpolant, and the run goes
// on from there. At an event the motor element maps its states (MotorForce::applyDueEvents) and
// the integrator starts afresh from the switched state. Rows at an event's time show the state
// after it (as in the reduced model).
class SupplyEvents {
 public:
  SupplyEvents(const MultibodyModel& model, double t_end, double constraint_tol)
      : model_(model), motor_(model.motorForce()), active_(motor_ && !motor_->supply().constant()),
        t_end_(t_end), tol_(constraint_tol) {}

  // The next timed event and the trigger speed of the supply's phase in s (after a (re)start).
  void arm(const SimTK::State& s) {
    t_stop_ = active_ ? std::min(t_end_, motor_->supply().nextEventTime(motor_->phase(s))) : t_end_;
    trigger_ = active_ ? motor_->supply().triggerSpeed(motor_->phase(s)) : std::nan("");
  }
  double stopTime() const { return t_stop_; }  // the integrator's advance limit [s]

  // Whether the step from `from` to `advanced` holds an event: the speed trigger crossed inside it
  // (t_event is moved back to the crossing), or the step ended at a timed event. `switched` then
  // holds the state at the event, not yet switched.
  bool find(const StepStart& from, const SimTK::State& advanced, SimTK::State& switched, double& t_event) {
    by_speed_ = false;
    if (!std::isnan(trigger_) && motor_->rotorSpeed(advanced) >= trigger_) {
      switched = advanced;
      t_event = locateSpeedTrigger(model_, from.t, from.y, from.ydot, advanced, trigger_, tol_, switched);
      return by_speed_ = true;
    }
    if (active_ && t_stop_ < t_end_ && t_event >= t_stop_ - 1e-12 * std::max(1.0, t_stop_)) {
      switched = advanced;
      model_.system().realize(switched, SimTK::Stage::Velocity);  // a State copy starts with its cache invalid
      return true;
    }
    return false;
  }
  // Switches the state at the event found last (the motor element maps its states).
  void apply(SimTK::State& switched) const { motor_->applyDueEvents(switched, by_speed_); }

 private:
  const MultibodyModel& model_;
  const MotorForce* motor_;
  bool active_;
  double t_end_, tol_;
  double t_stop_ = 0, trigger_ = std::nan("");
  bool by_speed_ = false;
};

// The integrator's counts over every restart (initialize() starts them afresh).
struct IntegratorCounts {
  long steps = 0, realizations = 0, rejected = 0;  // counted before the last restart at an event
  void keep(const SimTK::Integrator& integ) {
    steps += integ.getNumStepsTaken();
    rejected += integ.getNumErrorTestFailures();
    realizations += integ.getNumRealizations();
  }
  void write(const SimTK::Integrator& integ, RunStats& stats) const {
    stats.steps = steps + integ.getNumStepsTaken();
    stats.error_test_failures = rejected + integ.getNumErrorTestFailures();
    stats.realizations = realizations + integ.getNumRealizations();
  }
};

// The output rows: motion and reactions of a realized state, then the stop rules every run shares
// (analysis/RunRecorder.h).
class OutputRows {
 public:
  OutputRows(const MultibodyModel& model, RunRecorder& recorder, RunStats& stats)
      : model_(model), recorder_(recorder), stats_(stats), reactions_(model.scene().simulation.reactions),
        cart_speeds_(model.carts().size()) {}

  // The row of state s at output time t; false when the run ends there.
  bool record(const SimTK::State& s, double t) {
    model_.system().realize(s, SimTK::Stage::Acceleration);
    model_.observeMotion(s, s.getUDot(), ts_row_);
    if (reactions_) model_.observeReactions(s, re_row_);
    stats_.constraint_error_max = std::max(stats_.constraint_error_max, model_.constraintError(s));
    return recorder_.record(t, ts_row_, reactions_ ? &re_row_ : nullptr, stopRuleMotion(model_, s, cart_speeds_, phase_));
  }

 private:
  const MultibodyModel& model_;
  RunRecorder& recorder_;
  RunStats& stats_;
  bool reactions_;
  std::vector<double> ts_row_, re_row_, cart_speeds_;
  SupplyPhase phase_;
};

// The algebraic guide-friction law needs the guide reactions before the accelerations, which only
// the minimal formulation has.
void refuseAlgebraicFriction(const MultibodyModel& model) {
  if (model.hasGuideFriction() && !model.hasFrictionLagStates())
    throw std::invalid_argument(
        "multibody model: loads.guide_friction.normal_force = algebraic needs simulation.formulation = minimal "
        "(the constrained formulation knows the guide reactions only after Simbody's constrained solve); "
        "use loads.guide_friction.normal_force = lagged");
}

// The stepping of a constrained run: Simbody's integrator to its next stop, the output rows inside
// each step from the step's interpolant, a restart at each supply event.
// Output rows come from our own cubic Hermite interpolation between the integrator's steps,
// into one State we keep (`sample_`), rather than from Simbody's report times: Simbody copies
// the whole State (every cache entry, ~640k instructions here) for each interpolated report,
// which cost ~10 % of a balanced-4cart run. The interpolant is the one Simbody uses
// (third order, from y and ẏ at both ends of the step); the sample is then projected onto the
// constraints like Simbody's reports, so rows satisfy them to the same tolerance.
class ConstrainedStepping {
 public:
  ConstrainedStepping(const MultibodyModel& model, SimTK::Integrator& integ, double constraint_tol, OutputRows& rows,
                      RunRecorder& recorder)
      : model_(model), integ_(integ), tol_(constraint_tol), rows_(rows), recorder_(recorder),
        times_(outputTimes(model.scene().simulation)),  // the grid the reduced model uses
        t_end_(model.scene().simulation.t_end), events_(model, t_end_, constraint_tol), sample_(integ.getState()) {}

  // The first row, then steps until t_end or a stop.
  void runToEnd() {
    stop_ = !rows_.record(integ_.getState(), integ_.getTime());
    last_row_ = &integ_.getState();
    from_.at(integ_.getState());
    extrema_.restart(from_.t, model_.crankSpeed(integ_.getState()), model_.crankAcceleration(integ_.getState()));
    events_.arm(integ_.getState());
    while (!stop_ && from_.t < t_end_ - 1e-12 && step()) {
    }
  }
  const SimTK::State& lastRow() const { return *last_row_; }
  // The crank speed's extrema inside the steps, on the rows' interpolant, up to the last row.
  std::vector<CrankSpeedExtremum> extremaUpToLastRow() { return extrema_.takeUpTo(last_row_->getTime()); }
  void writeCounts(RunStats& stats) const { counts_.write(integ_, stats); }

 private:
  // One step and the rows inside it; false when the run ends (the integrator failed, or cannot
  // start again after an event).
  bool step() {
    try {
      integ_.stepTo(t_end_, events_.stopTime());
    } catch (const std::exception& ex) {
      recorder_.fail(statusAt("integration failed", integ_.getTime()) + ": " + ex.what());
      return false;
    }
    const SimTK::State& advanced = integ_.getState();
    model_.system().realize(advanced, SimTK::Stage::Acceleration);  // the next step starts from this ẏ
    double t_now = advanced.getTime();
    extrema_.stepTo(advanced.getTime(), model_.crankSpeed(advanced), model_.crankAcceleration(advanced));
    const bool event = events_.find(from_, advanced, switched_, t_now);
    recordRowsInStep(advanced, t_now, event);
    if (!event || stop_) {
      from_.at(advanced);
      return true;
    }
    return restartAtEvent(t_now);
  }

  // The output times up to t_now (before an event's time: rows there show the switched state).
  void recordRowsInStep(const SimTK::State& advanced, double t_now, bool event) {
    for (; !stop_ && k_ < times_.size() && times_[k_] <= t_now + 1e-12 && !(event && times_[k_] >= t_now - 1e-12);
         ++k_) {
      const double t_out = times_[k_];
      const bool at_step = std::abs(t_out - t_now) <= 1e-12;
      if (!at_step)
        sampleWithinStep(model_.system(), from_.t, from_.y, from_.ydot, advanced, t_out, tol_, sample_);
      const SimTK::State& s = at_step ? advanced : sample_;
      last_row_ = &s;
      stop_ = !rows_.record(s, t_out);
    }
  }

  // Continues from the state switched at the event at t_event: the integrator starts afresh there
  // (its counts kept), the step's extrema after the event, which belonged to the old supply, are
  // dropped. False, with the run's status set, when the integrator cannot start there.
  bool restartAtEvent(double t_event) {
    events_.apply(switched_);
    counts_.keep(integ_);
    try {
      integ_.initialize(switched_);
    } catch (const std::exception& ex) {
      recorder_.fail(statusAt("integration failed", t_event) + ": " + ex.what());
      return false;
    }
    const SimTK::State& s = integ_.getState();
    model_.system().realize(s, SimTK::Stage::Acceleration);
    extrema_.dropAfter(t_event);
    extrema_.restart(t_event, model_.crankSpeed(s), model_.crankAcceleration(s));
    sample_ = integ_.getState();  // rows interpolated from now on carry the new supply phase
    events_.arm(integ_.getState());
    from_.at(integ_.getState());
    return true;
  }

  const MultibodyModel& model_;
  SimTK::Integrator& integ_;
  double tol_;
  OutputRows& rows_;
  RunRecorder& recorder_;
  const std::vector<double> times_;
  const double t_end_;
  SupplyEvents events_;
  SimTK::State sample_;
  SimTK::State switched_;  // the state at an event, switched
  StepStart from_;
  CrankSpeedExtremaFinder extrema_;
  IntegratorCounts counts_;
  const SimTK::State* last_row_ = nullptr;
  std::size_t k_ = 1;
  bool stop_ = false;
};

// The energy audit from e0 to the last recorded row s1, where the tables end too (a run stopped
// early may have integrated past it).
EnergyAudit auditToLastRow(const MultibodyModel& model, const EnergySnapshot& e0, const SimTK::State& s1) {
  model.system().realize(s1, SimTK::Stage::Acceleration);
  return energyAuditBetween(e0, model.energy(s1));
}

// The constrained formulation: Simbody's integrator on the full coordinates with the loop
// constraints, rows interpolated within its steps (ConstrainedStepping).
RunResult simulateConstrained(const MultibodyModel& model, const RunControl& control) {
  refuseAlgebraicFriction(model);
  const Scene& sc = model.scene();
  RunResult run = emptyRun(model);
  SimTK::State s0 = model.initialState();
  const EnergySnapshot e0 = model.energy(s0);
  const double constraint_tol = simbodyConstraintTolerance(sc, s0);
  auto integ = makeIntegrator(sc.simulation.integrator, model.system(), sc.simulation.accuracy, constraint_tol);
  integ->initialize(s0);
  const MotorForce* motor = model.motorForce();
  RunRecorder recorder(sc, motor ? &motor->supply() : nullptr, model.options().prescribe_crank_speed, run, control);
  OutputRows rows(model, recorder, run.stats);
  integ->setReturnEveryInternalStep(true);
  ConstrainedStepping stepping(model, *integ, constraint_tol, rows, recorder);

  const std::clock_t cpu0 = std::clock();
  stepping.runToEnd();
  run.stats.cpu_seconds = double(std::clock() - cpu0) / CLOCKS_PER_SEC;
  run.crank_speed_extrema = stepping.extremaUpToLastRow();
  stepping.writeCounts(run.stats);
  run.energy = auditToLastRow(model, e0, stepping.lastRow());
  return run;
}

}  // namespace

RunResult simulateMultibody(const MultibodyModel& model, const RunControl& control) {
  const Scene& sc = model.scene();
  RunResult run = sc.simulation.formulation == Formulation::Minimal ? simulateMinimal(model, control)
                                                                    : simulateConstrained(model, control);
  appendBearingColumns(sc, run);  // each main bearing's share, when crankshaft.* places them
  return run;
}

RunResult runMultibodyModel(const Scene& scene, const RunControl& control) {
  const MultibodyModel model(scene);
  return simulateMultibody(model, control);
}

}  // namespace rollerdyn
