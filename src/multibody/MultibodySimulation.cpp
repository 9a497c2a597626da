#include "multibody/MultibodySimulation.h"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <sstream>

#include "multibody/IntegratorFactory.h"

namespace rollerdyn {
namespace {

bool allFinite(const std::vector<double>& row) {
  for (double v : row)
    if (!std::isfinite(v)) return false;
  return true;
}

std::string atTime(const char* what, double t) {
  std::ostringstream os;
  os.precision(4);
  os << what << " at t = " << t << " s";
  return os.str();
}

// A motor has stalled when the crank has stayed below 5 % of its synchronous speed for a full
// second after the first half second: a start from rest passes 5 % within a fraction of a second
// with any motor that can carry its load, while an overloaded drive never leaves that band.
struct StallWatch {
  double threshold;          // crank speed below which the drive counts as stopped [rad/s]
  double since = -1;         // time the crank last fell below the threshold
  bool stalled(double t, double omega) {
    if (t < 0.5 || omega >= threshold) {
      since = -1;
      return false;
    }
    if (since < 0) since = t;
    return t - since >= 1.0;
  }
};

}  // namespace

RunResult simulateMultibody(const MultibodyModel& model, const RunControl& control) {
  const Scene& sc = model.scene();
  const SimTK::MultibodySystem& system = model.system();
  RunResult run;
  run.model = "multibody";
  run.integrator = sc.simulation.integrator;
  run.effects = sc.effects();
  run.timeseries.columns = model.timeseriesColumns();
  run.reactions.columns = model.reactionColumns();

  SimTK::State s0 = model.initialState();
  const EnergySnapshot e0 = model.energy(s0);
  // simulation.constraint_tolerance bounds the LARGEST position-constraint error, but Simbody
  // projects when the RMS of its m constraint errors exceeds its tolerance; the largest error
  // can then be √m times the RMS (seen: 1.7e-6 at a 1e-6 tolerance on recuperative-2cart), so
  // Simbody gets tol/√m.
  const int n_constraint_eqs = std::max(1, s0.getNQErr());
  auto integ = makeIntegrator(sc.simulation.integrator, system, sc.simulation.accuracy,
                              sc.simulation.constraint_tolerance / std::sqrt(double(n_constraint_eqs)));
  integ->initialize(s0);

  StallWatch stall{0.05 * sc.motor.omega_sync / sc.reducer.ratio};
  std::vector<double> ts_row, re_row;
  auto record = [&](const SimTK::State& s) {
    system.realize(s, SimTK::Stage::Acceleration);
    model.observe(s, ts_row, re_row);
    run.timeseries.rows.push_back(ts_row);
    run.reactions.rows.push_back(re_row);
    run.stats.constraint_error_max = std::max(run.stats.constraint_error_max, model.constraintError(s));
  };

  const std::clock_t cpu0 = std::clock();
  record(integ->getState());
  const double t_end = sc.simulation.t_end, dt = sc.simulation.output_step;
  for (long k = 1; integ->getTime() < t_end - 1e-12; ++k) {
    const double t_out = std::min(k * dt, t_end);
    try {
      while (integ->getTime() < t_out - 1e-12) {
        const auto status = integ->stepTo(t_out, t_end);
        if (status == SimTK::Integrator::EndOfSimulation) break;
      }
    } catch (const std::exception& ex) {
      run.stats.complete = false;
      run.stats.status = atTime("integration failed", integ->getTime()) + ": " + ex.what();
      break;
    }
    record(integ->getState());
    const double t = integ->getTime();
    if (!allFinite(ts_row) || !allFinite(re_row)) {
      run.stats.complete = false;
      run.stats.status = atTime("numerical failure (non-finite value)", t);
      break;
    }
    if (sc.hasMotor() && stall.stalled(t, model.crankSpeed(integ->getState()))) {
      run.stats.complete = false;
      run.stats.status = atTime("motor stalled", stall.since);
      break;
    }
    if (control.progress) control.progress(t, t_end);
    if (control.interrupt && control.interrupt->load()) {
      run.stats.complete = false;
      run.stats.status = atTime("interrupted", t);
      break;
    }
  }
  run.stats.cpu_seconds = double(std::clock() - cpu0) / CLOCKS_PER_SEC;
  run.stats.steps = integ->getNumStepsTaken();
  run.stats.realizations = integ->getNumRealizations();

  const SimTK::State& s1 = integ->getState();
  system.realize(s1, SimTK::Stage::Acceleration);
  const EnergySnapshot e1 = model.energy(s1);
  run.energy.motor_work = e1.motor_work - e0.motor_work;
  run.energy.damping_dissipation = e1.damping_dissipation - e0.damping_dissipation;
  run.energy.friction_dissipation = e1.friction_dissipation - e0.friction_dissipation;
  run.energy.load_work = e1.load_work - e0.load_work;
  run.energy.kinetic_initial = e0.kinetic;
  run.energy.kinetic_final = e1.kinetic;
  run.energy.potential_initial = e0.potential;
  run.energy.potential_final = e1.potential;
  return run;
}

RunResult runMultibodyModel(const Scene& scene, const RunControl& control) {
  const MultibodyModel model(scene);
  return simulateMultibody(model, control);
}

}  // namespace rollerdyn
