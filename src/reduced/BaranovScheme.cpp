#include "reduced/BaranovScheme.h"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <stdexcept>
#include <vector>

#include <Eigen/Core>

#include "analysis/CrankSpeedExtrema.h"
#include "analysis/OutputGrid.h"
#include "analysis/RunRecorder.h"
#include "analysis/StallDetector.h"
#include "reduced/ReducedRunRows.h"

namespace rollerdyn {
namespace {

void checkSchemeApplies(const ReducedModel& m) {
  if (!m.rigid())
    throw std::invalid_argument(
        "reduced.integrator = baranov needs coupling.type = rigid (the scheme of Loveikin and Pochka (2007) eq. (4) "
        "is for the one-mass model)");
  if (!(m.scene().reduced.baranov_step > 0.0)) throw std::invalid_argument("reduced.baranov_step must be > 0");
  if (!m.supply().constant() || m.motorStateCount() > 0)
    throw std::invalid_argument(
        "reduced.integrator = baranov steps in crank angle with a torque that depends on the speed alone: it takes "
        "neither a starting method that switches in time (motor.start, motor.stop) nor a motor model with states "
        "(motor.model kloss_dynamic, park); use reduced.integrator = cvode");
}

// The crank speed after one step Δφ from ω (inertia J_i there, J_next at its end) under the
// torque M = M_p(ω_i) - M_o(φ_i); 0 or less (or not finite) when the drive cannot go on.
double nextSpeed(double w, double J_i, double J_next, double M, double dphi) {
  if (w > 0.0) return M / (J_i * w) * dphi + (3.0 * J_i - J_next) / (2.0 * J_i) * w;  // Loveikin and Pochka (2007) eq. (4)
  // From rest eq. (4) divides by ω = 0, and starting it at a tiny ω instead would return
  // ω_1 ≈ M·Δφ/(J·ω_tiny), a huge overshoot. The first step therefore uses eq. (2) before
  // its division by ω, i.e. the energy theorem over one step: J_1·ω_1² = J_0·ω_0² + 2·M·Δφ.
  const double w2 = (J_i * w * w + 2.0 * M * dphi) / J_next;
  return w2 > 0.0 ? std::sqrt(w2) : 0.0;
}

// The work integrals by the same left-point rule as the scheme: dW = (force·x_B')·Δφ [J].
struct SchemeWork {
  double motor = 0, friction = 0, load = 0, friction_kinetostatic = 0, reducer = 0;
  void addStep(const ReducedModel& m, const ModelEvaluation& e, double w, double dphi) {
    motor += e.motor_torque * dphi;
    reducer += e.reducer_loss_torque * dphi;
    if (w > 0.0) friction_kinetostatic += e.friction_power_kinetostatic / w * dphi;  // P/ω·Δφ
    for (int j = 0; j < m.cartCount(); ++j) {
      const CartEvaluation& c = e.carts[j];
      const double sigma = m.scene().carts.side[j];
      friction -= sigma * c.statics.friction * c.pose.dx_B * dphi;
      load -= sigma * c.roller_force * c.pose.dx_B * dphi;
    }
  }
};

// The scheme's state at a node: crank angle φ [rad], speed ω [rad/s], time t [s].
struct Node {
  double phi = 0, w = 0, t = 0;
  Eigen::VectorXd state(const ReducedModel& m) const {
    Eigen::VectorXd y = Eigen::VectorXd::Zero(m.stateSize());
    y(m.iPhi()) = phi;
    y(m.iOmega()) = w;
    return y;
  }
};

// The output rows on the grid inside each step, through the stop rules every run shares.
class SchemeRows {
 public:
  SchemeRows(const ReducedModel& m, RunResult& res, const RunControl& control)
      : m_(m), res_(res), times_(outputTimes(m.scene().simulation)),
        recorder_(m.scene(), &m.supply(), false, res, control), phase_(m.supply().initialPhase()),
        cart_speeds_(m.cartCount()) {}
  double tEnd() const { return times_.back(); }
  RunRecorder& recorder() { return recorder_; }

  // Rows on the output grid inside [from.t, t_next]: ω linear in time across the step, the
  // assumption behind the trapezoidal time of eq. (10), so ε = eq. (11) is constant and φ is
  // its integral, quadratic in time. It reaches φ_next at t_next exactly because of eq. (10);
  // interpolating φ linearly instead made the rows' φ disagree with ∫ω dt by up to Δφ/4.
  // False when a stop rule ended the run at one of them.
  bool emitUpTo(const Node& from, double t_next, double phi_next, double w_next, double eps) {
    const double phi = from.phi, w = from.w, t = from.t;
    while (k_out_ < times_.size() && times_[k_out_] <= t_next) {
      const double a = (t_next > t) ? (times_[k_out_] - t) / (t_next - t) : 1.0;
      const double tau = a * (t_next - t);
      Eigen::VectorXd yo = Eigen::VectorXd::Zero(m_.stateSize());
      yo(m_.iPhi()) = (a < 1.0) ? phi + w * tau + 0.5 * eps * tau * tau : phi_next;
      yo(m_.iOmega()) = w + a * (w_next - w);
      ModelEvaluation e = m_.evaluate(yo);
      ++res_.stats.realizations;
      e.eps_crank = e.eps_motor = eps;
      e.coupling_torque = e.motor_torque - m_.motorSideInertia() * eps;
      const double t_out = times_[k_out_++];
      if (!recordRows(m_, t_out, e, phase_, recorder_, res_, cart_speeds_)) return false;
    }
    return true;
  }

 private:
  const ReducedModel& m_;
  RunResult& res_;
  const std::vector<double> times_;
  RunRecorder recorder_;
  const SupplyPhase phase_;  // constant: the scheme takes no switching
  std::vector<double> cart_speeds_;
  std::size_t k_out_ = 0;  // next output time to fill
};

// The energy audit at the last node (at or just past t_end, or at the stall).
void closeAudit(const ReducedModel& m, const Node& last, const SchemeWork& W, RunResult& res) {
  const Eigen::VectorXd y = last.state(m);
  res.energy.motor_work = W.motor;
  res.energy.reducer_losses = reducerLossesOf(m, W.motor, W.reducer);
  res.energy.friction_dissipation = W.friction;
  res.energy.load_work = W.load;
  res.energy.kinetic_final = m.kineticEnergy(y);
  res.energy.potential_final = m.potentialEnergy(y);
  if (m.checksFrictionWork()) res.friction_work_kinetostatic = W.friction_kinetostatic;
}

// The first node: the initial crank angle and speed at t = 0, and the energies there.
Node startNode(const ReducedModel& m, RunResult& res) {
  const Scene& s = m.scene();
  Node node;
  node.phi = s.initial.crank_angle;
  node.w = std::max(s.initial.crank_speed, 0.0);  // the scheme only marches forward in φ
  const Eigen::VectorXd y = node.state(m);
  res.energy.kinetic_initial = m.kineticEnergy(y);
  res.energy.potential_initial = m.potentialEnergy(y);
  return node;
}

// The scheme's march in φ, node to node one step dφ apart (Loveikin and Pochka (2007) eq. (10),
// (11)): the rows inside each step, the works, and the crank speed's extrema.
class BaranovMarch {
 public:
  BaranovMarch(const ReducedModel& m, const Node& start, SchemeRows& rows, RunResult& res)
      : m_(m), dphi_(m.scene().reduced.baranov_step), rows_(rows), res_(res), node_(start),
        J_i_(m.reducedInertia(start.phi)) {}

  // Steps until the end time, a stop rule, a failed friction loop or a stall.
  void run() {
    while (node_.t < rows_.tEnd() && step()) {
    }
  }
  bool stalled() const { return stalled_; }
  const Node& lastNode() const { return node_; }
  const SchemeWork& work() const { return work_; }
  std::vector<CrankSpeedExtremum> extremaUpTo(double t) { return extrema_.takeUpTo(t); }

 private:
  // One step from node_; false when the run ends in it.
  bool step() {
    const ModelEvaluation e = m_.evaluate(node_.state(m_));
    ++res_.stats.realizations;
    if (!frictionLoopSolved(e)) return false;
    const double J_next = m_.reducedInertia(node_.phi + dphi_);
    const double w = node_.w, w_next = nextSpeed(w, J_i_, J_next, e.motor_torque - e.load_torque, dphi_);
    if (!(w_next > 0.0) || !std::isfinite(w_next)) {
      stalled_ = true;  // the scheme cannot stop or reverse: the drive has stalled
      return false;
    }
    const double t_next = node_.t + 2.0 * dphi_ / (w + w_next);  // Loveikin and Pochka (2007) eq. (10)
    const double eps = (w_next - w) / (t_next - node_.t);         // Loveikin and Pochka (2007) eq. (11)
    work_.addStep(m_, e, w, dphi_);
    const bool go = rows_.emitUpTo(node_, t_next, node_.phi + dphi_, w_next, eps);
    recordExtremum(w, w_next);
    node_ = {node_.phi + dphi_, w_next, t_next};
    J_i_ = J_next;
    ++res_.stats.steps;
    return go;  // false: a stop rule ended the run at a row inside this step
  }

  // Whether the evaluation at node_ solved its guide-friction loop; if not, the run stops there.
  bool frictionLoopSolved(const ModelEvaluation& e) {
    if (e.friction_loop.status == LoopStatus::Solved) return true;
    rows_.recorder().fail(statusAt("the run stopped", node_.t) + ": the " + describeLoopFailure(e.friction_loop));
    return false;
  }

  // The scheme's ω is linear within each step (eq. (10), (11)): its extrema lie on the nodes,
  // where the slope changes sign; w at node_, w_next at the next node [rad/s].
  void recordExtremum(double w, double w_next) {
    if ((slope_before_ < 0.0 && w_next > w) || (slope_before_ > 0.0 && w_next < w)) extrema_.record(node_.t, w);
    if (w_next != w) slope_before_ = w_next - w;
  }

  const ReducedModel& m_;
  const double dphi_;
  SchemeRows& rows_;
  RunResult& res_;
  Node node_;
  double J_i_;
  SchemeWork work_;
  CrankSpeedExtremaFinder extrema_;
  double slope_before_ = 0.0;
  bool stalled_ = false;
};

}  // namespace

RunResult runBaranov(const ReducedModel& m, RunResult res, const RunControl& control) {
  checkSchemeApplies(m);
  const std::clock_t c0 = std::clock();
  const Node start = startNode(m, res);
  SchemeRows rows(m, res, control);
  BaranovMarch march(m, start, rows, res);
  march.run();
  res.stats.cpu_seconds = double(std::clock() - c0) / CLOCKS_PER_SEC;
  res.crank_speed_extrema = march.extremaUpTo(res.timeseries.rows.empty() ? 0.0 : res.timeseries.rows.back()[0]);
  if (march.stalled()) rows.recorder().fail(StallDetector::statusAt(march.lastNode().t));
  closeAudit(m, march.lastNode(), march.work(), res);
  return res;
}

}  // namespace rollerdyn
