#include "compare/MotorOnInertia.h"

#include <cmath>
#include <stdexcept>

#include "numerics/CvodeIntegrator.h"

namespace rollerdyn {

namespace {
double finiteOr0(double v) { return std::isfinite(v) ? v : 0.0; }
}  // namespace

InertiaRun runMotorOnInertia(const MotorLaw& law, const InertiaRunOptions& o) {
  if (!(o.inertia > 0)) throw std::invalid_argument("motor on an inertia: J must be > 0");
  const int n = law.stateCount();
  const int iw = n, iel = n + 1, icu = n + 2, iwm = n + 3, iwl = n + 4, size = n + 5;
  auto load = [&](double w) { return o.load_torque ? o.load_torque(w) : 0.0; };
  auto evaluate = [&](const double* y, MotorEvaluation& e, double* yd) {
    law.evaluate(o.supply, y[iw], y, e, yd);
    if (yd) {
      const double w = y[iw];
      yd[iw] = (e.torque - load(w)) / o.inertia;
      yd[iel] = finiteOr0(e.electrical_power);
      yd[icu] = finiteOr0(e.copper_loss);
      yd[iwm] = e.torque * w;
      yd[iwl] = load(w) * w;
    }
  };

  OdeProblem p;
  p.bdf = true;
  p.rtol = o.rtol;
  p.stop_time = o.t_end;
  p.y0 = Eigen::VectorXd::Zero(size);
  law.initialState(o.supply, o.omega_start, o.steady_start, p.y0.data());
  p.y0(iw) = o.omega_start;
  p.atol.resize(size);
  const std::vector<double> scales = law.stateScales();
  for (int i = 0; i < n; ++i) p.atol(i) = o.rtol * scales[i];
  p.atol(iw) = o.rtol * std::max(1.0, law.synchronousSpeed());
  for (int i = iel; i < size; ++i) p.atol(i) = 1e-9;  // energies [J]: relative control dominates
  p.absolute_only.assign(size, false);
  p.rhs = [&](double, const double* y, double* yd) {
    MotorEvaluation e;
    evaluate(y, e, yd);
    return std::isfinite(yd[iw]);
  };

  InertiaRun run;
  auto record = [&](double t, const Eigen::VectorXd& y) {
    MotorEvaluation e;
    evaluate(y.data(), e, nullptr);
    InertiaRunRow r;
    r.t = t;
    r.omega = y(iw);
    r.torque = e.torque;
    r.load_torque = load(y(iw));
    r.current = e.stator_current;
    r.electrical_power = e.electrical_power;
    r.copper_loss = e.copper_loss;
    r.magnetic_energy = e.magnetic_energy;
    run.rows.push_back(r);
  };
  CvodeIntegrator integ(p);
  record(0.0, p.y0);
  const int rows = static_cast<int>(std::ceil(o.t_end / o.output_step - 1e-9));
  for (int k = 1; k <= rows; ++k) {
    const double t = std::min(o.t_end, k * o.output_step);
    if (!integ.advanceTo(t)) {
      run.error = integ.error();
      break;
    }
    record(t, integ.y());
  }
  run.complete = run.error.empty();
  run.steps = integ.steps();
  run.rhs_evaluations = integ.rhsEvaluations();
  const Eigen::VectorXd& y = integ.y();
  run.electrical_energy = y(iel);
  run.copper_energy = y(icu);
  run.motor_work = y(iwm);
  run.load_work = y(iwl);
  run.magnetic_energy_change = finiteOr0(run.rows.back().magnetic_energy) - finiteOr0(run.rows.front().magnetic_energy);
  run.kinetic_energy_change = 0.5 * o.inertia * (y(iw) * y(iw) - o.omega_start * o.omega_start);
  return run;
}

}  // namespace rollerdyn
