#include "multibody/MinimalSimulation.h"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "analysis/CrankSpeedExtrema.h"
#include "analysis/OutputGrid.h"
#include "analysis/RestDetector.h"
#include "analysis/StallDetector.h"
#include "multibody/GuideFriction.h"
#include "multibody/MinimalCoordinates.h"
#include "multibody/MinimalDynamics.h"
#include "multibody/MinimalReactions.h"
#include "multibody/MotorForce.h"
#include "motor/Stiffness.h"
#include "physics/IntegrationScales.h"
#include "numerics/CvodeIntegrator.h"

namespace rollerdyn {
namespace {

// Layout of the integrated vector y = [φ2, twist?, φ̇2?, twist rate?, z...].
struct Layout {
  int phi = 0, twist = -1, omega = -1, twist_rate = -1, z = 0, size = 0;
  Layout(const MinimalCoordinates& c, int nz) {
    int i = 1;
    if (c.twistFree()) twist = i++;
    if (c.crankFree()) omega = i++;
    if (c.twistFree()) twist_rate = i++;
    z = i;
    size = i + nz;
  }
};

// One evaluation context: the State the right-hand side writes into, and the map/solver.
class MinimalSystem {
 public:
  MinimalSystem(const MultibodyModel& model, const SimTK::State& s0)
      : model_(model), s_(withoutConstraints(model, s0)), constrained_(s0), coords_(model, s0),
        dyn_(model, s0), reactions_(model, s0), layout_(coords_, model.forces().getZ(s0).size()) {}

  const Layout& layout() const { return layout_; }
  // The evaluation state (constraints disabled: see withoutConstraints).
  SimTK::State& state() { return s_; }
  // Sets the copy of the state that keeps the model's constraints exactly from y, evaluates the
  // projected dynamics on it (which realizes it to Velocity) and then lets Simbody do its full
  // constrained solve (realization to Acceleration, from Velocity on): the reaction columns and
  // the self-check at an output row, with Position and Velocity realized once.
  const SimTK::State* setConstrained(double t, const double* y) {
    place(t, y, constrained_);
    if (!evaluate(t, constrained_)) return nullptr;
    model_.system().realize(constrained_, SimTK::Stage::Acceleration);
    return &constrained_;
  }
  const MinimalDynamics& dynamics() const { return dyn_; }
  // The O(n) reactions row of the state last evaluated (MinimalReactions.h).
  void reactionsRow(const SimTK::State& s, std::vector<double>& row) { reactions_.row(s, dyn_, row); }
  // The friction loop's first failure (empty while it always solved) and its time.
  const std::string& loopFailure() const { return loop_failure_; }
  double loopFailureTime() const { return loop_failure_time_; }
  // Lagged law: the loop's normal forces at y (the values N̂ relaxes to) into y's N̂ entries.
  bool startLagStates(double t, Eigen::VectorXd& y) {
    place(t, y.data());
    if (!dyn_.evaluateWithLoop(s_, coords_)) return false;
    // N̂ sit after the motor element's z (MultibodyModel::buildForces): set them where the
    // friction element keeps them and copy the whole z back.
    model_.frictionElement().setNormalsInUse(s_, dyn_.guideNormals(s_));
    const SimTK::Vector& z = model_.forces().getZ(s_);
    for (int i = 0; i < z.size(); ++i) y(layout_.z + i) = z[i];
    return true;
  }

  Eigen::VectorXd pack(const SimTK::State& s) const {
    Eigen::VectorXd y(layout_.size);
    const IndependentState x = coords_.extract(s);
    y(layout_.phi) = x.crank_angle;
    if (layout_.twist >= 0) y(layout_.twist) = x.twist;
    if (layout_.omega >= 0) y(layout_.omega) = x.crank_speed;
    if (layout_.twist_rate >= 0) y(layout_.twist_rate) = x.twist_rate;
    const SimTK::Vector& z = model_.forces().getZ(s);
    for (int i = 0; i < z.size(); ++i) y(layout_.z + i) = z[i];
    return y;
  }

  // Sets the State exactly from y (closed-form loops) and evaluates the projected dynamics.
  // False when the guide-friction loop has no solution there (loopFailure()).
  bool set(double t, const double* y) {
    place(t, y);
    return evaluate(t, s_);
  }

  // Writes ∂(friction-dissipation rate)/∂N̂ at (t, y) into row `row` of jac, columns
  // first_column... (one per normal-force state): the known Jacobian entries that depend on the
  // state (see simulateMinimal).
  bool frictionPowerEntries(double t, const double* y, int row, int first_column, Eigen::Ref<Eigen::MatrixXd> jac) {
    place(t, y);
    model_.system().realize(s_, SimTK::Stage::Velocity);
    const SimTK::Vector g = model_.frictionPowerGradient(s_);
    for (int k = 0; k < g.size(); ++k) jac(row, first_column + k) = g[k];
    return true;
  }

  // Applies the motor's switching events due at t to y (MotorForce::applyDueEvents: the law's
  // states mapped, the supply phase latched in both states); true when anything switched.
  bool applyEvents(double t, Eigen::VectorXd& y, bool speed_reached) {
    const MotorForce* motor = model_.motorForce();
    if (!motor) return false;
    set(t, y.data());
    if (!motor->applyDueEvents(s_, speed_reached)) return false;
    motor->setPhase(constrained_, motor->phase(s_));
    const SimTK::Vector& z = model_.forces().getZ(s_);
    for (int i = 0; i < z.size(); ++i) y(layout_.z + i) = z[i];
    return true;
  }
  // The supply phase the run is in.
  SupplyPhase phase() const { return model_.motorForce()->phase(s_); }

  bool rhs(double t, const double* y, double* ydot) {
    // A loop without solution at a trial state is reported to CVODE as recoverable: a smaller step
    // may avoid it; where it cannot, CVODE gives up and the run's status names the cause.
    if (!set(t, y)) return false;
    const Eigen::Vector2d& nu_dot = dyn_.independentAccelerations();
    const int i_crank = coords_.crankFree() ? 0 : -1, i_twist = coords_.crankFree() ? 1 : 0;
    ydot[layout_.phi] = s_.getU()[model_.crank().getFirstUIndex(s_)];
    if (layout_.twist >= 0) ydot[layout_.twist] = y[layout_.twist_rate];
    if (layout_.omega >= 0) ydot[layout_.omega] = nu_dot(i_crank);
    if (layout_.twist_rate >= 0) ydot[layout_.twist_rate] = nu_dot(i_twist);
    if (model_.hasFrictionLagStates()) normals_ = dyn_.guideNormals(s_);
    model_.auxiliaryRates(s_, normals_, zdot_);
    for (int i = 0; i < zdot_.size(); ++i) ydot[layout_.z + i] = zdot_[i];
    return true;
  }

 private:
  bool evaluate(double t, SimTK::State& s) {
    if (dyn_.evaluate(s, coords_)) return true;
    if (loop_failure_.empty()) {
      loop_failure_ = describeLoopFailure(dyn_.loopResult());
      loop_failure_time_ = t;
    }
    return false;
  }
  // Sets q, u (closed-form loops) and z of the State exactly from y.
  void place(double t, const double* y) { place(t, y, s_); }
  void place(double t, const double* y, SimTK::State& s) {
    IndependentState x;
    x.crank_angle = y[layout_.phi];
    if (layout_.twist >= 0) x.twist = y[layout_.twist];
    if (layout_.omega >= 0) x.crank_speed = y[layout_.omega];
    if (layout_.twist_rate >= 0) x.twist_rate = y[layout_.twist_rate];
    coords_.apply(t, x, s);
    SimTK::Vector& z = model_.forces().updZ(s);
    for (int i = 0; i < z.size(); ++i) z[i] = y[layout_.z + i];
  }

  // The evaluations need no constraint: the closed forms satisfy them exactly, and the projected
  // equations use only Simbody's tree operators. With the constraints disabled in the evaluation
  // state, Simbody's realization no longer computes every loop's position and velocity errors
  // (~13 % of an evaluation's instructions at 4 carts).
  static SimTK::State withoutConstraints(const MultibodyModel& model, const SimTK::State& s0) {
    SimTK::State s = s0;
    const SimTK::SimbodyMatterSubsystem& matter = model.matter();
    for (SimTK::ConstraintIndex i(0); i < matter.getNumConstraints(); ++i) matter.getConstraint(i).disable(s);
    model.system().realize(s, SimTK::Stage::Instance);
    return s;
  }

  const MultibodyModel& model_;
  SimTK::State s_, constrained_;
  MinimalCoordinates coords_;
  MinimalDynamics dyn_;
  MinimalReactions reactions_;
  Layout layout_;
  SimTK::Vector normals_, zdot_;
  std::string loop_failure_;
  double loop_failure_time_ = 0;
};

// Largest |a - b| relative to max(largest |a|, floor) (0 when both vanish).
double relativeDifference(const SimTK::Vector& a, const SimTK::Vector& b, double floor = 0.0) {
  double diff = 0, scale = floor;
  for (int i = 0; i < a.size(); ++i) {
    diff = std::max(diff, std::abs(a[i] - b[i]));
    scale = std::max(scale, std::abs(a[i]));
  }
  return scale > 0 ? diff / scale : diff;
}

}  // namespace

RunResult simulateMinimal(const MultibodyModel& model, const RunControl& control) {
  const Scene& sc = model.scene();
  // Its closed-form loops turn one rigid crankshaft: a torsional chain would be held rigid without
  // a word (the scene parser refuses the pair; a caller that sets the formulation in code meets
  // this instead).
  if (model.crankshaftTorsion())
    throw std::invalid_argument(
        "multibody model: the minimal formulation turns one rigid crankshaft; the torsional chain "
        "(crankshaft.torsional_stiffness) needs simulation.formulation: constrained");
  const SimTK::MultibodySystem& system = model.system();
  RunResult run;
  run.model = "multibody";
  run.integrator = "cvode-adams (minimal coordinates)";
  run.effects = sc.effects();
  run.timeseries.columns = model.timeseriesColumns();
  if (sc.simulation.reactions) run.reactions.columns = model.reactionColumns();
  run.stats.formulation_self_check = 0.0;
  run.guide_normals = model.guideNormalsDescription();

  // The initial state from the closed forms (no projection, no constrained solve: O(n)), and,
  // with the lagged law, its normal-force states at the loop's solution (their fixed point).
  const SimTK::State s0 =
      model.closedFormState(sc.initial.crank_angle, sc.initial.crank_speed, sc.initial.twist);
  MinimalSystem ms(model, s0);
  const Layout& L = ms.layout();
  Eigen::VectorXd y0 = ms.pack(s0);
  if ((model.hasFrictionLagStates() && !ms.startLagStates(0.0, y0)) || !ms.set(0.0, y0.data())) {
    run.stats.complete = false;
    run.stats.status = statusAt("the run stopped", 0.0) + ": the " + ms.loopFailure();
    return run;
  }
  system.realize(ms.state(), SimTK::Stage::Dynamics);
  const EnergySnapshot e0 = model.energy(ms.state());

  // Tolerances: every state against its natural scale, the same scales as the reduced model's
  // (IntegrationScales.h), with the constrained formulation's weights for the twist (coupling
  // torque to accuracy·M_ref) and the friction normal forces (GuideFriction::setErrorWeights).
  const IntegrationScales scales = integrationScales(
      sc, model.options().prescribe_crank_speed ? model.options().crank_speed : std::numeric_limits<double>::quiet_NaN(),
      model.motorBreakdownTorque());
  const double rtol = scales.cvode_rtol, w_ref = scales.speed;
  const double w_sync = sc.motor.omega_sync / sc.reducer.ratio;
  // E_ref: kinetic energy of the machine at the reference speed (its work integrals' scale).
  SimTK::State kin = s0;
  {
    IndependentState x;
    x.crank_angle = y0(L.phi);
    x.crank_speed = w_ref;
    MinimalCoordinates(model, kin).apply(0.0, x, kin);
    system.realize(kin, SimTK::Stage::Velocity);
  }
  const double E_ref = std::max(system.calcKineticEnergy(kin), 1e-300);
  const int n_lag_states = model.hasFrictionLagStates() ? 2 * sc.carts.count : 0;
  OdeProblem p;
  p.t0 = 0.0;
  p.stop_time = sc.simulation.t_end;
  p.y0 = y0;
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
  // The motor element's z come first (MultibodyModel::buildForces): the law's states against
  // their natural magnitudes, then the brake work (an energy integral, atol as above).
  const int n_motor = model.motorStateCount();
  const int z_normals = L.z + n_motor;  // first friction normal force
  if (const MotorForce* motor = model.motorForce()) {
    const std::vector<double> scales = motor->law().stateScales();
    for (int i = 0; i < motor->lawStateCount(); ++i) p.atol(L.z + i) = rtol * scales.at(i);
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
  if (model.options().structured_jacobian) {
    const int n_normals = n_lag_states;
    p.jacobian.difference_quotient.assign(L.size, false);
    for (int i = 0; i < L.z; ++i) p.jacobian.difference_quotient[i] = true;
    if (const MotorForce* motor = model.motorForce())
      for (int i = 0; i < motor->lawStateCount(); ++i) p.jacobian.difference_quotient[L.z + i] = true;
    p.jacobian.diagonal = Eigen::VectorXd::Zero(L.size);
    if (n_normals > 0) {
      const double tau_N = sc.loads.guide_friction_lag;
      if (!(tau_N > 0.0) || !std::isfinite(tau_N))
        throw std::invalid_argument(
            "minimal formulation: loads.guide_friction.normal_force_lag must be a positive time [s], got " +
            std::to_string(tau_N));
      p.jacobian.diagonal.segment(z_normals, n_normals).setConstant(-1.0 / tau_N);
      // Energy integrals in EnergyMeter.h's order: motor work, damping, friction, load work
      // (then the reducer's losses).
      const int row_friction_dissipation = z_normals + n_normals + 2, first_normal = z_normals;
      p.jacobian.known_entries = [&ms, row_friction_dissipation, first_normal](
                                     double t, const double* y, Eigen::Ref<Eigen::MatrixXd> jac) {
        return ms.frictionPowerEntries(t, y, row_friction_dissipation, first_normal, jac);
      };
    }
  }
  // Cam drive: same step cap as the reduced model (ReducedIntegrators.cpp): the right-hand side
  // is constant over most of a stroke and an unbounded step leaps across a reversal.
  if (sc.hasCamDrive()) p.max_step = (M_PI / 6.0) / w_ref / 8.0;
  // Highest Adams-Moulton order 5: the friction normal-force lag puts an eigenvalue λ = -1/τ_N
  // (-500 1/s at 2 ms) in every run with guide friction, at hλ ≈ -0.5 ... -2 for the 1-4 ms
  // steps of accuracies 1e-4 ... 1e-8. Adams-Moulton's stability interval on the negative real
  // axis shrinks with the order (about [-1.8, 0] at order 5, [-1.2, 0] at 6, shorter above), so
  // a run that climbs above order 5 there is intermittently unstable in that mode, which its
  // error estimate sees only after the damage: measured on recuperative-2cart without gravity,
  // 1 s at accuracy 0.7e-10 ... 1.5e-10, coupling-torque error 1.9e-10 ... 7.2e-10 with order ≤ 5
  // against 4.2e-10 ... 2.9e-8 with order ≤ 12; balanced-4cart (10 s, accuracy 1e-2 ... 1e-6)
  // costs the same either way (CVODE seldom goes above order 5 there).
  p.max_order = 5;
  // A stiff motor law (motor/Stiffness.h: the space-phasor machine's electrical modes) switches
  // to BDF, with the same structured Newton matrix.
  const MotorForce* motor = model.motorForce();
  p.bdf = motor && lawIsStiff(&motor->law());
  if (p.bdf) run.integrator = "cvode-bdf (minimal coordinates)";
  p.rhs = [&ms](double t, const double* y, double* ydot) { return ms.rhs(t, y, ydot); };
  // The crank speed's extrema inside CVODE's steps, located on its own interpolant (a prescribed
  // speed has none).
  CrankSpeedExtremaFinder extrema;
  const CvodeIntegrator* stepping = nullptr;  // set once the integrator exists
  const int i_omega = L.omega;
  const CrankSpeedExtremaFinder::Dense dense = [&stepping, i_omega](double t, double& w, double& eps) {
    w = stepping->interpolate(t, 0, i_omega);
    eps = stepping->interpolate(t, 1, i_omega);
  };
  if (i_omega >= 0)
    p.on_step = [&](double t, const double* y, const double* ydot, bool after_step) {
      if (after_step && stepping) extrema.stepTo(t, y[i_omega], ydot[i_omega], dense);
      else extrema.restart(t, y[i_omega], ydot[i_omega]);
    };
  // Switching events of the starting method (motor/Supply.h): CVODE stops at the next timed one
  // (stop time) and at a speed-triggered one (root finding of ω_r - ω_switch on its
  // interpolant); the event is applied to y and CVODE restarts from there.
  const bool events = motor && !motor->supply().constant();
  double trigger_speed = std::nan("");
  const double ratio = sc.reducer.ratio;
  p.root = [&trigger_speed, &L, ratio](double, const double* y) {
    const double w_crank = L.omega >= 0 ? y[L.omega] : 0.0, w_twist = L.twist_rate >= 0 ? y[L.twist_rate] : 0.0;
    return ratio * (w_crank + w_twist) - trigger_speed;
  };
  CvodeIntegrator integ(p);
  stepping = &integ;
  auto arm = [&]() {
    const SupplyPhase phase = ms.phase();
    const double te = motor->supply().nextEventTime(phase);
    if (te > integ.time()) integ.setStopTime(std::min(te, sc.simulation.t_end));
    trigger_speed = motor->supply().triggerSpeed(phase);
    integ.enableRoot(!std::isnan(trigger_speed));
  };
  if (events) arm();

  StallDetector stall(sc.hasMotor(), w_sync);
  RestDetector rest(!sc.hasMotor() && !model.options().prescribe_crank_speed, sc.loads.velocity_smoothing);
  std::vector<double> cart_speeds(sc.carts.count);
  const std::vector<double> times = outputTimes(sc.simulation);
  std::vector<double> ts_row, re_row, re_simbody;
  SimTK::Vector udot_projected;
  const bool reactions = sc.simulation.reactions;
  const bool friction = model.hasGuideFriction();
  const int n_carts = sc.carts.count;
  // Every row's reactions come from the O(n) inverse-dynamics pass (MinimalReactions.h);
  // Simbody's constrained solve runs at every k-th row (simulation.self_check_interval, from row
  // 0) as the reference: accelerations, guide normal forces and every reaction column compared.
  const std::size_t check_interval = std::size_t(std::max(1, sc.selfCheckInterval()));
  {
    const std::vector<std::string> columns = model.reactionColumns();
    for (std::size_t i = 1; i < columns.size(); ++i) run.stats.reaction_self_check.push_back({columns[i], 0.0, 0.0});
  }
  // Compares Simbody's constrained solve at the row's state (realized to Acceleration) with the
  // projected accelerations, guide normal forces and O(n) reaction row of the same state.
  auto selfCheck = [&](const SimTK::State& s, const SimTK::Vector& udot_own, const SimTK::Vector& normals_own,
                       const std::vector<double>* own_row) {
    // Scale of the accelerations: their own, or ω2²·(1 rad) when the machine runs steadily and
    // its accelerations nearly vanish (a cam's constant-speed stretch: u̇ ~ 1e-7 from terms of
    // order ω2², whose round-off would otherwise read as a relative 1e-7).
    const double omega = model.crankSpeed(s);
    double check = relativeDifference(s.getUDot(), udot_own, omega * omega);
    model.observeReactions(s, re_simbody);
    if (friction) {
      SimTK::Vector normals_constrained(2 * n_carts);
      for (int j = 0; j < n_carts; ++j) {  // N_front_j, N_rear_j: reaction columns 1 + 6j, 2 + 6j
        normals_constrained[2 * j] = re_simbody[1 + 6 * j];
        normals_constrained[2 * j + 1] = re_simbody[2 + 6 * j];
      }
      check = std::max(check, relativeDifference(normals_constrained, normals_own));
    }
    if (std::isfinite(check))
      run.stats.formulation_self_check = std::max(run.stats.formulation_self_check, check);
    if (own_row) {
      for (std::size_t i = 1; i < re_simbody.size(); ++i) {
        ReactionCheck& c = run.stats.reaction_self_check[i - 1];
        c.max_difference = std::max(c.max_difference, std::abs((*own_row)[i] - re_simbody[i]));
        c.max_value = std::max(c.max_value, std::abs(re_simbody[i]));
      }
    }
    ++run.stats.self_check_rows;
    run.stats.constraint_error_max = std::max(run.stats.constraint_error_max, model.constraintError(s));
  };
  auto loopFailed = [&](double t) {
    run.stats.complete = false;
    run.stats.status = statusAt("the run stopped", t) + ": the " + ms.loopFailure();
    return false;
  };
  // Returns false when the run must stop (non-finite row, stall, interrupt, friction loop).
  auto record = [&](std::size_t k, double t, const Eigen::VectorXd& y) {
    if (!ms.set(t, y.data())) return loopFailed(t);
    const SimTK::State& s = ms.state();
    udot_projected = ms.dynamics().udot();
    model.observeMotion(s, udot_projected, ts_row);
    if (reactions) ms.reactionsRow(s, re_row);
    if (k % check_interval == 0) {
      const SimTK::Vector normals_own = friction ? ms.dynamics().guideNormals(s) : SimTK::Vector();
      const SimTK::Vector udot_own = udot_projected;
      const SimTK::State* constrained = ms.setConstrained(t, y.data());  // Simbody's full constrained solve
      if (!constrained) return loopFailed(t);
      selfCheck(*constrained, udot_own, normals_own, reactions ? &re_row : nullptr);
    }
    run.timeseries.rows.push_back(ts_row);
    if (reactions) run.reactions.rows.push_back(re_row);
    if (!rowIsFinite(ts_row) || (reactions && !rowIsFinite(re_row))) {
      run.stats.complete = false;
      run.stats.status = statusAt("numerical failure (non-finite value)", t);
      return false;
    }
    if ((!motor || Supply::fullSupply(motor->phase(s))) &&
        stall.update(t, model.crankAngle(s), model.crankSpeed(s), model.motorSpeed(s))) {
      run.stats.complete = false;
      run.stats.status = stall.status();
      return false;
    }
    if (motor && Supply::tripped(motor->phase(s))) {  // the soft starter gave up: a failed start
      run.stats.complete = false;
      run.stats.status = motor->supply().tripStatus(motor->supply().tripTime());
      return false;
    }
    for (int j = 0; j < n_carts; ++j) cart_speeds[j] = model.carts()[j].v(s);
    if (rest.update(t, cart_speeds, n_carts)) {
      run.stats.complete = false;
      run.stats.status = rest.status();
      return false;
    }
    return true;
  };

  const std::clock_t cpu0 = std::clock();
  bool go = record(0, times.front(), y0);
  double t_last = times.front();  // the last recorded row, whose state closes the energy audit
  Eigen::VectorXd y_last = y0;
  for (std::size_t k = 1; go && k < times.size(); ++k) {
    bool failed = false;
    while (true) {
      if (!integ.advanceTo(times[k])) {
        failed = true;
        break;
      }
      if (events) {
        Eigen::VectorXd y = integ.y();
        if (ms.applyEvents(integ.time(), y, integ.rootFound())) {
          integ.restart(integ.time(), y);
          arm();
        }
      }
      if (reachedOutputTime(integ.time(), times[k])) break;
    }
    if (failed) {
      run.stats.complete = false;
      if (!ms.loopFailure().empty())  // CVODE gave up on states where the friction loop has no solution
        run.stats.status = statusAt("the run stopped", ms.loopFailureTime()) + ": the " + ms.loopFailure();
      else
        run.stats.status = statusAt("integration failed", integ.time()) + ": " + integ.error();
      break;
    }
    go = record(k, times[k], integ.y());
    if (!go && !run.stats.complete && run.timeseries.rows.size() <= k) break;  // the row itself failed
    t_last = times[k];
    y_last = integ.y();
    if (go && control.progress) control.progress(times[k], sc.simulation.t_end);
    if (go && control.interrupt && control.interrupt->load()) {
      run.stats.complete = false;
      run.stats.status = statusAt("interrupted", times[k]);
      go = false;
    }
  }
  run.stats.cpu_seconds = double(std::clock() - cpu0) / CLOCKS_PER_SEC;
  run.crank_speed_extrema = extrema.takeUpTo(run.timeseries.rows.empty() ? t_last : run.timeseries.rows.back()[0]);
  run.stats.steps = integ.steps();
  run.stats.error_test_failures = integ.errorTestFailures();
  run.stats.realizations = integ.rhsEvaluations();
  run.stats.jacobian_evaluations = integ.jacobianEvaluations();
  run.stats.newton_convergence_failures = integ.newtonConvergenceFailures();
  if (!reactions) run.stats.reaction_self_check.clear();

  // The audit from the last recorded row's state (O(n): the evaluation state, realized to Dynamics).
  ms.set(t_last, y_last.data());
  system.realize(ms.state(), SimTK::Stage::Dynamics);
  run.energy = energyAuditBetween(e0, model.energy(ms.state()));
  return run;
}

}  // namespace rollerdyn
