#include "compare/MotorOnInertia.h"

#include <cmath>
#include <stdexcept>

#include "numerics/CvodeIntegrator.h"

namespace rollerdyn {

namespace {
double finiteOr0(double v) { return std::isfinite(v) ? v : 0.0; }

// The law on the inertia: its state vector (the law's states, then ω and the four energy
// integrals E_el, E_cu, W_M, W_L), its right-hand side and one output row.
struct InertiaBench {
  const MotorLaw& law;
  const InertiaRunOptions& o;
  int n = law.stateCount();
  int iw = n, iel = n + 1, icu = n + 2, iwm = n + 3, iwl = n + 4, size = n + 5;

  double load(double w) const { return o.load_torque ? o.load_torque(w) : 0.0; }

  void evaluate(const double* y, MotorEvaluation& e, double* yd) const {
    law.evaluate(o.supply, y[iw], y, e, yd);
    if (yd) {
      const double w = y[iw];
      yd[iw] = (e.torque - load(w)) / o.inertia;
      yd[iel] = finiteOr0(e.electrical_power);
      yd[icu] = finiteOr0(e.copper_loss);
      yd[iwm] = e.torque * w;
      yd[iwl] = load(w) * w;
    }
  }

  InertiaRunRow row(double t, const Eigen::VectorXd& y) const {
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
    return r;
  }
};

// CVODE's BDF problem of the bench: the start state and a tolerance per state.
OdeProblem inertiaProblem(const InertiaBench& b) {
  const InertiaRunOptions& o = b.o;
  OdeProblem p;
  p.bdf = true;
  p.rtol = o.rtol;
  p.stop_time = o.t_end;
  p.y0 = Eigen::VectorXd::Zero(b.size);
  b.law.initialState(o.supply, o.omega_start, o.steady_start, p.y0.data());
  p.y0(b.iw) = o.omega_start;
  p.atol.resize(b.size);
  const std::vector<double> scales = b.law.stateScales();
  for (int i = 0; i < b.n; ++i) p.atol(i) = o.rtol * scales[i];
  p.atol(b.iw) = o.rtol * std::max(1.0, b.law.synchronousSpeed());
  for (int i = b.iel; i < b.size; ++i) p.atol(i) = 1e-9;  // energies [J]: relative control dominates
  p.absolute_only.assign(b.size, false);
  p.rhs = [&b](double, const double* y, double* yd) {
    MotorEvaluation e;
    b.evaluate(y, e, yd);
    return std::isfinite(yd[b.iw]);
  };
  return p;
}

// The energy integrals at the end of the run (y: the final state) and the stored energies' changes.
void endEnergies(InertiaRun& run, const InertiaBench& b, const Eigen::VectorXd& y) {
  run.electrical_energy = y(b.iel);
  run.copper_energy = y(b.icu);
  run.motor_work = y(b.iwm);
  run.load_work = y(b.iwl);
  run.magnetic_energy_change = finiteOr0(run.rows.back().magnetic_energy) - finiteOr0(run.rows.front().magnetic_energy);
  run.kinetic_energy_change = 0.5 * b.o.inertia * (y(b.iw) * y(b.iw) - b.o.omega_start * b.o.omega_start);
}

}  // namespace

InertiaRun runMotorOnInertia(const MotorLaw& law, const InertiaRunOptions& o) {
  if (!(o.inertia > 0)) throw std::invalid_argument("motor on an inertia: J must be > 0");
  const InertiaBench bench{law, o};
  const OdeProblem p = inertiaProblem(bench);
  InertiaRun run;
  CvodeIntegrator integ(p);
  run.rows.push_back(bench.row(0.0, p.y0));
  const int rows = static_cast<int>(std::ceil(o.t_end / o.output_step - 1e-9));
  for (int k = 1; k <= rows; ++k) {
    const double t = std::min(o.t_end, k * o.output_step);
    if (!integ.advanceTo(t)) {
      run.error = integ.error();
      break;
    }
    run.rows.push_back(bench.row(t, integ.y()));
  }
  run.complete = run.error.empty();
  run.steps = integ.steps();
  run.rhs_evaluations = integ.rhsEvaluations();
  endEnergies(run, bench, integ.y());
  return run;
}

}  // namespace rollerdyn
