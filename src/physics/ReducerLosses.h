// The reducer's losses, the one law both models apply (reducer.losses).
//
// Where the reducer sits in these models. The motor side is one lumped body, J_n1 =
// (J_p + J_m + J_red)·δ·u² (Loveikin, Pochka, Romasevych (2018) eq. (1)): rotor, coupling hub
// and the reducer's own inertia turn together, and the elastic element c, k (reduced to the
// crank axis) joins that body to the crankshaft; in the one-mass model (Loveikin and Pochka
// (2007)) everything is one body. The papers apply η to the motor's torque, M_n1 = M·u·η
// (eq. (37) and (2007) eq. (8)), before it reaches any inertia or the coupling: in the model the
// reducer sits between the motor and the coupling, and the torque it transmits is the motor's
// torque M at the rotor (plus a brake's on the same shaft). The law is applied there, in both
// models; the power through it is P = M·ω_r, positive while the motor drives, negative while the
// crank side drives the rotor above synchronous speed (the motor generates). (A physical
// coupling on the motor shaft would put the reducer between coupling and crank, where it carries
// the coupling torque, motor-side inertia torque included; the papers' lumping leaves that out.)
//
// papers:     T = M·u·η whatever the sign of P. While the crank side drives (P < 0) the motor
//             side then receives |M·u·η·ω| < |M·ω_r|: the reducer creates (1 − η)·|P|.
// power_flow: Modelica's LossyGear (Modelica Standard Library, Rotational.Components.LossyGear):
//             T = η_f·M·u while the motor side drives (loss (1 − η_f)·|P|) and T = M·u/η_r while
//             the crank side drives (the crank must supply |P|/η_r: loss (1/η_r − 1)·|P|).
//
// The smooth transition. At P = 0 the exact law switches between two slopes; a variable-step
// integrator sees that kink at every reversal (several per crank revolution) and cuts its step,
// and an event-located switch would add two events per reversal. The law is therefore written
// as a loss torque that is C∞ and never does negative work:
//   L = σ(ω)·a(T)·k(σ(ω)·T),  T = M·u (the ideal torque at the crank axis), ω the motor side's
//   speed at the crank axis,
//   σ(ω) = tanh(ω/ω_b)                 sign of the speed (Coulomb-type regularisation at rest),
//   a(T) = T·tanh(T/T_b) ≥ 0           |T| smoothed over T_b, a(0) = 0,
//   k(x) = k_f·w + k_r·(1 − w),  w = ½(1 + tanh(x/T_b)),  k_f = 1 − η_f,  k_r = 1/η_r − 1,
// and the torque passed on at the crank axis is T − L. The loss power L·ω = ω·σ(ω)·a·k ≥ 0 for
// every T and ω (each factor is ≥ 0), the law is continuous with all its derivatives, and for
// |T| ≫ T_b, |ω| ≫ ω_b it is LossyGear's to within e^(−2|T|/T_b) (3·10⁻⁴ at |T| = 4·T_b).
// Widths:
//   T_b = 0.01·M_kr·u (1 % of the breakdown torque at the crank, the torque scale the integrators
//       already use). The slopes inside the band stay those of the law (|dL/dT| ≤ 1.2·max(k_f,
//       k_r)), only the curvature grows as 1/T_b, so the integrator resolves a reversal with a
//       few shorter steps and no event; and the deviation from LossyGear is confined to
//       |T| < 4·T_b, i.e. below 4 % of the breakdown torque, passed in a few ms per reversal
//       (the recuperative 2-cart drive's torque changes by ≈ 2.5 kN·m in 0.1 s): its share of
//       the energy is below 10⁻³ of the motor's work.
//   ω_b = 10⁻³·ω0/u (0.1 % of synchronous speed at the crank axis). It acts only at rest, where
//       the direction of the power flow is undefined: a start passes it in a millisecond or so,
//       a coast-down likewise; while running (ω ≈ ω0/u) σ = 1 to double precision.
// With these the forward law is monotone (T − L increases with T) for η_f > 0.17, η_r > 0.55.
#pragma once

#include <string>

#include "scene/Scene.h"

namespace rollerdyn {

struct ReducerLaw {
  ReducerLossModel model = ReducerLossModel::Papers;
  double ratio = 1;        // u [-]
  double eta_forward = 1;  // η (papers) or η_f, motor side driving [-]
  double eta_reverse = 1;  // η_r, crank side driving (power_flow) [-]
  double torque_band = 1;  // T_b, at the crank axis [N·m]
  double speed_band = 1;   // ω_b, at the crank axis [rad/s]
};

// The scene's reducer law (reducer.*; the bands from the motor's breakdown torque M_kr [N·m at
// the rotor, of the law the run uses: motor/BreakdownTorque.h] and synchronous speed as argued
// above).
ReducerLaw reducerLaw(const Scene& scene, double breakdown_torque);

// Torque the reducer passes on at the crank axis [N·m] for a torque M at its motor shaft [N·m]
// and the motor side's speed ω at the crank axis [rad/s]: papers M·u·η; power_flow M·u − L.
double reducerCrankTorque(const ReducerLaw& law, double shaft_torque, double omega_crank_axis);

// Loss torque L at the crank axis [N·m]: M·u minus the torque passed on. The loss power is L·ω
// [W]: ≥ 0 under power_flow; under papers (1 − η)·M·u·ω, negative while the crank side drives.
double reducerLossTorque(const ReducerLaw& law, double shaft_torque, double omega_crank_axis);

// The motor's torque at the rotor [N·m] from what a run records: the torque passed on at the
// crank axis and the loss torque (papers: M_crank/(u·η), the loss column is not read).
double reducerShaftTorque(const ReducerLaw& law, double crank_torque, double loss_torque);

// One line for the user: which loss law the run used, e.g. "the papers' constant η = 0.9 ...".
std::string reducerLossWords(const ReducerLaw& law);

}  // namespace rollerdyn
