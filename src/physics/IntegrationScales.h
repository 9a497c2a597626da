// The natural magnitude of each state of the drive, from its scene, for both models' error
// control: every integrator holds each state to its tolerance times its own scale, so
// simulation.accuracy means the same error in the multibody and the reduced model (the copies
// once drifted: one model's torque scale read the cam's stroke, the other's did not, and the
// reduced model's CVODE ran 100 times looser than the multibody model's, its crank speed off by
// 2000·accuracy in a rocking star-delta start where the multibody model's was within 10·accuracy).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "scene/Scene.h"

namespace rollerdyn {

// CVODE's error control (local error, weighted RMS norm over the states) lets the crank speed
// drift ~100-250x further from the exact solution than Simbody's Runge-Kutta-Merson at the same
// nominal accuracy (balanced-4cart, 10 s, crank-speed error against a run at 1e-12: constrained
// formulation 3.0e-8, minimal 7.5e-6 at 1e-6; 2.5e-10 / 5.4e-8 at 1e-8). So that
// simulation.accuracy means about the same error in every integrator, CVODE gets a relative
// tolerance 100 times tighter.
constexpr double kAccuracyToCvodeTolerance = 0.01;

struct IntegrationScales {
  double cvode_rtol;  // CVODE's relative tolerance, kAccuracyToCvodeTolerance·simulation.accuracy [-]
  double angle;       // crank angle φ: 1 rad (an error of rtol rad is negligible against a revolution) [rad]
  double speed;       // crank speed φ̇: ω_ref, the synchronous crank speed ω0/u; a prescribed speed,
                      // or with the motor off max(|φ̇(0)|, 1 rad/s) [rad/s]
  double torque;      // M_ref, the larger of the breakdown torque at the crank M_kr·u·η and the
                      // roller-force torque Σ_j (F_j1+F_j2)·max(r, cam stroke), at least 1 [N·m at the crank]
  double twist;       // ψ_ref = M_ref/c, the twist the coupling takes under the scene's largest
                      // torques [rad]; 0 for a rigid coupling
  double twist_rate;  // ψ_ref·√(c/J_n1), the coupling's own time scale [rad/s]; 0 for a rigid coupling
  // Largest step of a cam drive (Loveikin and Pochka (cam drive paper)) [s]; 0: unbounded. In
  // steady state its right-hand side is exactly constant over the constant-speed 2/3 of every
  // stroke, so an unbounded step grows until it leaps from one constant segment to the next
  // across the reversal without its error estimate ever seeing it (measured: the speed froze
  // while ε = 160 rad/s² at every reversal). The cap: 1/8 of the shortest segment, a crank angle
  // of π/6 at the reference speed.
  double max_step;
};

// Whether an integrator stopped at t_reached (a switching event's time) has reached the output time
// t_out: up to a few units of roundoff, a gap CVODE refuses to step across (CV_TOO_CLOSE). A
// converter ramp ending at t_on + t_ramp = 0.65 + 2.4 s fell 4e-16 s short of the output row
// 610·0.005 s, and both models stopped there with an integrator failure.
inline bool reachedOutputTime(double t_reached, double t_out) {
  return t_reached >= t_out - 64 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(t_out));
}

// `prescribed_crank_speed`: a crank speed the run imposes (a kinematic run), NaN when none;
// `breakdown_torque`: M_kr of the motor law the run uses [N·m at the rotor]
// (motor/BreakdownTorque.h: a circuit motor's own, not the Kloss key).
IntegrationScales integrationScales(const Scene& scene, double prescribed_crank_speed, double breakdown_torque);

}  // namespace rollerdyn
