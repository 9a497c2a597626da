// Integrators of the reduced model (CVODE and the papers' Baranov scheme) and the RunResult
// they fill. The model itself (equations, loads, inertia) lives in ReducedModel.cpp.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <limits>
#include <stdexcept>
#include <string>

#include <Eigen/Core>

#include "physics/CrankInertia.h"
#include "analysis/CrankSpeedExtrema.h"
#include "analysis/OutputGrid.h"
#include "analysis/RunRecorder.h"
#include "analysis/StallDetector.h"
#include "motor/MotorColumns.h"
#include "motor/Stiffness.h"
#include "numerics/CvodeIntegrator.h"
#include "physics/IntegrationScales.h"
#include "reduced/ReducedModel.h"

namespace rollerdyn {
namespace {

// The reducer's losses of a run [J]: the integrated state under power_flow; under the papers'
// constant η, L·ω = (1 − η)·M·u·ω, i.e. (1/η − 1) times the work passed on (no state).
double reducerLossesOf(const ReducedModel& m, double motor_work, double integrated) {
  if (!m.scene().motor.enabled) return 0.0;
  if (m.reducer().model == ReducerLossModel::PowerFlow) return integrated;
  return (1.0 / m.reducer().eta_forward - 1.0) * motor_work;
}

// The reactions row of an evaluation: the cart statics of reduced.guide_normals.
std::vector<double> reactionsRow(const ReducedModel& m, double t, const ModelEvaluation& e) {
  const ColumnLayout& L = m.reactionsLayout();
  std::vector<double> q;
  L.reset(q);
  L.set(q, Column::t, t);
  for (int j = 0; j < m.cartCount(); ++j) {
    const CartStaticsResult& c = e.carts[j].statics;
    L.set(q, Column::N_front, j + 1, c.N_front);
    L.set(q, Column::N_rear, j + 1, c.N_rear);
    L.set(q, Column::F_rod, j + 1, c.F_rod);
    L.set(q, Column::friction, j + 1, m.scene().carts.side[j] * c.friction);  // world x
  }
  L.set(q, Column::coupling_torque, e.coupling_torque);
  return q;
}

void setupTables(const ReducedModel& m, RunResult& res) {
  res.timeseries.columns = m.timeseriesLayout().names();
  if (m.scene().simulation.reactions) res.reactions.columns = m.reactionsLayout().names();  // else no reactions table
}

// One output row of both tables from an evaluation (its eps/coupling fields may have been
// replaced by the Baranov scheme's own values).
void appendRows(const ReducedModel& m, double t, const ModelEvaluation& e, RunResult& res) {
  const ColumnLayout& L = m.timeseriesLayout();
  std::vector<double> r;  // allocated once, at its final size
  L.reset(r);
  L.set(r, Column::t, t);
  L.set(r, Column::phi_motor, e.phi_crank + e.twist);
  L.set(r, Column::phi_crank, e.phi_crank);
  L.set(r, Column::omega_motor, e.omega_motor);
  L.set(r, Column::omega_crank, e.omega_crank);
  L.set(r, Column::eps_crank, e.eps_crank);
  L.set(r, Column::eps_motor, e.eps_motor);
  L.set(r, Column::twist, e.twist);
  L.set(r, Column::twist_rate, e.twist_rate);
  L.set(r, Column::twist_accel, e.twist_accel);
  L.set(r, Column::coupling_torque, e.coupling_torque);
  L.set(r, Column::motor_torque, e.motor_torque);
  L.set(r, Column::load_torque, e.load_torque);
  for (int j = 0; j < m.cartCount(); ++j) {
    const CartEvaluation& c = e.carts[j];
    const double w = e.omega_crank;
    L.set(r, Column::x_cart, j + 1, c.pose.x_B);
    L.set(r, Column::v_cart, j + 1, c.pose.dx_B * w);
    L.set(r, Column::a_cart, j + 1, c.pose.d2x_B * w * w + c.pose.dx_B * e.eps_crank);
  }
  setMotorColumns(L, e.stator_current, e.supply, e.brake_torque, r);
  if (L.has(Column::reducer_loss_torque)) L.set(r, Column::reducer_loss_torque, e.reducer_loss_torque);
  if (L.has(Column::tooth_contact))
    L.set(r, Column::tooth_contact, static_cast<double>(toothContact(m.coupling(), e.twist)));
  res.timeseries.rows.push_back(std::move(r));
  if (!res.reactions.columns.empty()) res.reactions.rows.push_back(reactionsRow(m, t, e));
}

// Appends the output rows of evaluation e at time t and applies the stop rules both models share
// (analysis/RunRecorder.h); false when the run ends there. cart_speeds: storage for the carts' v.
bool recordRows(const ReducedModel& m, double t, const ModelEvaluation& e, const SupplyPhase& phase,
                RunRecorder& recorder, RunResult& res, std::vector<double>& cart_speeds) {
  appendRows(m, t, e, res);
  const bool finite =
      rowIsFinite(res.timeseries.rows.back()) && (res.reactions.rows.empty() || rowIsFinite(res.reactions.rows.back()));
  for (int j = 0; j < m.cartCount(); ++j) cart_speeds[j] = e.carts[j].pose.dx_B * e.omega_crank;
  return recorder.check(t, finite, {e.phi_crank, e.omega_crank, e.omega_motor, &cart_speeds, &phase});
}

// ---------------------------------------------------------------------------------------------
// CVODE

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

// CVODE's method and accuracy for the reduced model: tolerances per state, Adams or BDF, the
// highest order, the cam drive's step cap.
void setMethodAndAccuracy(const ReducedModel& m, const IntegrationScales& scales, OdeProblem& p, RunResult& res) {
  p.rtol = scales.cvode_rtol;
  p.atol = absoluteTolerances(m, scales);
  // CVODE's usual weights 1/(rtol·|y_i| + atol_i) for every state except the crank angle, which is
  // held to the ABSOLUTE accuracy atol_φ: an angle error means the same after 1 turn or 1000
  // turns, whereas rtol·|φ| would loosen the angle (and with it J(φ), the kinematics and the
  // energy balance) as the crank keeps turning.
  p.absolute_only.assign(m.stateSize(), false);
  p.absolute_only[m.iPhi()] = true;
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
  // A stiff motor law (motor/Stiffness.h: the space-phasor machine's electrical transients)
  // switches to BDF: Adams would be held to steps set by the stability of those modes.
  const bool stiff = lawIsStiff(m.motorLaw());
  res.integrator = stiff ? "cvode-bdf" : "cvode-adams";
  p.bdf = stiff;
  p.max_order = stiff ? 0 : kAdamsMaxOrder;  // BDF keeps its 5
  // Cam drive (Loveikin and Pochka (cam drive paper)): in steady state the right-hand side is exactly constant over the
  // constant-speed 2/3 of every stroke, so an unbounded step grows until it leaps from one
  // constant segment to the next across the reversal without its error estimate ever seeing it
  // (measured: the speed froze while ε = 160 rad/s² at every reversal). Cap the step at 1/8 of
  // the shortest segment, a crank angle of π/6 at the reference speed.
  if (m.scene().hasCamDrive()) p.max_step = (M_PI / 6.0) / scales.speed / 8.0;
}

// The reduced model as CVODE's problem (numerics/CvodeIntegrator.h), integrated from one output
// time to the next, with what the run reads back: the supply phase its equations run in, the
// model's evaluations, the first failed friction loop, the crank speed's extrema inside CVODE's
// steps.
class ReducedOde {
 public:
  ReducedOde(const ReducedModel& m, const std::vector<double>& times, RunResult& res)
      : m_(m), t_end_(times.back()), phase_(m.supply().initialPhase()), integ_(problem(times, res)) {
    if (events_) arm(times.front());
  }
  ReducedOde(const ReducedOde&) = delete;
  ReducedOde& operator=(const ReducedOde&) = delete;

  // Advances to the output time t, applying the switching events due on the way (motor/Supply.h):
  // CVODE stops at the next timed event (its stop time) and at a speed-triggered one (its root
  // finding of ω_r - ω_switch, rising, on the interpolant); the event is applied there (the law's
  // states mapped across it) and CVODE restarts from the new state. A constant supply has none,
  // and the run is exactly the one without starting methods. False when CVODE gave up.
  bool advanceTo(double t) {
    while (true) {
      if (!integ_.advanceTo(t)) return false;
      // CVODE returns at the stop time, or at the output time when it is the stop time: either
      // way the events due there are applied here.
      if (events_) {
        Eigen::VectorXd y = integ_.y();
        if (m_.supply().applyDueEvents(phase_, integ_.time(), m_.rotorSpeed(y.data()), integ_.rootFound(),
                                       m_.motorLaw(), y.data() + m_.iMotorStates())) {
          integ_.restart(integ_.time(), y);
          arm(integ_.time());
        }
      }
      if (reachedOutputTime(integ_.time(), t)) return true;
    }
  }
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
  CrankSpeedExtremaFinder& extrema() { return extrema_; }

 private:
  OdeProblem problem(const std::vector<double>& times, RunResult& res) {
    OdeProblem p;
    p.t0 = times.front();
    p.stop_time = times.back();
    p.y0 = m_.initialState();
    // The supply's events due at t = 0 (a speed trigger already met by the initial speed).
    m_.supply().applyDueEvents(phase_, 0.0, m_.rotorSpeed(p.y0.data()), false, m_.motorLaw(),
                               p.y0.data() + m_.iMotorStates());
    p.rhs = [this](double t, const double* y, double* ydot) { return derivatives(t, y, ydot); };
    const IntegrationScales scales =
        integrationScales(m_.scene(), std::numeric_limits<double>::quiet_NaN(), m_.motorBreakdownTorque());
    setMethodAndAccuracy(m_, scales, p, res);
    p.on_step = [this](double t, const double* y, const double* ydot, bool after_step) {
      observe(t, y, ydot, after_step);
    };
    p.root = [this](double, const double* y) { return m_.rotorSpeed(y) - trigger_speed_; };
    return p;
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

  // The crank speed's extrema inside CVODE's steps (analysis/CrankSpeedExtrema.h): each step's
  // end observed with ε from CVODE's interpolant; at a (re)start ε is f itself, and the extrema of
  // a step an event cut short are forgotten.
  void observe(double t, const double* y, const double* ydot, bool after_step) {
    const int i_omega = m_.iOmega();
    if (after_step) {
      extrema_.stepTo(t, y[i_omega], ydot[i_omega], dense_);
      return;
    }
    extrema_.dropAfter(t);
    extrema_.restart(t, y[i_omega], ydot[i_omega]);
  }

  // The stop time at the next timed event, the root finding on for a speed-triggered one.
  void arm(double t_now) {
    const double te = std::min(m_.supply().nextEventTime(phase_), t_end_);
    if (te > t_now) integ_.setStopTime(te);
    trigger_speed_ = m_.supply().triggerSpeed(phase_);
    integ_.enableRoot(!std::isnan(trigger_speed_));
  }

  const ReducedModel& m_;
  const double t_end_;
  const bool events_ = !m_.supply().constant();
  SupplyPhase phase_;  // changes only between integrations, at events
  long evaluations_ = 0;
  std::string friction_failure_;  // the first evaluation whose guide-friction loop failed, in words
  double trigger_speed_ = std::numeric_limits<double>::quiet_NaN();  // rotor speed of a speed-triggered event [rad/s]
  CrankSpeedExtremaFinder extrema_;
  // CVODE's interpolant of its last step: ω and ε inside it (called only after a step).
  const CrankSpeedExtremaFinder::Dense dense_ = [this](double tq, double& w, double& eps) {
    w = integ_.interpolate(tq, 0, m_.iOmega());
    eps = integ_.interpolate(tq, 1, m_.iOmega());
  };
  CvodeIntegrator integ_;  // last: built from the members above
};

RunResult runCvode(const ReducedModel& m, RunResult res, const RunControl& control) {
  const Scene& s = m.scene();
  const std::vector<double> times = outputTimes(s.simulation);
  ReducedOde ode(m, times, res);
  const SupplyPhase& phase = ode.phase();

  const Eigen::VectorXd y0 = m.initialState();
  res.energy.kinetic_initial = m.kineticEnergy(y0);
  res.energy.potential_initial = m.potentialEnergy(y0);

  RunRecorder recorder(s, &m.supply(), false, res, control);  // the stop rules both models share
  std::vector<double> cart_speeds(m.cartCount());
  const std::clock_t c0 = std::clock();
  res.timeseries.rows.reserve(times.size());
  res.reactions.rows.reserve(times.size());
  ModelEvaluation e;  // reused for every output row (keeps its carts' storage)
  const Eigen::VectorXd& ym = ode.integrator().y();  // the state at the last output time
  Eigen::VectorXd y_last = ym;
  for (size_t k = 0; k < times.size(); ++k) {
    double t = times[k];
    if (k > 0) {
      if (!ode.advanceTo(t)) {
        recorder.fail(ode.failureStatus());
        break;
      }
      t = ode.integrator().time();
    }
    y_last = ym;
    m.evaluate(t, phase, y_last.data(), e, true);
    if (e.friction_loop.status != LoopStatus::Solved) {
      recorder.fail(statusAt("the run stopped", t) + ": the " + describeLoopFailure(e.friction_loop));
      break;
    }
    if (!recordRows(m, t, e, phase, recorder, res, cart_speeds)) break;
  }
  res.stats.cpu_seconds = double(std::clock() - c0) / CLOCKS_PER_SEC;
  res.crank_speed_extrema =
      ode.extrema().takeUpTo(res.timeseries.rows.empty() ? times.front() : res.timeseries.rows.back()[0]);

  res.stats.steps = ode.integrator().steps();
  res.stats.error_test_failures = ode.integrator().errorTestFailures();
  res.stats.realizations = ode.evaluations();  // includes the difference-quotient Jacobian calls

  res.energy.motor_work = y_last(m.iMotorWork());
  res.energy.damping_dissipation = m.rigid() ? 0.0 : y_last(m.iDampingWork());
  res.energy.friction_dissipation = y_last(m.iFrictionWork());
  res.energy.load_work = y_last(m.iLoadWork());
  if (m.iBrakeWork() >= 0) res.energy.brake_dissipation = y_last(m.iBrakeWork());
  res.energy.reducer_losses = reducerLossesOf(m, res.energy.motor_work, m.iReducerLosses() >= 0 ? y_last(m.iReducerLosses()) : 0.0);
  res.energy.kinetic_final = m.kineticEnergy(y_last);
  res.energy.potential_final = m.potentialEnergy(y_last);
  if (m.checksFrictionWork()) res.friction_work_kinetostatic = y_last(m.iFrictionWorkKinetostatic());
  return res;
}

// ---------------------------------------------------------------------------------------------
// Baranov's fixed-step scheme in crank angle (Loveikin and Pochka (2007) eq. (2)-(4), (10), (11)), rigid drive.

RunResult runBaranov(const ReducedModel& m, RunResult res, const RunControl& control) {
  const Scene& s = m.scene();
  if (!m.rigid())
    throw std::invalid_argument(
        "reduced.integrator = baranov needs coupling.type = rigid (the scheme of Loveikin and Pochka (2007) eq. (4) "
        "is for the one-mass model)");
  const double dphi = s.reduced.baranov_step;
  if (!(dphi > 0.0)) throw std::invalid_argument("reduced.baranov_step must be > 0");
  if (!m.supply().constant() || m.motorStateCount() > 0)
    throw std::invalid_argument(
        "reduced.integrator = baranov steps in crank angle with a torque that depends on the speed alone: it takes "
        "neither a starting method that switches in time (motor.start, motor.stop) nor a motor model with states "
        "(motor.model kloss_dynamic, park); use reduced.integrator = cvode");
  const std::vector<double> times = outputTimes(s.simulation);

  const std::clock_t c0 = std::clock();
  double phi = s.initial.crank_angle;
  double w = std::max(s.initial.crank_speed, 0.0);  // the scheme only marches forward in φ
  double t = 0.0;
  double W_motor = 0.0, W_friction = 0.0, W_load = 0.0, W_friction_kinetostatic = 0.0, W_reducer = 0.0;

  Eigen::VectorXd y(m.stateSize());
  y.setZero();
  y(m.iPhi()) = phi;
  y(m.iOmega()) = w;
  res.energy.kinetic_initial = m.kineticEnergy(y);
  res.energy.potential_initial = m.potentialEnergy(y);

  size_t k_out = 0;  // next output time to fill
  RunRecorder recorder(s, &m.supply(), false, res, control);  // the stop rules both models share
  const SupplyPhase phase = m.supply().initialPhase();      // constant: the scheme takes no switching
  std::vector<double> cart_speeds(m.cartCount());
  auto emitUpTo = [&](double t_next, double phi_next, double w_next, double eps) {
    // Rows on the output grid inside [t, t_next]: ω linear in time across the step, the
    // assumption behind the trapezoidal time of eq. (10), so ε = eq. (11) is constant and φ is
    // its integral, quadratic in time. It reaches φ_next at t_next exactly because of eq. (10);
    // interpolating φ linearly instead made the rows' φ disagree with ∫ω dt by up to Δφ/4.
    while (k_out < times.size() && times[k_out] <= t_next) {
      const double a = (t_next > t) ? (times[k_out] - t) / (t_next - t) : 1.0;
      const double tau = a * (t_next - t);
      Eigen::VectorXd yo = Eigen::VectorXd::Zero(m.stateSize());
      yo(m.iPhi()) = (a < 1.0) ? phi + w * tau + 0.5 * eps * tau * tau : phi_next;
      yo(m.iOmega()) = w + a * (w_next - w);
      ModelEvaluation e = m.evaluate(yo);
      ++res.stats.realizations;
      e.eps_crank = e.eps_motor = eps;
      e.coupling_torque = e.motor_torque - m.motorSideInertia() * eps;
      const double t_out = times[k_out++];
      if (!recordRows(m, t_out, e, phase, recorder, res, cart_speeds)) return false;
    }
    return true;
  };

  bool stalled = false;
  double J_i = m.reducedInertia(phi);
  // The scheme's ω is linear within each step (eq. (10), (11)): its extrema lie on the nodes,
  // where the slope changes sign.
  CrankSpeedExtremaFinder extrema;
  double slope_before = 0.0;
  while (t < times.back()) {
    Eigen::VectorXd yi = Eigen::VectorXd::Zero(m.stateSize());
    yi(m.iPhi()) = phi;
    yi(m.iOmega()) = w;
    const ModelEvaluation e = m.evaluate(yi);
    ++res.stats.realizations;
    if (e.friction_loop.status != LoopStatus::Solved) {
      recorder.fail(statusAt("the run stopped", t) + ": the " + describeLoopFailure(e.friction_loop));
      break;
    }
    const double M = e.motor_torque - e.load_torque;  // M_p(ω_i) - M_o(φ_i)
    const double J_next = m.reducedInertia(phi + dphi);
    double w_next;
    if (w > 0.0) {
      // Loveikin and Pochka (2007) eq. (4)
      w_next = M / (J_i * w) * dphi + (3.0 * J_i - J_next) / (2.0 * J_i) * w;
    } else {
      // From rest eq. (4) divides by ω = 0, and starting it at a tiny ω instead would return
      // ω_1 ≈ M·Δφ/(J·ω_tiny), a huge overshoot. The first step therefore uses eq. (2) before
      // its division by ω, i.e. the energy theorem over one step: J_1·ω_1² = J_0·ω_0² + 2·M·Δφ.
      const double w2 = (J_i * w * w + 2.0 * M * dphi) / J_next;
      w_next = w2 > 0.0 ? std::sqrt(w2) : 0.0;
    }
    if (!(w_next > 0.0) || !std::isfinite(w_next)) {
      stalled = true;  // the scheme cannot stop or reverse: the drive has stalled
      break;
    }
    const double t_next = t + 2.0 * dphi / (w + w_next);  // Loveikin and Pochka (2007) eq. (10)
    const double eps = (w_next - w) / (t_next - t);        // Loveikin and Pochka (2007) eq. (11)
    // Work over the step by the same left-point rule as the scheme: dW = (force·x_B')·Δφ.
    W_motor += e.motor_torque * dphi;
    W_reducer += e.reducer_loss_torque * dphi;
    if (w > 0.0) W_friction_kinetostatic += e.friction_power_kinetostatic / w * dphi;  // P/ω·Δφ
    for (int j = 0; j < m.cartCount(); ++j) {
      const CartEvaluation& c = e.carts[j];
      const double sigma = s.carts.side[j];
      W_friction -= sigma * c.statics.friction * c.pose.dx_B * dphi;
      W_load -= sigma * c.roller_force * c.pose.dx_B * dphi;
    }
    const bool go = emitUpTo(t_next, phi + dphi, w_next, eps);
    if ((slope_before < 0.0 && w_next > w) || (slope_before > 0.0 && w_next < w)) extrema.record(t, w);
    if (w_next != w) slope_before = w_next - w;
    phi += dphi;
    w = w_next;
    t = t_next;
    J_i = J_next;
    ++res.stats.steps;
    if (!go) break;  // a stop rule ended the run at a row inside this step
  }
  res.stats.cpu_seconds = double(std::clock() - c0) / CLOCKS_PER_SEC;
  res.crank_speed_extrema = extrema.takeUpTo(res.timeseries.rows.empty() ? 0.0 : res.timeseries.rows.back()[0]);
  if (stalled) recorder.fail(StallDetector::statusAt(t));
  // Energy audit at the last node (at or just past t_end, or at the stall).
  y(m.iPhi()) = phi;
  y(m.iOmega()) = w;
  res.energy.motor_work = W_motor;
  res.energy.reducer_losses = reducerLossesOf(m, W_motor, W_reducer);
  res.energy.friction_dissipation = W_friction;
  res.energy.load_work = W_load;
  res.energy.kinetic_final = m.kineticEnergy(y);
  res.energy.potential_final = m.potentialEnergy(y);
  if (m.checksFrictionWork()) res.friction_work_kinetostatic = W_friction_kinetostatic;
  return res;
}

}  // namespace

RunResult runReducedModel(const Scene& scene, const RunControl& control) {
  return runReducedModel(scene, nullptr, control);
}

RunResult runReducedModel(const Scene& scene, std::shared_ptr<const MotorLaw> law, const RunControl& control) {
  // The model's kinematics and loads stay evaluable (tests and studies read them); its motion is
  // not, where the crank side has no inertia at the dead centres (physics/CrankInertia.h).
  const std::string without_inertia = crankWithoutInertia(scene, "reduced model");
  if (!without_inertia.empty()) throw std::invalid_argument(without_inertia);
  const ReducedModel model(scene, std::move(law));
  RunResult res;
  res.model = "reduced";
  res.effects = scene.effects();
  // The papers' crankshaft is rigid: a torsional chain given for the multibody model is not built
  // here (and is named as without effect, KeyEffects.h).
  res.effects.erase(std::remove(res.effects.begin(), res.effects.end(), std::string("crankshaft_torsion")),
                    res.effects.end());
  res.guide_normals = model.guideNormalsDescription();
  setupTables(model, res);
  if (scene.reduced.integrator == ReducedIntegrator::Baranov) {
    res.integrator = "baranov";
    return runBaranov(model, std::move(res), control);
  }
  return runCvode(model, std::move(res), control);
}

}  // namespace rollerdyn
