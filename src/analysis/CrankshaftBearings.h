// The crankshaft as a beam on its main bearings (scene keys crankshaft.throw_positions and
// crankshaft.bearing_positions): each main bearing's reaction from the forces at the throws.
//
// Statics. The shaft is a straight beam along z on rigid supports at the bearings z_1 < ... < z_m
// (m ≥ 2), loaded by point forces in the plane normal to it (x and y separately: the beam is
// round, so the two planes are independent and alike). A force between two bearings, or beyond
// the outer ones (an overhung throw), is allowed: statics hold either way.
//  * m = 2: statically determinate, the lever rule R_1 = −P·(z_2 − z)/(z_2 − z_1),
//    R_2 = −P·(z − z_1)/(z_2 − z_1) (R the force of the bearing on the shaft).
//  * m > 2: a continuous beam, statically indeterminate; solved by the stiffness method with
//    Euler-Bernoulli (Hermite cubic) elements between consecutive load and support points, which
//    is exact for point loads. With one bending stiffness E·I along the whole shaft and rigid
//    supports E·I scales out of the reactions: they do not depend on its value (crankshaft.
//    bending_stiffness has no effect on them). Classic checks, two equal spans L: a load P at
//    the middle of each span gives 5/16, 11/8, 5/16 of P; one load P at the middle of the first
//    span gives 13/32, 11/16, −3/32 of P (the far bearing is pulled the other way).
//
// What loads the shaft at throw j (the forces reactions.csv holds): the rod's force on crank pin j
// (crankpin_x_j, crankpin_y_j), and under rods.model = split the half rod mass m_rod/2 on the pin,
// its d'Alembert force −m·a_pin and its weight −m·g·ŷ (a_pin from the crank's angle, speed and
// acceleration). Whatever else the resultant (bearing_x, bearing_y) holds is placed at mid-span
// between the outer bearings: in the multibody model that is the weight of the rotors' token
// masses on the axis (2 g in all, 0.02 N); the shaft's and the cranks' own weights are not in the
// model (the scenes give inertias, not masses), and the coupling passes a pure torque, no radial
// force. So Σ_k bearing_k = (bearing_x, bearing_y) at every row.
//
// Torque along the shaft: the crank pin's force acts at the pin, radius r at angle θ_j, and loads
// the shaft with T_j = x_pin·F_y − y_pin·F_x about z. The drive torque enters at the coupling end,
// taken as the end with the smallest z (positions are measured from the coupling side), so the
// shaft segment between the coupling and the k-th throw along z (counted from the coupling)
// carries the torque −Σ_{throws at or beyond it} T_j (the shaft's and cranks' own inertia torques
// left out: small against the rods'). The bending moment at a throw is the moment of all forces on
// one side of it: M(z) = Σ_{z_f < z} F·(z − z_f), |M| = hypot(M_x, M_y).
#pragma once

#include <string>
#include <vector>

#include "analysis/RunResult.h"
#include "analysis/SteadyState.h"
#include "scene/Scene.h"

namespace rollerdyn {

// The linear map from point loads to support reactions and bending moments of one shaft layout.
class ShaftBeam {
 public:
  // bearings ascending, at least two, distinct; load positions anywhere (any order, repeats
  // allowed). std::invalid_argument on a bad layout.
  ShaftBeam(std::vector<double> bearings, std::vector<double> load_positions);

  // R_k, the force of bearing k on the shaft, for loads P_i at the load positions (one component).
  std::vector<double> reactions(const std::vector<double>& loads) const;
  // Bending moment at position z, taking the forces (loads and reactions) on the side z' < z.
  double bendingMoment(const std::vector<double>& loads, const std::vector<double>& reactions, double z) const;

  const std::vector<double>& bearings() const { return bearings_; }
  const std::vector<double>& loadPositions() const { return loads_; }

 private:
  std::vector<double> bearings_, loads_;
  std::vector<std::vector<double>> influence_;  // influence_[k][i]: R_k per unit load i
};

// Whether the layout keys are given and the run's reactions allow the per-bearing columns; ""
// when they do, else why not (in the engineer's words, with what to do).
std::string crankshaftBearingsNotApplicable(const Scene& scene, const RunResult& run);

// Appends bearing_x_k, bearing_y_k (k = 1..m along z) to run.reactions when the scene gives the
// layout and the run has crank-pin forces; otherwise leaves the run as it is.
void appendBearingColumns(const Scene& scene, RunResult& run);

// Figures of the shaft over the steady window, for sizing.
struct CrankshaftSizing {
  bool given = false;      // the scene places throws and bearings (crankshaft.*)
  bool available = false;
  std::string reason;                      // why not available ("" when available)
  std::vector<double> bearing_positions;   // z_k [m]
  std::vector<int> throw_carts;            // carts in the order of their throws along z (1-based)
  std::vector<double> throw_positions;     // z of those throws [m]
  std::vector<double> bending_moment_peak; // per throw (same order): max |M| over the window [N·m]
  std::vector<double> segment_torque_peak; // per shaft segment k (coupling → first throw, then between
                                           // consecutive throws): max |T| over the window [N·m]
  bool chain_torques = false;  // the segments between throws carry the torsional chain's simulated
                               // torques (shaft_torque_k); else the quasi-static sum of the crank-pin
                               // forces' torques beyond the segment (the throws' inertia left out)
};

CrankshaftSizing sizeCrankshaft(const Scene& scene, const RunResult& run, const SteadyState& window);

}  // namespace rollerdyn
