#include "reduced/CvodeRun.h"

#include <ctime>
#include <limits>
#include <stdexcept>
#include <string>

#include <Eigen/Core>

#include "analysis/CvodeSupplyEvents.h"
#include "analysis/OutputGrid.h"
#include "analysis/RunRecorder.h"
#include "analysis/StepExtrema.h"
#include "motor/Stiffness.h"
#include "numerics/CvodeIntegrator.h"
#include "physics/IntegrationScales.h"
#include "reduced/ReducedRunRows.h"

namespace rollerdyn {
namespace {

// Absolute tolerances: atol_i = rtol·(reference magnitude of state i, IntegrationScales.h, the
// multibody model's too), so every component is held to the same relative accuracy measured
// against its natural scale and absolute control only takes over when a state is far below that
// scale (e.g. at a start from rest); the work integrals against E_ref = ½·J(φ0)·ω_ref², the
// kinetic energy at the reference speed.
Eigen::VectorXd absoluteTolerances(const ReducedModel& m, const IntegrationScales& scales) {
  const Scene& s = m.scene();
  const double rtol = scales.cvode_rtol, w_ref = scales.speed;
  const double E_ref = 0.5 * (m.reducedInertia(s.initial.crank_angle) + m.motorSideInertia()) *
                       w_ref * w_ref;
  Eigen::VectorXd am(m.stateSize());
  am.setConstant(rtol * E_ref);
  // The motor law's states against their natural magnitudes (MotorLaw::stateScales).
  if (m.motorStateCount() > 0) {
    const std::vector<double> motor_scales = m.motorLaw()->stateScales();
    for (int i = 0; i < m.motorStateCount(); ++i) am(m.iMotorStates() + i) = rtol * motor_scales.at(i);
  }
  am(m.iPhi()) = rtol * scales.angle;
  am(m.iOmega()) = rtol * w_ref;
  if (!m.rigid()) {
    am(m.iTwist()) = rtol * scales.twist;
    am(m.iTwistRate()) = rtol * scales.twist_rate;
  }
  return am;
}

// Highest Adams order: 6 (CVODE's default is 12). Higher Adams-Moulton orders have smaller
// stability regions, and a stiff coupling's torsional mode (p0 ≈ 4.5e3 rad/s at c = 1e9) then
// sits near their edge. Measured with scripts/hardcase-constants.py (reduced model, every hard
// case at a·{0.7, 0.85, 1, 1.2, 1.4}) for caps 4, 5, 6 and 12: at 6 every largest constant
// equals 12's (the runs never go above 6) except StiffCoupling1e9WithDamping's energy, whose
// outlier at 0.85·a (46.5·a·E) disappears (0.0065), and ThousandRevolutionsWithoutDrift, 1.1-1.3x
// smaller; caps 5 and 4 make that case 2x and others (r/l = 0.95: speed 16 and 71 against 13)
// worse. On the shipped scenes at 1e-5 ... 1e-8 cap 6 takes the same steps (±1 %) and has the
// same crank-speed error as 12. The stiff case still has rare outliers at other accuracies (19
// accuracies 0.6·a ... 1.5·a: 30.8·a·E at 1.15·a with either cap, 12.9 at 0.6·a with 6): an
// error accepted within the first 5 ms of the stiff mode's start transient, not an order
// effect; its claims cover them (test_hardcases.cpp).
constexpr int kAdamsMaxOrder = 6;

// CVODE's method and accuracy for the reduced model: tolerances per state, Adams or BDF, the
// highest order, the cam drive's step cap.
//
// CVODE's usual weights 1/(rtol·|y_i| + atol_i) for every state except the crank angle, which is
// held to the ABSOLUTE accuracy atol_φ: an angle error means the same after 1 turn or 1000
// turns, whereas rtol·|φ| would loosen the angle (and with it J(φ), the kinematics and the
// energy balance) as the crank keeps turning.
//
// Adams-Moulton (orders 1-12) with a Newton corrector on a dense difference-quotient Jacobian.
// Measured against BDF on the Loveikin, Pochka, Romasevych (2018) scenes: as fast or faster (fewer steps on these smooth,
// mildly stiff equations) and 10-100x smaller energy-audit residuals at the same accuracy
// (BDF's low-order, damped error drifts the energy of the periodic J(φ) motion). Newton rather
// than fixed-point iteration keeps the corrector converging through the stiff patches: the
// smoothed load laws have a slope (F1+F2)/v_s·x_B'²/J ~ 10³-10⁴ s⁻¹ within a few v_s of each
// cart reversal (and the creep of a stalled drive lives there).
// Re-measured (model/balanced-4cart.yaml, error of ω against a run at accuracy
// 1e-10): for an ω error <= 1e-6 BDF needs ~1.6x the steps of Adams, fixed-point iteration
// ~1.8x the right-hand sides;
// capping the order (4, 5) does not help the cost (the steady state runs at order 3-6); tighter or
// looser twist weights (ψ_ref x0.1 ... x3), a less frequent Jacobian (msbp 50) and other step
// bounds only move along the same work-precision curve. So CVODE's defaults stay; the cost
// per step is what was cut (allocation-free right-hand side, numerics/EigenSundials.h).
//
// A stiff motor law (motor/Stiffness.h: the space-phasor machine's electrical transients)
// switches to BDF: Adams would be held to steps set by the stability of those modes.
void setMethodAndAccuracy(const ReducedModel& m, const IntegrationScales& scales, OdeProblem& p, RunResult& res) {
  p.rtol = scales.cvode_rtol;
  p.atol = absoluteTolerances(m, scales);
  p.absolute_only.assign(m.stateSize(), false);
  p.absolute_only[m.iPhi()] = true;  // the crank angle: absolute accuracy (above)
  const bool stiff = lawIsStiff(m.motorLaw());
  res.integrator = stiff ? "cvode-bdf" : "cvode-adams";
  p.bdf = stiff;
  p.max_order = stiff ? 0 : kAdamsMaxOrder;  // BDF keeps its 5
  p.max_step = scales.max_step;  // a cam drive's (IntegrationScales.h)
}

// The reduced model as CVODE's problem (numerics/CvodeIntegrator.h), integrated from one output
// time to the next, with what the run reads back: the supply phase its equations run in, the
// model's evaluations, the first failed friction loop, the crank speed's extrema inside CVODE's
// steps.
class ReducedOde {
 public:
  ReducedOde(const ReducedModel& m, const std::vector<double>& times, RunResult& res)
      : m_(m), phase_(m.supply().initialPhase()), events_(supplyEvents(times.back())), extrema_(m.iOmega()),
        integ_(problem(times, res)) {
    extrema_.observe(integ_);
    events_.arm(integ_);
  }
  ReducedOde(const ReducedOde&) = delete;
  ReducedOde& operator=(const ReducedOde&) = delete;

  // Advances to the output time t, applying the switching events due on the way
  // (analysis/CvodeSupplyEvents.h). False when CVODE gave up.
  bool advanceTo(double t) { return events_.advanceTo(integ_, t); }
  // Why the run stopped after advanceTo returned false.
  std::string failureStatus() const {
    if (!friction_failure_.empty()) return statusAt("the run stopped", integ_.failureTime()) + ": the " + friction_failure_;
    return std::string("integrator failure at t = ") + std::to_string(integ_.failureTime()) + " s: " + integ_.error();
  }
  const CvodeIntegrator& integrator() const { return integ_; }
  const SupplyPhase& phase() const { return phase_; }
  // The model's evaluations (the run's realizations): CVODE's, those of its difference-quotient
  // Jacobian and those at every (re)start that the extrema finder reads.
  long evaluations() const { return evaluations_; }
  StepExtrema& extrema() { return extrema_; }

 private:
  OdeProblem problem(const std::vector<double>& times, RunResult& res) {
    OdeProblem p;
    p.t0 = times.front();
    p.stop_time = times.back();
    p.y0 = m_.initialState();
    events_.applyAtStart(0.0, p.y0);
    p.rhs = [this](double t, const double* y, double* ydot) { return derivatives(t, y, ydot); };
    const IntegrationScales scales =
        integrationScales(m_.scene(), std::numeric_limits<double>::quiet_NaN(), m_.motorBreakdownTorque());
    setMethodAndAccuracy(m_, scales, p, res);
    extrema_.install(p);
    events_.install(p);
    return p;
  }

  // The model's own pieces of the supply's events: the phase kept here, the rotor speed from the
  // state, the law's states mapped across an event.
  CvodeSupplyEvents::Model supplyEvents(double t_end) {
    CvodeSupplyEvents::Model e;
    e.supply = &m_.supply();
    e.t_end = t_end;
    e.rotor_speed = [this](const double* y) { return m_.rotorSpeed(y); };
    e.phase = [this] { return phase_; };
    e.apply = [this](double t, Eigen::VectorXd& y, bool speed_reached) {
      return m_.supply().applyDueEvents(phase_, t, m_.rotorSpeed(y.data()), speed_reached, m_.motorLaw(),
                                        y.data() + m_.iMotorStates());
    };
    return e;
  }

  bool derivatives(double t, const double* y, double* ydot) {
    ++evaluations_;
    if (m_.derivatives(t, phase_, y, ydot)) return true;  // allocation-free
    // A cart locks at this trial state: recoverable (a smaller step may stay clear of it); where
    // it cannot, CVODE gives up and the run's status names the cause.
    if (friction_failure_.empty()) {
      ModelEvaluation e;
      m_.evaluate(t, phase_, y, e, false);
      friction_failure_ = describeLoopFailure(e.friction_loop);
    }
    return false;
  }

  const ReducedModel& m_;
  SupplyPhase phase_;  // changes only between integrations, at events
  CvodeSupplyEvents events_;
  long evaluations_ = 0;
  std::string friction_failure_;  // the first evaluation whose guide-friction loop failed, in words
  StepExtrema extrema_;  // the crank speed's extrema inside CVODE's steps
  CvodeIntegrator integ_;  // last: built from the members above
};

// CVODE advanced to the output time t, which becomes the time it reached; false (the run failed,
// in the recorder) when it gave up.
bool reachOutputTime(ReducedOde& ode, RunRecorder& recorder, double& t) {
  if (!ode.advanceTo(t)) {
    recorder.fail(ode.failureStatus());
    return false;
  }
  t = ode.integrator().time();
  return true;
}

// Whether the evaluation e at time t solved its guide-friction loop; if not, the run stops with
// the reason in the recorder.
bool frictionLoopSolved(const ModelEvaluation& e, double t, RunRecorder& recorder) {
  if (e.friction_loop.status == LoopStatus::Solved) return true;
  recorder.fail(statusAt("the run stopped", t) + ": the " + describeLoopFailure(e.friction_loop));
  return false;
}

// The rows at the output times: CVODE to each, the model evaluated there, the stop rules. Returns
// the state of the last row, where the energy audit ends.
Eigen::VectorXd recordOutputRows(const ReducedModel& m, ReducedOde& ode, const std::vector<double>& times,
                                 RunRecorder& recorder, RunResult& res) {
  const SupplyPhase& phase = ode.phase();
  std::vector<double> cart_speeds(m.cartCount());
  res.timeseries.rows.reserve(times.size());
  res.reactions.rows.reserve(times.size());
  ModelEvaluation e;  // reused for every output row (keeps its carts' storage)
  const Eigen::VectorXd& ym = ode.integrator().y();  // the state at the last output time
  Eigen::VectorXd y_last = ym;
  for (size_t k = 0; k < times.size(); ++k) {
    double t = times[k];
    if (k > 0 && !reachOutputTime(ode, recorder, t)) break;
    y_last = ym;
    m.evaluate(t, phase, y_last.data(), e, true);
    if (!frictionLoopSolved(e, t, recorder)) break;
    if (!recordRows(m, t, e, phase, recorder, res, cart_speeds)) break;
  }
  return y_last;
}

// The energy audit's closing terms from the state of the last row: the works integrated with the
// motion, and the kinetic and potential energy there.
void closeEnergyAudit(const ReducedModel& m, const Eigen::VectorXd& y_last, RunResult& res) {
  res.energy.motor_work = y_last(m.iMotorWork());
  res.energy.damping_dissipation = m.rigid() ? 0.0 : y_last(m.iDampingWork());
  res.energy.friction_dissipation = y_last(m.iFrictionWork());
  res.energy.load_work = y_last(m.iLoadWork());
  if (m.iBrakeWork() >= 0) res.energy.brake_dissipation = y_last(m.iBrakeWork());
  res.energy.reducer_losses = reducerLossesOf(m, res.energy.motor_work, m.iReducerLosses() >= 0 ? y_last(m.iReducerLosses()) : 0.0);
  res.energy.kinetic_final = m.kineticEnergy(y_last);
  res.energy.potential_final = m.potentialEnergy(y_last);
  if (m.checksFrictionWork()) res.friction_work_kinetostatic = y_last(m.iFrictionWorkKinetostatic());
}

}  // namespace

RunResult runCvode(const ReducedModel& m, RunResult res, const RunControl& control) {
  const Scene& s = m.scene();
  const std::vector<double> times = outputTimes(s.simulation);
  ReducedOde ode(m, times, res);

  const Eigen::VectorXd y0 = m.initialState();
  res.energy.kinetic_initial = m.kineticEnergy(y0);
  res.energy.potential_initial = m.potentialEnergy(y0);

  RunRecorder recorder(s, &m.supply(), false, res, control);  // the stop rules both models share
  const std::clock_t c0 = std::clock();
  const Eigen::VectorXd y_last = recordOutputRows(m, ode, times, recorder, res);
  res.stats.cpu_seconds = double(std::clock() - c0) / CLOCKS_PER_SEC;
  res.crank_speed_extrema =
      ode.extrema().takeUpTo(res.timeseries.rows.empty() ? times.front() : res.timeseries.rows.back()[0]);

  res.stats.steps = ode.integrator().steps();
  res.stats.error_test_failures = ode.integrator().errorTestFailures();
  res.stats.realizations = ode.evaluations();  // includes the difference-quotient Jacobian calls
  closeEnergyAudit(m, y_last, res);
  return res;
}

}  // namespace rollerdyn
