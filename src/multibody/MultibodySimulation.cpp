#include "multibody/MultibodySimulation.h"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <sstream>

#include "analysis/OutputGrid.h"
#include "analysis/StallDetector.h"
#include "multibody/IntegratorFactory.h"
#include "multibody/MinimalSimulation.h"

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

}  // namespace

RunResult simulateMultibody(const MultibodyModel& model, const RunControl& control) {
  const Scene& sc = model.scene();
  if (sc.simulation.formulation == Formulation::Minimal) return simulateMinimal(model, control);
  const SimTK::MultibodySystem& system = model.system();
  RunResult run;
  run.model = "multibody";
  run.integrator = sc.simulation.integrator;
  run.effects = sc.effects();
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
  auto integ = makeIntegrator(sc.simulation.integrator, system, sc.simulation.accuracy, constraint_tol);
  integ->initialize(s0);

  StallDetector stall(sc.hasMotor(), sc.motor.omega_sync / sc.reducer.ratio);
  std::vector<double> ts_row, re_row;
  auto record = [&](const SimTK::State& s) {
    system.realize(s, SimTK::Stage::Acceleration);
    model.observeMotion(s, s.getUDot(), ts_row);
    run.timeseries.rows.push_back(ts_row);
    if (reactions) {
      model.observeReactions(s, re_row);
      run.reactions.rows.push_back(re_row);
    }
    run.stats.constraint_error_max = std::max(run.stats.constraint_error_max, model.constraintError(s));
  };

  // Output rows come from our own cubic Hermite interpolation between the integrator's steps,
  // into one State we keep (`sample`), rather than from Simbody's report times: Simbody copies
  // the whole State (every cache entry, ~640k instructions here) for each interpolated report,
  // which cost ~10 % of a balanced-4cart run. The interpolant is the one Simbody uses
  // (third order, from y and ẏ at both ends of the step); the sample is then projected onto the
  // constraints like Simbody's reports, so rows satisfy them to the same tolerance.
  integ->setReturnEveryInternalStep(true);
  SimTK::State sample = integ->getState();
  const std::vector<double> times = outputTimes(sc.simulation);  // the grid the reduced model uses
  const double t_end = sc.simulation.t_end;

  const std::clock_t cpu0 = std::clock();
  record(integ->getState());
  stall.update(integ->getTime(), model.crankAngle(integ->getState()), model.crankSpeed(integ->getState()),
               model.motorSpeed(integ->getState()));
  const SimTK::State* last_row = &integ->getState();
  SimTK::Vector y_prev = integ->getState().getY(), ydot_prev = integ->getState().getYDot();
  double t_prev = integ->getTime();
  std::size_t k = 1;
  bool stop = false;
  while (!stop && t_prev < t_end - 1e-12) {
    try {
      integ->stepTo(t_end, t_end);
    } catch (const std::exception& ex) {
      run.stats.complete = false;
      run.stats.status = statusAt("integration failed", integ->getTime()) + ": " + ex.what();
      break;
    }
    const SimTK::State& advanced = integ->getState();
    system.realize(advanced, SimTK::Stage::Acceleration);  // the next step starts from this ẏ
    const double t_now = advanced.getTime();
    for (; !stop && k < times.size() && times[k] <= t_now + 1e-12; ++k) {
      const double t_out = times[k];
      const bool at_step = std::abs(t_out - t_now) <= 1e-12;
      if (!at_step)
        sampleWithinStep(system, t_prev, y_prev, ydot_prev, advanced, t_out, constraint_tol, sample);
      const SimTK::State& s = at_step ? advanced : sample;
      record(s);
      last_row = &s;
      if (!rowIsFinite(ts_row) || !rowIsFinite(re_row)) {
        run.stats.complete = false;
        run.stats.status = statusAt("numerical failure (non-finite value)", t_out);
        stop = true;
      } else if (stall.update(t_out, model.crankAngle(s), model.crankSpeed(s), model.motorSpeed(s))) {
        run.stats.complete = false;
        run.stats.status = stall.status();
        stop = true;
      } else {
        if (control.progress) control.progress(t_out, t_end);
        if (control.interrupt && control.interrupt->load()) {
          run.stats.complete = false;
          run.stats.status = statusAt("interrupted", t_out);
          stop = true;
        }
      }
    }
    y_prev = advanced.getY();
    ydot_prev = advanced.getYDot();
    t_prev = t_now;
  }
  run.stats.cpu_seconds = double(std::clock() - cpu0) / CLOCKS_PER_SEC;
  run.stats.steps = integ->getNumStepsTaken();
  run.stats.realizations = integ->getNumRealizations();

  // The audit ends at the last recorded row, where the tables end too (a run stopped early may
  // have integrated past it).
  const SimTK::State& s1 = *last_row;
  system.realize(s1, SimTK::Stage::Acceleration);
  const EnergySnapshot e1 = model.energy(s1);
  run.energy = energyAuditBetween(e0, e1);
  return run;
}

RunResult runMultibodyModel(const Scene& scene, const RunControl& control) {
  const MultibodyModel model(scene);
  return simulateMultibody(model, control);
}

}  // namespace rollerdyn
