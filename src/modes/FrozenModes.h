// Frozen-angle modes: the drive linearized about its steady motion at one crank angle, with the
// coefficients held ("frozen") at that angle, as if the crank stood still in that position while
// the drive vibrated. At each angle φ2:
//   M(φ2)·δν̈ + C·δν̇ + K·δν = 0,    δν = (δφ2, δψ)
// with M the mass matrix (DriveModels.h: the reduced model's J_n1, J_n2(φ2), or Simbody's tree
// mass matrix projected on the independent coordinates) and
//   K = -M·∂ν̈/∂ν,  C = -M·∂ν̈/∂ν̇    (central differences of each model's own accelerations)
// so K holds the coupling stiffness c and the loads' and inertia's dependence on the crank angle
// at the operating speed; C the coupling damping k, the motor's torque-speed slope and the
// Coriolis term ½·J_n2'(φ2)·φ̇2² differentiated in φ̇2. Natural frequencies p_i = √λ_i with λ_i the
// eigenvalues of M⁻¹K; with a constant inertia and no angle-dependent load the torsional one is
// Dyomin's p0 = √(c(J1 + J2)/(J1·J2)) (Dyomin (two rotors) eq. (10)).
//
// Mode shapes are named by what moves: each mode's kinetic energy ½·δν̇ᵀMδν̇ is split into the
// motor side (motor, coupling hub, reducer: J_n1·δφ1², δφ1 = δφ2 + δψ), the carts
// (Σ m_B·x_B'²·δφ2²) and the crankshaft with the rods (the rest of J_n2·δφ2²).
//
// A frozen analysis ignores that the angle moves: it is exact for a constant inertia and an
// estimate otherwise (the Floquet analysis, DriveOrbit.h, is the exact linear answer).
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "modes/DriveModels.h"
#include "scene/Scene.h"

namespace rollerdyn::modes {

// Each undamped mode (eigenpair of M⁻¹K) gets one pair of eigenvalues of the damped state matrix
// [[0, I], [-M⁻¹K, -M⁻¹C]] as its own: the matrix's pairs (a complex conjugate pair, or two real
// eigenvalues) go to the undamped modes whose shapes their eigenvectors resemble most (modal
// assurance in the mass metric), never by sorting frequencies apart; with one complex pair and two
// real eigenvalues the complex pair is the coupling mode's (the rigid-body mode has no restoring
// stiffness of its own to oscillate with). So a mode's damping ratio,
// natural and damped frequency all come from one pair. From the pair λ_a, λ_b:
//   ω_n = √(λ_a·λ_b) (= |λ| for a complex pair),   ζ = -(λ_a + λ_b)/(2·ω_n),
//   ω_d = |Im λ| = ω_n·√(1 - ζ²) for ζ < 1; ζ ≥ 1 (two real λ): overdamped, no oscillation.
// The frequency without damping, √λ of M⁻¹K, is another system's (the damping left out): with the
// motor's slope the damping is not proportional and ω_n can lie far from it.
struct FrozenMode {
  std::string name;            // e.g. "motor side against crank side (coupling twist)"
  double lambda = 0;           // eigenvalue of M⁻¹K [1/s²]
  double frequency = 0;        // √λ [rad/s], without damping; NaN when λ ≤ 0 (no oscillation while frozen)
  double damping_ratio = 0;    // ζ of this mode's damped pair; NaN without a frequency
  double natural_frequency = NAN;  // ω_n of this mode's damped pair [rad/s]
  bool oscillates = false;     // ζ < 1: the damped pair is complex
  // ω_d = Im λ of the damped pair [rad/s]: the frequency a free vibration actually has (the branch a
  // Floquet frequency is read on); 0 when the pair does not oscillate (overdamped: there is no
  // damped frequency; outputs say so), NaN without a frequency.
  double damped_frequency = NAN;
  Eigen::Vector2d shape = Eigen::Vector2d::Zero();  // (δφ2, δψ), normalized to max |δφ| = 1
  double energy_motor_side = 0, energy_shaft_rods = 0, energy_carts = 0;  // kinetic-energy fractions
  bool torsional = false;      // the coupling's mode (motor side against the crank side)
};

struct FrozenAngle {
  DrivePoint point;            // operating point (steady motion at this angle)
  Eigen::MatrixXd M, K, C;     // in (φ2, ψ) coordinates (rigid: 1×1)
  std::vector<FrozenMode> modes;  // ascending λ; the torsional one last
  // The torsional mode (elastic coupling), or NaN.
  double torsional_frequency() const;
  // The damped frequency Im λ [rad/s] of the drive's oscillation while frozen: the torsional
  // mode's where it oscillates, else the other mode's where that one does (with a heavy,
  // non-proportional damping the pair continued from the rigid-body mode can be the one that
  // oscillates, the coupling mode's overdamped), else 0; NaN without a frequency. The reference
  // for the branch of the Floquet frequency, which is known only modulo the crank speed's first
  // order (the Floquet multipliers' complex pair is this oscillation).
  double oscillation_frequency() const;
};

// Linearizes `drive` at `p` (setOperatingPoint first). `scene` supplies the inertia split for
// the names. `fd_scale`: the twist scale for its difference step [rad].
FrozenAngle frozenModes(DriveModel& drive, const Scene& scene, const DrivePoint& p);

// Mean, smallest and largest of a frequency over a revolution's samples (NaN ignored).
struct Band {
  double mean = NAN, min = NAN, max = NAN;
};
Band bandOf(const std::vector<double>& values);

}  // namespace rollerdyn::modes
