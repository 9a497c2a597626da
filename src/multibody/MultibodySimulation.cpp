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

}  // namespace

RunResult simulateMultibody(const MultibodyModel& model, const RunControl& control) {
  const Scene& sc = model.scene();
  if (sc.simulation.formulation == Formulation::Minimal) {
    RunResult run = simulateMinimal(model, control);
    appendBearingColumns(sc, run);  // each main bearing's share, when crankshaft.* places them
    return run;
  }
  if (model.hasGuideFriction() && !model.hasFrictionLagStates())
    throw std::invalid_argument(
        "multibody model: loads.guide_friction.normal_force = algebraic needs simulation.formulation = minimal "
        "(the constrained formulation knows the guide reactions only after Simbody's constrained solve); "
        "use loads.guide_friction.normal_force = lagged");
  const SimTK::MultibodySystem& system = model.system();
  RunResult run;
  run.model = "multibody";
  run.integrator = sc.simulation.integrator;
  run.effects = sc.effects();
  run.guide_normals = model.guideNormalsDescription();
  run.timeseries.columns = model.timeseriesColumns();
  const bool reactions = sc.simulation.reactions;
  if (reactions) run.reactions.columns = model.reactionColumns();

  SimTK::State s0 = model.initialState();
  const EnergySnapshot e0 = model.energy(s0);
  // simulation.constraint_tolerance bounds the LARGEST position-constraint error, but Simbody
  // projects when the RMS of its m constraint errors exceeds its tolerance; the largest error
  // can then be √m times the RMS (seen: 1.7e-6 at a 1e-6 tolerance on recuperative-2cart), so
  // Simbody gets tol/√m.
  const int n_constraint_eqs = std::max(1, s0.getNQErr());
  const double constraint_tol = sc.simulation.constraint_tolerance / std::sqrt(double(n_constraint_eqs));
  const std::vector<double> times = outputTimes(sc.simulation);  // the grid the reduced model uses
  const double t_end = sc.simulation.t_end;
  auto integ = makeIntegrator(sc.simulation.integrator, system, sc.simulation.accuracy, constraint_tol);
  integ->initialize(s0);

  // Switching events of the starting method (motor/Supply.h): a timed one is the integrator's
  // advance limit, so no step crosses it; a speed-triggered one (the star-delta changeover by
  // speed) is found after the step that crosses it, on the step's interpolant, and the run goes
  // on from there. At an event the motor element maps its states (MotorForce::applyDueEvents) and
  // the integrator starts afresh from the switched state. Rows at an event's time show the state
  // after it (as in the reduced model).
  const MotorForce* motor = model.motorForce();
  const bool events = motor && !motor->supply().constant();
  auto nextStop = [&](const SimTK::State& s) {
    return events ? std::min(t_end, motor->supply().nextEventTime(motor->phase(s))) : t_end;
  };
  auto triggerOf = [&](const SimTK::State& s) {
    return events ? motor->supply().triggerSpeed(motor->phase(s)) : std::nan("");
  };

  // Every row goes through the stop rules both models share (analysis/RunRecorder.h).
  RunRecorder recorder(sc, motor ? &motor->supply() : nullptr, model.options().prescribe_crank_speed, run, control);
  std::vector<double> cart_speeds(model.carts().size());
  std::vector<double> ts_row, re_row;
  SupplyPhase phase;
  // Records the row of state s at output time t; false when the run ends there.
  auto record = [&](const SimTK::State& s, double t) {
    system.realize(s, SimTK::Stage::Acceleration);
    model.observeMotion(s, s.getUDot(), ts_row);
    if (reactions) model.observeReactions(s, re_row);
    run.stats.constraint_error_max = std::max(run.stats.constraint_error_max, model.constraintError(s));
    for (size_t j = 0; j < cart_speeds.size(); ++j) cart_speeds[j] = model.carts()[j].v(s);
    if (motor) phase = motor->phase(s);
    const RowMotion motion{model.crankAngle(s), model.crankSpeed(s), model.motorSpeed(s), &cart_speeds,
                           motor ? &phase : nullptr};
    return recorder.record(t, ts_row, reactions ? &re_row : nullptr, motion);
  };

  // Output rows come from our own cubic Hermite interpolation between the integrator's steps,
  // into one State we keep (`sample`), rather than from Simbody's report times: Simbody copies
  // the whole State (every cache entry, ~640k instructions here) for each interpolated report,
  // which cost ~10 % of a balanced-4cart run. The interpolant is the one Simbody uses
  // (third order, from y and ẏ at both ends of the step); the sample is then projected onto the
  // constraints like Simbody's reports, so rows satisfy them to the same tolerance.
  integ->setReturnEveryInternalStep(true);
  SimTK::State sample = integ->getState();

  const std::clock_t cpu0 = std::clock();
  bool stop = !record(integ->getState(), integ->getTime());
  const SimTK::State* last_row = &integ->getState();
  SimTK::Vector y_prev = integ->getState().getY(), ydot_prev = integ->getState().getYDot();
  double t_prev = integ->getTime();
  CrankSpeedExtremaFinder extrema;  // the crank speed's extrema inside the steps, on the rows' interpolant
  extrema.restart(t_prev, model.crankSpeed(integ->getState()), model.crankAcceleration(integ->getState()));
  double t_stop = nextStop(integ->getState()), trigger = triggerOf(integ->getState());
  SimTK::State switched;  // the state at an event, switched
  long steps_before = 0, realizations_before = 0, rejected_before = 0;  // counted before the last restart at an event
  std::size_t k = 1;
  while (!stop && t_prev < t_end - 1e-12) {
    try {
      integ->stepTo(t_end, t_stop);
    } catch (const std::exception& ex) {
      recorder.fail(statusAt("integration failed", integ->getTime()) + ": " + ex.what());
      break;
    }
    const SimTK::State& advanced = integ->getState();
    system.realize(advanced, SimTK::Stage::Acceleration);  // the next step starts from this ẏ
    double t_now = advanced.getTime();
    // An event in this step: the speed trigger crossed inside it, or the step ended at a timed event.
    bool event = false, by_speed = false;
    extrema.stepTo(advanced.getTime(), model.crankSpeed(advanced), model.crankAcceleration(advanced));
    if (!std::isnan(trigger) && motor->rotorSpeed(advanced) >= trigger) {
      switched = advanced;
      t_now = locateSpeedTrigger(model, t_prev, y_prev, ydot_prev, advanced, trigger, constraint_tol, switched);
      event = by_speed = true;
    } else if (events && t_stop < t_end && t_now >= t_stop - 1e-12 * std::max(1.0, t_stop)) {
      switched = advanced;
      system.realize(switched, SimTK::Stage::Velocity);  // a State copy starts with its cache invalid
      event = true;
    }
    for (; !stop && k < times.size() && times[k] <= t_now + 1e-12 && !(event && times[k] >= t_now - 1e-12); ++k) {
      const double t_out = times[k];
      const bool at_step = std::abs(t_out - t_now) <= 1e-12;
      if (!at_step)
        sampleWithinStep(system, t_prev, y_prev, ydot_prev, advanced, t_out, constraint_tol, sample);
      const SimTK::State& s = at_step ? advanced : sample;
      last_row = &s;
      stop = !record(s, t_out);
    }
    if (event && !stop) {
      motor->applyDueEvents(switched, by_speed);
      // initialize() starts the integrator's statistics afresh: keep what it counted so far.
      steps_before += integ->getNumStepsTaken();
      rejected_before += integ->getNumErrorTestFailures();
      realizations_before += integ->getNumRealizations();
      try {
        integ->initialize(switched);  // a fresh start from the switched state (statistics keep counting)
      } catch (const std::exception& ex) {
        recorder.fail(statusAt("integration failed", t_now) + ": " + ex.what());
        break;
      }
      system.realize(integ->getState(), SimTK::Stage::Acceleration);
      // The step's extrema after the event belonged to the old supply: drop them, start afresh.
      extrema.dropAfter(t_now);
      extrema.restart(t_now, model.crankSpeed(integ->getState()), model.crankAcceleration(integ->getState()));
      sample = integ->getState();  // rows interpolated from now on carry the new supply phase
      t_stop = nextStop(integ->getState());
      trigger = triggerOf(integ->getState());
      y_prev = integ->getState().getY();
      ydot_prev = integ->getState().getYDot();
      t_prev = integ->getTime();
      continue;
    }
    y_prev = advanced.getY();
    ydot_prev = advanced.getYDot();
    t_prev = t_now;
  }
  run.stats.cpu_seconds = double(std::clock() - cpu0) / CLOCKS_PER_SEC;
  run.crank_speed_extrema = extrema.takeUpTo(last_row->getTime());
  run.stats.steps = steps_before + integ->getNumStepsTaken();
  run.stats.error_test_failures = rejected_before + integ->getNumErrorTestFailures();
  run.stats.realizations = realizations_before + integ->getNumRealizations();

  // The audit ends at the last recorded row, where the tables end too (a run stopped early may
  // have integrated past it).
  const SimTK::State& s1 = *last_row;
  system.realize(s1, SimTK::Stage::Acceleration);
  const EnergySnapshot e1 = model.energy(s1);
  run.energy = energyAuditBetween(e0, e1);
  appendBearingColumns(sc, run);  // each main bearing's share, when crankshaft.* places them
  return run;
}

RunResult runMultibodyModel(const Scene& scene, const RunControl& control) {
  const MultibodyModel model(scene);
  return simulateMultibody(model, control);
}

}  // namespace rollerdyn
