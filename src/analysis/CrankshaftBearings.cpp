#include "analysis/CrankshaftBearings.h"

#include "analysis/ShaftTorsion.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

#include <Eigen/Dense>

#include "io/OutputColumns.h"

namespace rollerdyn {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Hermite cubic beam element of length L and E·I = 1: stiffness on (w1, θ1, w2, θ2).
Eigen::Matrix4d elementStiffness(double L) {
  const double L2 = L * L, L3 = L2 * L;
  Eigen::Matrix4d k;
  k << 12 / L3, 6 / L2, -12 / L3, 6 / L2,  //
      6 / L2, 4 / L, -6 / L2, 2 / L,       //
      -12 / L3, -6 / L2, 12 / L3, -6 / L2, //
      6 / L2, 2 / L, -6 / L2, 4 / L;
  return k;
}

// y(t) at the times tq (linear; both ascending); y itself when the grids are the same rows.
std::vector<double> onRows(const std::vector<double>& t, const std::vector<double>& y, const std::vector<double>& tq) {
  if (t == tq) return y;
  std::vector<double> out(tq.size(), kNaN);
  if (t.size() < 2) return out;
  std::size_t hi = 1;
  for (std::size_t i = 0; i < tq.size(); ++i) {
    while (hi + 1 < t.size() && t[hi] < tq[i]) ++hi;
    const double dt = t[hi] - t[hi - 1];
    const double f = dt > 0 ? std::clamp((tq[i] - t[hi - 1]) / dt, 0.0, 1.0) : 1.0;
    out[i] = y[hi - 1] + f * (y[hi] - y[hi - 1]);
  }
  return out;
}

// The forces on the shaft at every reactions row: per throw j (cart order) and the rest of the
// resultant at mid-span (CrankshaftBearings.h), with the pins' torques about the axis.
struct ShaftLoads {
  std::vector<std::vector<double>> px, py;  // [row][load]: throws 0..n-1, then the rest
  std::vector<std::vector<double>> torque;  // [row][throw]: T_j = x_pin·P_y − y_pin·P_x [N·m]
};

// The crank's angle, speed and acceleration at the reactions rows.
struct CrankOnRows {
  std::vector<double> phi, w, eps;
};

CrankOnRows crankOnRows(const RunResult& run, const std::vector<double>& t) {
  const std::vector<double> ts_t = run.timeseries.column("t");
  return {onRows(ts_t, run.timeseries.column("phi_crank"), t), onRows(ts_t, run.timeseries.column("omega_crank"), t),
          onRows(ts_t, run.timeseries.column("eps_crank"), t)};
}

// One component of every crank pin's force column (axis "x" or "y"), carts in order.
std::vector<std::vector<double>> pinForceColumns(const Table& rx, int n, const char* axis) {
  std::vector<std::vector<double>> f(n);
  for (int j = 0; j < n; ++j) f[j] = rx.column(std::string("crankpin_") + axis + "_" + std::to_string(j + 1));
  return f;
}

// The run's forces on the crank pins and main bearings, and the crank's motion, on the reactions rows.
struct PinForcesOnRows {
  std::vector<double> t, Rx, Ry;            // Rx, Ry: the main bearings' resultant [N]
  CrankOnRows crank;
  std::vector<std::vector<double>> fx, fy;  // [throw][row]: the rods' forces on the pins [N]
};

PinForcesOnRows pinForcesOnRows(const Scene& sc, const RunResult& run) {
  const Table& rx = run.reactions;
  const int n = sc.carts.count;
  PinForcesOnRows f;
  f.t = rx.column("t");
  f.Rx = rx.column("bearing_x");
  f.Ry = rx.column("bearing_y");
  f.crank = crankOnRows(run, f.t);
  f.fx = pinForceColumns(rx, n, "x");
  f.fy = pinForceColumns(rx, n, "y");
  return f;
}

// Row i of the shaft's loads: each throw's pin force less the inertia and weight of the rod mass
// m_pin [kg] the pin carries round with the shaft, its torque, and the rest of the resultant.
void fillRowLoads(ShaftLoads& L, std::size_t i, const Scene& sc, const PinForcesOnRows& f, double m_pin) {
  const int n = sc.carts.count;
  const double g = sc.loads.gravity, r = sc.crank.radius;
  const CrankOnRows& k = f.crank;
  double rest_x = f.Rx[i], rest_y = f.Ry[i];
  for (int j = 0; j < n; ++j) {
    const double th = k.phi[i] + sc.crankPhase(j), c = std::cos(th), s = std::sin(th);
    const double ax = r * (-k.eps[i] * s - k.w[i] * k.w[i] * c), ay = r * (k.eps[i] * c - k.w[i] * k.w[i] * s);
    const double Px = f.fx[j][i] - m_pin * ax, Py = f.fy[j][i] - m_pin * (ay + g);
    L.px[i][j] = Px;
    L.py[i][j] = Py;
    L.torque[i][j] = r * (c * Py - s * Px);
    rest_x += Px;  // Σ R = −Σ P: what the throws do not explain
    rest_y += Py;
  }
  L.px[i][n] = -rest_x;
  L.py[i][n] = -rest_y;
}

ShaftLoads shaftLoads(const Scene& sc, const RunResult& run) {
  const int n = sc.carts.count;
  const PinForcesOnRows f = pinForcesOnRows(sc, run);
  // rods.model = split: half the rod's mass sits on each crank pin and turns with the shaft.
  const double m_pin = (sc.rods.model == RodModel::Split && !sc.hasCamDrive()) ? 0.5 * sc.rods.mass : 0.0;
  ShaftLoads L;
  L.px.assign(f.t.size(), std::vector<double>(n + 1));
  L.py = L.px;
  L.torque.assign(f.t.size(), std::vector<double>(n));
  for (std::size_t i = 0; i < f.t.size(); ++i) fillRowLoads(L, i, sc, f, m_pin);
  return L;
}

std::vector<double> loadPositions(const Scene& sc) {
  std::vector<double> z = sc.crankshaft.throw_positions;
  const std::vector<double>& b = sc.crankshaft.bearing_positions;
  z.push_back(0.5 * (b.front() + b.back()));  // the rest of the resultant
  return z;
}

// Nodes: every distinct support and load position, ascending.
std::vector<double> beamNodes(const std::vector<double>& bearings, const std::vector<double>& loads) {
  std::vector<double> nodes = bearings;
  nodes.insert(nodes.end(), loads.begin(), loads.end());
  std::sort(nodes.begin(), nodes.end());
  const double span = nodes.back() - nodes.front();
  const double tol = 1e-12 * std::max(1.0, span);
  nodes.erase(std::unique(nodes.begin(), nodes.end(), [&](double a, double b) { return std::abs(a - b) <= tol; }),
              nodes.end());
  return nodes;
}

std::size_t nearestNode(const std::vector<double>& nodes, double z) {
  std::size_t best = 0;
  for (std::size_t q = 1; q < nodes.size(); ++q)
    if (std::abs(nodes[q] - z) < std::abs(nodes[best] - z)) best = q;
  return best;
}

// The beam's stiffness on (w, θ) of every node: the Hermite elements between the nodes, assembled.
Eigen::MatrixXd beamStiffness(const std::vector<double>& nodes) {
  const std::size_t N = nodes.size(), dofs = 2 * N;
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(dofs, dofs);
  for (std::size_t q = 0; q + 1 < N; ++q) K.block<4, 4>(2 * q, 2 * q) += elementStiffness(nodes[q + 1] - nodes[q]);
  return K;
}

// The beam held at its supports: its stiffness, the supports' and the free degrees of freedom
// (all but the deflection at the supports), and the free block's factorisation.
struct SupportedBeam {
  Eigen::MatrixXd K;
  std::vector<std::size_t> support_dof, free;
  Eigen::FullPivLU<Eigen::MatrixXd> lu;

  SupportedBeam(const std::vector<double>& nodes, const std::vector<double>& bearings) : K(beamStiffness(nodes)) {
    std::vector<bool> fixed(K.rows(), false);
    for (double z : bearings) {
      support_dof.push_back(2 * nearestNode(nodes, z));
      fixed[support_dof.back()] = true;
    }
    for (std::size_t d = 0; d < fixed.size(); ++d)
      if (!fixed[d]) free.push_back(d);
    Eigen::MatrixXd Kff(free.size(), free.size());
    for (std::size_t a = 0; a < free.size(); ++a)
      for (std::size_t b = 0; b < free.size(); ++b) Kff(a, b) = K(free[a], free[b]);
    lu.compute(Kff);
  }

  // The supports' forces on the beam under a unit load on degree of freedom `load_dof`: K·u = f + r.
  Eigen::VectorXd forcesUnderUnitLoad(std::size_t load_dof) const {
    Eigen::VectorXd f = Eigen::VectorXd::Zero(K.rows());
    f[load_dof] = 1.0;
    Eigen::VectorXd ff(free.size());
    for (std::size_t a = 0; a < free.size(); ++a) ff[a] = f[free[a]];
    const Eigen::VectorXd uf = lu.solve(ff);
    Eigen::VectorXd u = Eigen::VectorXd::Zero(K.rows());
    for (std::size_t a = 0; a < free.size(); ++a) u[free[a]] = uf[a];
    return K * u - f;
  }
};

}  // namespace

ShaftBeam::ShaftBeam(std::vector<double> bearings, std::vector<double> load_positions)
    : bearings_(std::move(bearings)), loads_(std::move(load_positions)) {
  if (bearings_.size() < 2) throw std::invalid_argument("ShaftBeam: at least two bearings");
  for (std::size_t k = 1; k < bearings_.size(); ++k)
    if (!(bearings_[k] > bearings_[k - 1])) throw std::invalid_argument("ShaftBeam: bearings must ascend");
  const std::vector<double> nodes = beamNodes(bearings_, loads_);
  const SupportedBeam beam(nodes, bearings_);
  influence_.assign(bearings_.size(), std::vector<double>(loads_.size(), 0.0));
  for (std::size_t i = 0; i < loads_.size(); ++i) {
    const Eigen::VectorXd r = beam.forcesUnderUnitLoad(2 * nearestNode(nodes, loads_[i]));
    for (std::size_t k = 0; k < bearings_.size(); ++k) influence_[k][i] = r[beam.support_dof[k]];
  }
}

std::vector<double> ShaftBeam::reactions(const std::vector<double>& loads) const {
  std::vector<double> R(bearings_.size(), 0.0);
  for (std::size_t k = 0; k < R.size(); ++k)
    for (std::size_t i = 0; i < loads_.size() && i < loads.size(); ++i) R[k] += influence_[k][i] * loads[i];
  return R;
}

double ShaftBeam::bendingMoment(const std::vector<double>& loads, const std::vector<double>& reactions,
                                double z) const {
  double M = 0;
  for (std::size_t i = 0; i < loads_.size() && i < loads.size(); ++i)
    if (loads_[i] < z) M += loads[i] * (z - loads_[i]);
  for (std::size_t k = 0; k < bearings_.size() && k < reactions.size(); ++k)
    if (bearings_[k] < z) M += reactions[k] * (z - bearings_[k]);
  return M;
}

std::string crankshaftBearingsNotApplicable(const Scene& sc, const RunResult& run) {
  if (!sc.crankshaft.given())
    return "the scene gives no bearing positions (crankshaft.bearing_positions, crankshaft.throw_positions): "
           "only the resultant of the main bearings is known";
  const Table& rx = run.reactions;
  if (!rx.has("t") || !rx.has("bearing_x") || !rx.has("crankpin_x_1"))
    return run.model == "reduced"
               ? "the reduced model computes no crank-pin forces, which the bearings' share needs (run the "
                 "multibody model)"
               : "the run has no crank-pin forces (simulation.reactions: false)";
  for (const char* c : {"t", "phi_crank", "omega_crank", "eps_crank"})
    if (!run.timeseries.has(c)) return std::string("the run's time series lacks ") + c;
  return "";
}

void appendBearingColumns(const Scene& sc, RunResult& run) {
  if (!crankshaftBearingsNotApplicable(sc, run).empty()) return;
  const ShaftBeam beam(sc.crankshaft.bearing_positions, loadPositions(sc));
  const ShaftLoads L = shaftLoads(sc, run);
  const std::size_t m = beam.bearings().size();
  Table& rx = run.reactions;
  for (std::size_t k = 1; k <= m; ++k)
    for (Column c : {Column::main_bearing_x, Column::main_bearing_y})
      rx.columns.push_back(numberedColumnName(c, int(k)));
  for (std::size_t i = 0; i < rx.rows.size(); ++i) {
    const std::vector<double> Rx = beam.reactions(L.px[i]), Ry = beam.reactions(L.py[i]);
    for (std::size_t k = 0; k < m; ++k) {
      rx.rows[i].push_back(Rx[k]);
      rx.rows[i].push_back(Ry[k]);
    }
  }
}

namespace {

// The throws in their order along the shaft (stable: equal positions keep the cart order); each
// throw's cart (1-based) and position go into `out`. Returns the carts' indices in that order.
std::vector<int> throwsAlongShaft(const Scene& sc, CrankshaftSizing& out) {
  std::vector<int> order(sc.carts.count);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return sc.crankshaft.throw_positions[a] < sc.crankshaft.throw_positions[b];
  });
  for (int j : order) {
    out.throw_carts.push_back(j + 1);
    out.throw_positions.push_back(sc.crankshaft.throw_positions[j]);
  }
  return order;
}

// One reactions row's bending moment at each throw and torque of each segment, into the peaks.
// `split_torque`: the segments' torques follow from the pins' (not for a cam drive, whose force
// does not act at the crank radius).
void widenThrowPeaks(CrankshaftSizing& out, const ShaftBeam& beam, const ShaftLoads& L, std::size_t i,
                     const std::vector<int>& order, bool split_torque) {
  const std::vector<double> Rx = beam.reactions(L.px[i]), Ry = beam.reactions(L.py[i]);
  double beyond = 0;  // −Σ T_j over the throws at or beyond the segment, from the far end
  for (int q = int(order.size()) - 1; q >= 0; --q) {
    const int j = order[q];
    const double M = std::hypot(beam.bendingMoment(L.px[i], Rx, out.throw_positions[q]),
                                beam.bendingMoment(L.py[i], Ry, out.throw_positions[q]));
    beyond -= L.torque[i][j];
    double& pm = out.bending_moment_peak[q];
    if (std::isfinite(M)) pm = std::isfinite(pm) ? std::max(pm, M) : M;
    if (split_torque && !(out.chain_torques && q >= 1) && std::isfinite(beyond)) {
      double& pt = out.segment_torque_peak[q];
      pt = std::isfinite(pt) ? std::max(pt, std::abs(beyond)) : std::abs(beyond);
    }
  }
}

// The peaks over the reactions rows inside the steady window; false when the window holds none.
bool widenOverSteadyRows(CrankshaftSizing& out, const Scene& sc, const RunResult& run, const SteadyState& w,
                         const std::vector<int>& order) {
  const ShaftBeam beam(sc.crankshaft.bearing_positions, loadPositions(sc));
  const ShaftLoads L = shaftLoads(sc, run);
  const std::vector<double> t = run.reactions.column("t");
  bool any = false;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (!(t[i] >= w.t_begin && t[i] <= w.t_end)) continue;
    widenThrowPeaks(out, beam, L, i, order, !sc.hasCamDrive());
    any = true;
  }
  return any;
}

// Why the shaft cannot be sized from this run ("" when it can): the bearings' share needs the
// crank-pin forces, and the peaks a steady window.
std::string crankshaftSizingNotApplicable(const Scene& sc, const RunResult& run, const SteadyState& w) {
  const std::string reason = crankshaftBearingsNotApplicable(sc, run);
  if (!reason.empty()) return reason;
  if (!w.reached) return "no steady window (steady state not reached): run longer (simulation.t_end)";
  return "";
}

}  // namespace

CrankshaftSizing sizeCrankshaft(const Scene& sc, const RunResult& run, const SteadyState& w) {
  CrankshaftSizing out;
  out.given = sc.crankshaft.given();
  out.bearing_positions = sc.crankshaft.bearing_positions;
  out.reason = crankshaftSizingNotApplicable(sc, run, w);
  if (!out.reason.empty()) return out;
  const int n = sc.carts.count;
  const std::vector<int> order = throwsAlongShaft(sc, out);
  out.bending_moment_peak.assign(n, kNaN);
  // A cam's force does not act at the crank radius: no torque split for a cam drive.
  out.segment_torque_peak.assign(n, kNaN);
  // A torsional chain's segments between throws carry the springs' torques the run simulated
  // (their throws' inertia included), whose steady peaks ShaftTorsion.h computes once; the segment
  // from the coupling to the first throw is rigid.
  const ShaftTorsionSummary torsion = computeShaftTorsion(sc, run, w, true);
  out.chain_torques = torsion.applies;
  if (!widenOverSteadyRows(out, sc, run, w, order)) {
    out.reason = "no reactions row in the steady window";
    return out;
  }
  for (int q = 1; out.chain_torques && q < n; ++q)
    out.segment_torque_peak[q] = torsion.segments[q - 1].torque_peak_steady;
  out.available = true;
  return out;
}

}  // namespace rollerdyn
