#include "multibody/MinimalSimulation.h"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "analysis/CvodeSupplyEvents.h"
#include "analysis/OutputGrid.h"
#include "analysis/RunRecorder.h"
#include "analysis/StepExtrema.h"
#include "multibody/MinimalSystem.h"
#include "multibody/MotorForce.h"
#include "multibody/StopRuleMotion.h"
#include "motor/Stiffness.h"
#include "physics/IntegrationScales.h"
#include "numerics/CvodeIntegrator.h"

namespace rollerdyn {
namespace {

// Largest |a - b| relative to max(largest |a|, floor) (0 when both vanish).
double relativeDifference(const SimTK::Vector& a, const SimTK::Vector& b, double floor = 0.0) {
  double diff = 0, scale = floor;
  for (int i = 0; i < a.size(); ++i) {
    diff = std::max(diff, std::abs(a[i] - b[i]));
    scale = std::max(scale, std::abs(a[i]));
  }
  return scale > 0 ? diff / scale : diff;
}

// E_ref: kinetic energy of the machine at the reference speed w_ref [J] (its work integrals'
// scale), at the initial crank angle.
double referenceKineticEnergy(const MultibodyModel& model, const SimTK::State& s0, double crank_angle, double w_ref) {
  SimTK::State kin = s0;
  IndependentState x;
  x.crank_angle = crank_angle;
  x.crank_speed = w_ref;
  MinimalCoordinates(model, kin).apply(0.0, x, kin);
  model.system().realize(kin, SimTK::Stage::Velocity);
  return std::max(model.system().calcKineticEnergy(kin), 1e-300);
}

// The mechanical states' tolerances: φ2 absolute [rad], ω2, the twist and its rate against their
// reference scales; every other state (the energy-audit integrals) against rtol·E_ref [J].
void setMechanicalTolerances(OdeProblem& p, const MinimalLayout& L, const IntegrationScales& scales, double E_ref) {
  const double rtol = scales.cvode_rtol, w_ref = scales.speed;
  p.rtol = rtol;
  p.atol = Eigen::VectorXd::Constant(L.size, rtol * E_ref);  // energy-audit integrals
  p.absolute_only.assign(L.size, false);
  p.atol(L.phi) = rtol * scales.angle;  // [rad]
  p.absolute_only[L.phi] = true;
  if (L.omega >= 0) p.atol(L.omega) = rtol * w_ref;
  if (L.twist >= 0) {
    p.atol(L.twist) = rtol * scales.twist;
    p.atol(L.twist_rate) = rtol * scales.twist_rate;
  }
}

// Tolerances: every state against its natural scale, the same scales as the reduced model's
// (IntegrationScales.h), with the constrained formulation's weights for the twist (coupling
// torque to accuracy·M_ref) and the friction normal forces (GuideFriction::setErrorWeights).
void setTolerances(OdeProblem& p, const MultibodyModel& model, const MinimalLayout& L, const SimTK::State& s0,
                   const IntegrationScales& scales) {
  const Scene& sc = model.scene();
  const double rtol = scales.cvode_rtol;
  setMechanicalTolerances(p, L, scales, referenceKineticEnergy(model, s0, p.y0(L.phi), scales.speed));
  const int n_lag_states = model.hasFrictionLagStates() ? 2 * sc.carts.count : 0;
  // The motor element's z come first (MultibodyModel::buildForces): the law's states against
  // their natural magnitudes, then the brake work (an energy integral, atol as above).
  const int n_motor = model.motorStateCount();
  const int z_normals = L.z + n_motor;  // first friction normal force
  if (const MotorForce* motor = model.motorForce()) {
    const std::vector<double> state_scales = motor->law().stateScales();
    for (int i = 0; i < motor->lawStateCount(); ++i) p.atol(L.z + i) = rtol * state_scales.at(i);
  }
  if (L.size - L.z != n_motor + n_lag_states + model.energyStateCount())
    throw std::logic_error(
        "minimal formulation: auxiliary states are not [motor states, friction normal-force lags, energy integrals]");
  if (n_lag_states > 0) {
    // One unit of N̂: the error whose friction changes a cart's speed by 1 m/s in 1 s.
    const double N_unit = sc.lightestCartMassWithRodShare() * 1.0 / sc.loads.guide_friction;
    // The friction element is built before the energy meter (MultibodyModel::buildForces), so
    // its normal forces are the next z entries.
    for (int i = 0; i < n_lag_states; ++i) p.atol(z_normals + i) = rtol * N_unit;
  }
}

// Newton matrix from a structured Jacobian (CvodeIntegrator.h): difference quotients only for
// the mechanical states (φ2, twist, φ̇2, twist rate: at most 4 evaluations per Jacobian instead
// of one per state, 72 at 32 carts), known columns for the auxiliary states:
//  - friction normal forces N̂ (GuideFriction.h: dN̂/dt = (N - N̂)/τ_N): diagonal -1/τ_N, and the
//    friction-dissipation integral's rate ∂P/∂N̂ (GuideFriction::dissipatedPowerGradient).
//    Neglected: N̂'s effect through the friction force on the accelerations and on N (of order
//    f·lever/inertia, f the friction coefficient, against 1/τ_N = 500/s at 2 ms);
//  - energy-audit integrals (EnergyMeter.h): their rates are powers of the forces, which do not
//    depend on the integrals: the column is exactly zero.
// The neglected entries change only the iteration matrix, never the equations solved: CVODE's
// corrector still converges to the same implicit Adams step and its local-error test still
// decides acceptance, so the solution is that of the full Jacobian to the tolerance.
// ∂P/∂N̂ is not neglected because the energy audit is a consistency check at the level of the
// corrector's convergence tolerance: with that row missing, the friction-dissipation integral
// lags the N̂ corrections (large: N̂ relaxes in τ_N, shorter than a step) and the audit showed
// outliers of 0.4·accuracy·E (stiff-coupling hard case, 1 accuracy in 12; ≤ 8e-4 with the full
// Jacobian, ≤ 3e-3 with this row included).
//  - the motor law's states (MotorForce.h): difference quotients like the mechanical states
//    (they couple to the speed both ways); the brake work: an energy integral, column zero.
// With the algebraic law there are no lag states: the friction is part of the mechanical
// states' right-hand side, whose columns are difference quotients.
void setStructuredJacobian(OdeProblem& p, const MultibodyModel& model, MinimalSystem& ms, const MinimalLayout& L) {
  const Scene& sc = model.scene();
  const int n_normals = model.hasFrictionLagStates() ? 2 * sc.carts.count : 0;
  const int z_normals = L.z + model.motorStateCount();  // first friction normal force
  p.jacobian.difference_quotient.assign(L.size, false);
  for (int i = 0; i < L.z; ++i) p.jacobian.difference_quotient[i] = true;
  if (const MotorForce* motor = model.motorForce())
    for (int i = 0; i < motor->lawStateCount(); ++i) p.jacobian.difference_quotient[L.z + i] = true;
  p.jacobian.diagonal = Eigen::VectorXd::Zero(L.size);
  if (n_normals == 0) return;
  const double tau_N = sc.loads.guide_friction_lag;
  if (!(tau_N > 0.0) || !std::isfinite(tau_N))
    throw std::invalid_argument(
        "minimal formulation: loads.guide_friction.normal_force_lag must be a positive time [s], got " +
        std::to_string(tau_N));
  p.jacobian.diagonal.segment(z_normals, n_normals).setConstant(-1.0 / tau_N);
  // Energy integrals in EnergyMeter.h's order: motor work, damping, friction, load work
  // (then the reducer's losses).
  const int row_friction_dissipation = z_normals + n_normals + 2, first_normal = z_normals;
  p.jacobian.known_entries = [&ms, row_friction_dissipation, first_normal](double t, const double* y,
                                                                          Eigen::Ref<Eigen::MatrixXd> jac) {
    return ms.frictionPowerEntries(t, y, row_friction_dissipation, first_normal, jac);
  };
}

// Highest Adams-Moulton order 5: the friction normal-force lag puts an eigenvalue λ = -1/τ_N
// (-500 1/s at 2 ms) in every run with guide friction, at hλ ≈ -0.5 ... -2 for the 1-4 ms
// steps of accuracies 1e-4 ... 1e-8. Adams-Moulton's stability interval on the negative real
// axis shrinks with the order (about [-1.8, 0] at order 5, [-1.2, 0] at 6, shorter above), so
// a run that climbs above order 5 there is intermittently unstable in that mode, which its
// error estimate sees only after the damage: measured on recuperative-2cart without gravity,
// 1 s at accuracy 0.7e-10 ... 1.5e-10, coupling-torque error 1.9e-10 ... 7.2e-10 with order ≤ 5
// against 4.2e-10 ... 2.9e-8 with order ≤ 12; balanced-4cart (10 s, accuracy 1e-2 ... 1e-6)
// costs the same either way (CVODE seldom goes above order 5 there).
constexpr int kMinimalAdamsMaxOrder = 5;

// The ODE CVODE integrates: the minimal system's right-hand side from y0, its tolerances, its
// Newton matrix and its method.
OdeProblem minimalProblem(const MultibodyModel& model, MinimalSystem& ms, const Eigen::VectorXd& y0,
                            const SimTK::State& s0) {
  const Scene& sc = model.scene();
  const IntegrationScales scales = integrationScales(
      sc, model.options().prescribe_crank_speed ? model.options().crank_speed : std::numeric_limits<double>::quiet_NaN(),
      model.motorBreakdownTorque());
  OdeProblem p;
  p.t0 = 0.0;
  p.stop_time = sc.simulation.t_end;
  p.y0 = y0;
  setTolerances(p, model, ms.layout(), s0, scales);
  if (model.options().structured_jacobian) setStructuredJacobian(p, model, ms, ms.layout());
  p.max_step = scales.max_step;  // a cam drive's (IntegrationScales.h), as the reduced model's
  p.max_order = kMinimalAdamsMaxOrder;
  // A stiff motor law (motor/Stiffness.h: the space-phasor machine's electrical modes) switches
  // to BDF, with the same structured Newton matrix.
  const MotorForce* motor = model.motorForce();
  p.bdf = motor && lawIsStiff(&motor->law());
  p.rhs = [&ms](double t, const double* y, double* ydot) { return ms.rhs(t, y, ydot); };
  return p;
}

// Every row's reactions come from the O(n) inverse-dynamics pass (MinimalReactions.h);
// Simbody's constrained solve runs at every k-th row (simulation.self_check_interval, from row
// 0) as the reference: accelerations, guide normal forces and every reaction column compared.
class FormulationSelfCheck {
 public:
  FormulationSelfCheck(const MultibodyModel& model, RunStats& stats)
      : model_(model), stats_(stats), interval_(std::size_t(std::max(1, model.scene().selfCheckInterval()))) {
    const std::vector<std::string> columns = model.reactionColumns();
    for (std::size_t i = 1; i < columns.size(); ++i) stats_.reaction_self_check.push_back({columns[i], 0.0, 0.0});
  }
  bool due(std::size_t row) const { return row % interval_ == 0; }

  // Compares Simbody's constrained solve at the row's state (realized to Acceleration) with the
  // projected accelerations, guide normal forces and O(n) reaction row of the same state.
  void compare(const SimTK::State& s, const SimTK::Vector& udot_own, const SimTK::Vector& normals_own,
               const std::vector<double>* own_row) {
    // Scale of the accelerations: their own, or ω2²·(1 rad) when the machine runs steadily and
    // its accelerations nearly vanish (a cam's constant-speed stretch: u̇ ~ 1e-7 from terms of
    // order ω2², whose round-off would otherwise read as a relative 1e-7).
    const double omega = model_.crankSpeed(s);
    double check = relativeDifference(s.getUDot(), udot_own, omega * omega);
    model_.observeReactions(s, re_simbody_);
    if (model_.hasGuideFriction()) check = std::max(check, relativeDifference(constrainedNormals(), normals_own));
    if (std::isfinite(check)) stats_.formulation_self_check = std::max(stats_.formulation_self_check, check);
    if (own_row) compareReactionRow(*own_row);
    ++stats_.self_check_rows;
    stats_.constraint_error_max = std::max(stats_.constraint_error_max, model_.constraintError(s));
  }

 private:
  // The guide normal forces of Simbody's constrained solve, N_front, N_rear per cart [N].
  SimTK::Vector constrainedNormals() const {
    const int n_carts = model_.scene().carts.count;
    SimTK::Vector normals(2 * n_carts);
    const ColumnLayout& L = model_.reactionsLayout();
    for (int j = 0; j < n_carts; ++j) {
      normals[2 * j] = L.get(re_simbody_, Column::N_front, j + 1);
      normals[2 * j + 1] = L.get(re_simbody_, Column::N_rear, j + 1);
    }
    return normals;
  }

  // Each reaction column's largest difference between the O(n) row and Simbody's, and its scale.
  void compareReactionRow(const std::vector<double>& own_row) {
    for (std::size_t i = 1; i < re_simbody_.size(); ++i) {
      ReactionCheck& c = stats_.reaction_self_check[i - 1];
      c.max_difference = std::max(c.max_difference, std::abs(own_row[i] - re_simbody_[i]));
      c.max_value = std::max(c.max_value, std::abs(re_simbody_[i]));
    }
  }

  const MultibodyModel& model_;
  RunStats& stats_;
  std::size_t interval_;
  std::vector<double> re_simbody_;
};

// The output rows of the minimal formulation: motion and O(n) reactions at each output time,
// Simbody's constrained solve beside them at every self-check row, then the stop rules.
class OutputRows {
 public:
  OutputRows(const MultibodyModel& model, MinimalSystem& ms, RunRecorder& recorder, RunStats& stats)
      : model_(model), ms_(ms), recorder_(recorder), self_check_(model, stats),
        reactions_(model.scene().simulation.reactions), cart_speeds_(model.scene().carts.count) {}

  // Row k at time t from state y; false when the run must stop (non-finite row, stall, interrupt,
  // friction loop).
  bool record(std::size_t k, double t, const Eigen::VectorXd& y) {
    if (!ms_.set(t, y.data())) return loopFailed(t);
    const SimTK::State& s = ms_.state();
    const SimTK::Vector udot_projected = ms_.dynamics().udot();
    model_.observeMotion(s, udot_projected, ts_row_);
    if (reactions_) ms_.reactionsRow(s, re_row_);
    if (self_check_.due(k)) {
      const SimTK::Vector normals_own = model_.hasGuideFriction() ? ms_.dynamics().guideNormals(s) : SimTK::Vector();
      const SimTK::State* constrained = ms_.setConstrained(t, y.data());  // Simbody's full constrained solve
      if (!constrained) return loopFailed(t);
      self_check_.compare(*constrained, udot_projected, normals_own, reactions_ ? &re_row_ : nullptr);
    }
    return recorder_.record(t, ts_row_, reactions_ ? &re_row_ : nullptr, stopRuleMotion(model_, s, cart_speeds_, phase_));
  }

 private:
  bool loopFailed(double t) {
    recorder_.fail(statusAt("the run stopped", t) + ": the " + ms_.loopFailure());
    return false;
  }

  const MultibodyModel& model_;
  MinimalSystem& ms_;
  RunRecorder& recorder_;
  FormulationSelfCheck self_check_;
  bool reactions_;
  std::vector<double> ts_row_, re_row_, cart_speeds_;
  SupplyPhase phase_;
};

// The run's tables and statistics before the first row.
RunResult emptyRun(const MultibodyModel& model) {
  const Scene& sc = model.scene();
  RunResult run;
  run.model = "multibody";
  run.integrator = "cvode-adams (minimal coordinates)";
  run.effects = sc.effects();
  run.timeseries.columns = model.timeseriesColumns();
  if (sc.simulation.reactions) run.reactions.columns = model.reactionColumns();
  run.stats.formulation_self_check = 0.0;
  run.guide_normals = model.guideNormalsDescription();
  return run;
}

void keepIntegratorStatistics(const CvodeIntegrator& integ, RunStats& stats) {
  stats.steps = integ.steps();
  stats.error_test_failures = integ.errorTestFailures();
  stats.realizations = integ.rhsEvaluations();
  stats.jacobian_evaluations = integ.jacobianEvaluations();
  stats.newton_convergence_failures = integ.newtonConvergenceFailures();
}

// Its closed-form loops turn one rigid crankshaft: a torsional chain would be held rigid without
// a word (the scene parser refuses the pair; a caller that sets the formulation in code meets
// this instead).
void refuseTorsionalChain(const MultibodyModel& model) {
  if (model.crankshaftTorsion())
    throw std::invalid_argument(
        "multibody model: the minimal formulation turns one rigid crankshaft; the torsional chain "
        "(crankshaft.torsional_stiffness) needs simulation.formulation: constrained");
}

// With the lagged law, the normal-force states at the friction loop's solution (their fixed
// point); then the evaluation state at y0, realized to Dynamics. False, with the run's status
// set, when the loop has no solution there.
bool startFrictionLoop(const MultibodyModel& model, MinimalSystem& ms, Eigen::VectorXd& y0, RunResult& run) {
  if ((model.hasFrictionLagStates() && !ms.startLagStates(0.0, y0)) || !ms.set(0.0, y0.data())) {
    run.stats.complete = false;
    run.stats.status = statusAt("the run stopped", 0.0) + ": the " + ms.loopFailure();
    return false;
  }
  model.system().realize(ms.state(), SimTK::Stage::Dynamics);
  return true;
}

// The minimal formulation's own pieces of the supply's events (analysis/CvodeSupplyEvents.h): the
// phase kept in the State, the rotor speed ω_r = i·(φ̇2 + twist rate), the events applied by the
// system (the law's states mapped, the phase latched).
CvodeSupplyEvents::Model supplyEventsOf(const MultibodyModel& model, MinimalSystem& ms) {
  CvodeSupplyEvents::Model e;
  e.supply = model.motorForce() ? &model.motorForce()->supply() : nullptr;
  e.t_end = model.scene().simulation.t_end;
  const MinimalLayout& L = ms.layout();
  const double ratio = model.scene().reducer.ratio;
  e.rotor_speed = [&L, ratio](const double* y) {
    const double w_crank = L.omega >= 0 ? y[L.omega] : 0.0, w_twist = L.twist_rate >= 0 ? y[L.twist_rate] : 0.0;
    return ratio * (w_crank + w_twist);
  };
  e.phase = [&ms] { return ms.phase(); };
  e.apply = [&ms](double t, Eigen::VectorXd& y, bool speed_reached) { return ms.applyEvents(t, y, speed_reached); };
  return e;
}

// The integration of one run: CVODE on the minimal coordinates with the supply's events and the
// crank speed's extrema hooked into its problem, and the rows at the output times, every one
// through the stop rules both models share (analysis/RunRecorder.h).
class MinimalRun {
 public:
  MinimalRun(const MultibodyModel& model, MinimalSystem& ms, OdeProblem& p, RunResult& run, const RunControl& control)
      : model_(model), ms_(ms), run_(run), extrema_(ms.layout().omega), events_(supplyEventsOf(model, ms)),
        integ_(withHooks(p)),
        recorder_(model.scene(), model.motorForce() ? &model.motorForce()->supply() : nullptr,
                  model.options().prescribe_crank_speed, run, control),
        rows_(model, ms, recorder_, run.stats) {
    extrema_.observe(integ_);
    events_.arm(integ_);
  }
  MinimalRun(const MinimalRun&) = delete;
  MinimalRun& operator=(const MinimalRun&) = delete;

  // Row 0 from y0, then one row per output time until the end or a stop.
  void recordRows(const Eigen::VectorXd& y0) {
    const std::vector<double> times = outputTimes(model_.scene().simulation);
    bool go = rows_.record(0, times.front(), y0);
    t_last_ = times.front();
    y_last_ = y0;
    for (std::size_t k = 1; go && k < times.size(); ++k) {
      if (!advanceTo(times[k])) break;
      go = rows_.record(k, times[k], integ_.y());
      if (!go && !run_.stats.complete && run_.timeseries.rows.size() <= k) break;  // the row itself failed
      t_last_ = times[k];
      y_last_ = integ_.y();
    }
  }

  // The extrema and the integrator's statistics, and the energy audit from the last recorded
  // row's state (O(n): the evaluation state, realized to Dynamics).
  void finish(const EnergySnapshot& e0) {
    run_.crank_speed_extrema =
        extrema_.takeUpTo(run_.timeseries.rows.empty() ? t_last_ : run_.timeseries.rows.back()[0]);
    keepIntegratorStatistics(integ_, run_.stats);
    if (!model_.scene().simulation.reactions) run_.stats.reaction_self_check.clear();
    ms_.set(t_last_, y_last_.data());
    model_.system().realize(ms_.state(), SimTK::Stage::Dynamics);
    run_.energy = energyAuditBetween(e0, model_.energy(ms_.state()));
  }

 private:
  OdeProblem& withHooks(OdeProblem& p) {
    extrema_.install(p);
    events_.install(p);
    return p;
  }

  // CVODE to the output time t_out, the supply's events applied on the way. False, with the
  // run's status set, when it fails.
  bool advanceTo(double t_out) {
    if (events_.advanceTo(integ_, t_out)) return true;
    if (!ms_.loopFailure().empty())  // CVODE gave up on states where the friction loop has no solution
      recorder_.fail(statusAt("the run stopped", ms_.loopFailureTime()) + ": the " + ms_.loopFailure());
    else
      recorder_.fail(statusAt("integration failed", integ_.time()) + ": " + integ_.error());
    return false;
  }

  const MultibodyModel& model_;
  MinimalSystem& ms_;
  RunResult& run_;
  StepExtrema extrema_;
  CvodeSupplyEvents events_;
  CvodeIntegrator integ_;
  RunRecorder recorder_;
  OutputRows rows_;
  double t_last_ = 0;  // the last recorded row, whose state closes the energy audit
  Eigen::VectorXd y_last_;
};

}  // namespace

RunResult simulateMinimal(const MultibodyModel& model, const RunControl& control) {
  refuseTorsionalChain(model);
  const Scene& sc = model.scene();
  RunResult run = emptyRun(model);
  // The initial state from the closed forms (no projection, no constrained solve: O(n)), and,
  // with the lagged law, its normal-force states at the loop's solution (their fixed point).
  const SimTK::State s0 =
      model.closedFormState(sc.initial.crank_angle, sc.initial.crank_speed, sc.initial.twist);
  MinimalSystem ms(model, s0);
  Eigen::VectorXd y0 = ms.pack(s0);
  if (!startFrictionLoop(model, ms, y0, run)) return run;
  const EnergySnapshot e0 = model.energy(ms.state());

  OdeProblem p = minimalProblem(model, ms, y0, s0);
  if (p.bdf) run.integrator = "cvode-bdf (minimal coordinates)";
  MinimalRun minimal(model, ms, p, run, control);
  const std::clock_t cpu0 = std::clock();
  minimal.recordRows(y0);
  run.stats.cpu_seconds = double(std::clock() - cpu0) / CLOCKS_PER_SEC;
  minimal.finish(e0);
  return run;
}

}  // namespace rollerdyn
