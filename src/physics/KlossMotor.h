// Induction motor torque by Kloss's formula, the one law both models use.
#pragma once

namespace rollerdyn {

struct KlossMotor;

// Rotor torque [N·m] at rotor speed ω_rotor [rad/s]:
//   M = 2·M_kr·s·s_kr / (s² + s_kr²),  s = 1 - ω_rotor/ω0        (Loveikin, Pochka, Romasevych (2018) eq. (37))
// This is eq. (37)'s 2·M_kr/(s/s_kr + s_kr/s) multiplied through by s·s_kr, so it is finite
// and smooth at s = 0 (synchronous speed), where eq. (37) as printed divides by zero; with
// s_kr = (ω0 - ω_kr)/ω0 it is also Loveikin and Pochka (2007) eq. (7). Negative slip gives generator torque.
double klossRotorTorque(const KlossMotor& motor, double omega_rotor);

// Motor torque reduced to the crank axis [N·m] at crank-axis speed ω1 [rad/s]:
//   M_n1 = M(u·ω1)·u·η                                          (Loveikin, Pochka, Romasevych (2018) eq. (37), Loveikin and Pochka (2007) eq. (8))
// η multiplies in both directions of power flow, as in the papers.
double klossCrankTorque(const KlossMotor& motor, double ratio, double efficiency, double omega_crank_axis);

}  // namespace rollerdyn
