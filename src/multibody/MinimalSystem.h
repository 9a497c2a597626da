// The multibody model's minimal formulation as an ODE in its independent coordinates: the
// integrated vector's layout, and the one evaluation context (State, closed-form loops, projected
// dynamics, O(n) reactions) that the right-hand side, the output rows and the events share.
// MinimalSimulation.cpp integrates it with CVODE.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "multibody/GuideFriction.h"
#include "multibody/MinimalCoordinates.h"
#include "multibody/MinimalDynamics.h"
#include "multibody/MinimalReactions.h"
#include "multibody/MotorForce.h"
#include "multibody/MultibodyModel.h"

namespace rollerdyn {

// Layout of the integrated vector y = [φ2, twist?, φ̇2?, twist rate?, z...].
struct MinimalLayout {
  int phi = 0, twist = -1, omega = -1, twist_rate = -1, z = 0, size = 0;
  MinimalLayout(const MinimalCoordinates& c, int nz) {
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

  const MinimalLayout& layout() const { return layout_; }
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
  // state (MinimalSimulation.cpp: the structured Jacobian).
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
  MinimalLayout layout_;
  SimTK::Vector normals_, zdot_;
  std::string loop_failure_;
  double loop_failure_time_ = 0;
};

}  // namespace rollerdyn
