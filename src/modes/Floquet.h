// Floquet multipliers of a linear system with periodic coefficients and what they mean for an
// engineer (Floquet's theorem: every solution of ẋ = A(t)x, A(t + T) = A(t), is a sum of
// terms p(t)·e^{λt} with p T-periodic; the multipliers μ = e^{λT} are the eigenvalues of the
// monodromy matrix Φ(T), PeriodicFlow.h).
//
//   growth (or decay) rate per unit time   σ = ln|μ| / T            [1/s]
//   oscillation frequency                   ω_d = (arg μ + 2πm)/T    [rad/s]
// The integer m is not in the multipliers (a frequency is only known modulo 2π/T, the crank
// speed's first order): it is taken from a reference frequency (the frozen-angle mode's damped
// frequency Im λ, the one a free vibration has) as the branch closest to it. The modal damping ratio then is
//   ζ = -σ / √(σ² + ω_d²)     (a constant-coefficient mode: λ = -ζω_n ± iω_n√(1-ζ²)).
// Stability: every |μ| < 1. The margin is 1 - max|μ| (> 0 stable) and, per unit time, the
// slowest decay rate -max σ [1/s].
#pragma once

#include <complex>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace rollerdyn::modes {

struct FloquetMultiplier {
  std::complex<double> mu;   // eigenvalue of the monodromy matrix
  double modulus = 0;        // |μ|
  double growth_rate = 0;    // σ = ln|μ|/T [1/s] (> 0: grows)
  double frequency = 0;      // ω_d ≥ 0 [rad/s], branch closest to the reference (0 for a real μ > 0)
  double damping_ratio = 0;  // ζ (NaN when σ = ω_d = 0)
  Eigen::VectorXcd vector;   // eigenvector (Floquet mode at t = 0)
};

// Multipliers of a monodromy over period T [s], sorted by modulus, largest first; the frequency
// branch of complex (or negative real) multipliers is chosen closest to `reference_frequency`
// [rad/s] (0: the principal branch |arg μ|/T).
std::vector<FloquetMultiplier> floquetMultipliers(const Eigen::MatrixXd& monodromy, double period,
                                                  double reference_frequency = 0);

// The branch of ω_d = (|arg μ| + 2πm)/T, m ≥ 0 and its mirror (2πm' - |arg μ|)/T, closest to the
// reference (the two cover every frequency whose samples at period T give μ's angle).
double frequencyBranch(std::complex<double> mu, double period, double reference_frequency);

}  // namespace rollerdyn::modes
