// Direction laws of the technological loads, shared by both models.
#pragma once

namespace rollerdyn {

struct Loads;

// Smoothed sign of a velocity: tanh(v / v_s). A hard sign(v) would make the right-hand side
// discontinuous at every velocity reversal and force an adaptive integrator to crawl through
// it; v_s (loads.velocity_smoothing) is small against the carts' ~2 m/s peak speed, so the
// load is at full value except within a few v_s of reversal.
double smoothSign(double v, double v_s);

// Total horizontal compacting-roller force on a cart along the cart's local +x' axis (pointing
// away from the shaft) [N], given the cart's local velocity v' [m/s]:
//   opposes_velocity: -(F_j1 + F_j2)·sign(v')  (rolling resistance, the reading of Loveikin and Pochka (2007) eq. (5))
//   as_printed:       +(F_j1 + F_j2)           (Loveikin, Pochka, Romasevych (2018) fig. 3 and eq. (10): constant direction)
// plus, in either reading, the rolling resistance of the rollers in the mix
//   -μ_r·(R_j1 + R_j2)·sign(v')               (loads.rolling_resistance; 0 unless given)
// As printed, the force keeps its direction while the cart reverses, so over a stroke and back it
// does no net work (a constant force is conservative): compaction then costs the motor nothing.
// A real roller dissipates the energy that compacts the mix; μ_r (or the other reading) says how
// much: a cart absorbs on average μ_r·(R_j1 + R_j2)·mean|v'| (docs/loads.md).
double rollerHorizontalForce(const Loads& loads, double v_local);

// Power the technological load of one cart absorbs [W]: -H(v')·v' (positive when it takes energy
// from the drive), H from rollerHorizontalForce.
double rollerLoadPower(const Loads& loads, double v_local);

// Direction factor of the guide friction along local x': friction = factor·f·(|N_front| + |N_rear|).
// Guide friction always opposes the cart's velocity (it is friction, whatever the reading of the
// roller forces), so the factor is -sign(v').
double frictionDirection(const Loads& loads, double v_local);

}  // namespace rollerdyn
