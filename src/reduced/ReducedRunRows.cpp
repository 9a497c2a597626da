#include "reduced/ReducedRunRows.h"

#include <utility>

#include "physics/CouplingLaw.h"
#include "motor/MotorColumns.h"

namespace rollerdyn {
namespace {

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

// The carts' positions, speeds and accelerations (world x) into the timeseries row r [m, m/s, m/s²].
void setCartMotion(const ReducedModel& m, const ModelEvaluation& e, std::vector<double>& r) {
  const ColumnLayout& L = m.timeseriesLayout();
  for (int j = 0; j < m.cartCount(); ++j) {
    const CartEvaluation& c = e.carts[j];
    const double w = e.omega_crank;
    L.set(r, Column::x_cart, j + 1, c.pose.x_B);
    L.set(r, Column::v_cart, j + 1, c.pose.dx_B * w);
    L.set(r, Column::a_cart, j + 1, c.pose.d2x_B * w * w + c.pose.dx_B * e.eps_crank);
  }
}

}  // namespace

// Under the papers' constant η, L·ω = (1 − η)·M·u·ω.
double reducerLossesOf(const ReducedModel& m, double motor_work, double integrated) {
  if (!m.scene().motor.enabled) return 0.0;
  if (m.reducer().model == ReducerLossModel::PowerFlow) return integrated;
  return (1.0 / m.reducer().eta_forward - 1.0) * motor_work;
}

void setupTables(const ReducedModel& m, RunResult& res) {
  res.timeseries.columns = m.timeseriesLayout().names();
  if (m.scene().simulation.reactions) res.reactions.columns = m.reactionsLayout().names();  // else no reactions table
}

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
  setCartMotion(m, e, r);
  setMotorColumns(L, e.stator_current, e.supply, e.brake_torque, r);
  if (L.has(Column::reducer_loss_torque)) L.set(r, Column::reducer_loss_torque, e.reducer_loss_torque);
  if (L.has(Column::tooth_contact))
    L.set(r, Column::tooth_contact, static_cast<double>(toothContact(m.coupling(), e.twist)));
  res.timeseries.rows.push_back(std::move(r));
  if (!res.reactions.columns.empty()) res.reactions.rows.push_back(reactionsRow(m, t, e));
}

bool recordRows(const ReducedModel& m, double t, const ModelEvaluation& e, const SupplyPhase& phase,
                RunRecorder& recorder, RunResult& res, std::vector<double>& cart_speeds) {
  appendRows(m, t, e, res);
  const bool finite =
      rowIsFinite(res.timeseries.rows.back()) && (res.reactions.rows.empty() || rowIsFinite(res.reactions.rows.back()));
  for (int j = 0; j < m.cartCount(); ++j) cart_speeds[j] = e.carts[j].pose.dx_B * e.omega_crank;
  return recorder.check(t, finite, {e.phi_crank, e.omega_crank, e.omega_motor, &cart_speeds, &phase});
}

}  // namespace rollerdyn
