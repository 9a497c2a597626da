// The periodic steady motion of a drive and the Floquet analysis of the motion linearized about it.
//
// In steady running every load and inertia is 2π-periodic in the crank angle φ2 and the motor's
// torque depends on its speed only, so the steady motion is a periodic orbit: taking φ2 as the
// independent variable (as Loveikin and Pochka (2007) eq. (4) do), the states
//   x = (φ̇2, ψ, ψ̇)   elastic coupling (ψ = φ1 - φ2, the twist)      x = (φ̇2)   rigid
// obey dx/dφ2 = (φ̈2, ψ̇, ψ̈)/φ̇2, periodic in φ2 with period 2π, and the steady motion is the
// fixed point of the map over one revolution (found by Newton's method, PeriodicFlow.h). The
// time of a revolution T = ∫dφ2/φ̇2 rides along. The linearized map's matrix (the monodromy on
// the section φ2 = const) has as eigenvalues the Floquet multipliers of the time-domain motion
// about its orbit, less the trivial multiplier 1 of the shift along the orbit, which taking φ2
// as the clock removes. So every multiplier here says something: |μ| < 1 for all: the steady
// motion is stable; |μ| > 1 for the torsional one: parametric resonance (the periodic inertia
// J_n2(φ2) and load stiffness pump the coupling's oscillation).
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "modes/DriveModels.h"
#include "modes/Floquet.h"
#include "scene/Scene.h"

namespace rollerdyn::modes {

// A first guess of the steady motion from the reduced model's mean load torque and the motor's
// torque curve (the speed where the motor carries the mean load; twist = that torque / c).
struct SteadyGuess {
  bool ok = false;
  std::string failure;   // no motor, or the mean load exceeds the motor's breakdown torque
  double omega = 0;      // [rad/s]
  double twist = 0;      // [rad]
  double mean_load_torque = 0;  // [N·m] at the crank
};
SteadyGuess steadyGuess(const ReducedModel& model);

enum class ModeKind { Torsional, Speed };
const char* toString(ModeKind k);  // "torsional (coupling)", "speed (whole drive)"

struct ClassifiedMultiplier {
  FloquetMultiplier m;
  ModeKind kind = ModeKind::Speed;
};

// Multipliers smaller than this are not resolved by the integration (see judge()).
inline constexpr double kResolvedModulus = 1e-6;

struct FloquetVerdict {
  bool stable = false;
  std::string text;         // "stable", "parametrically unstable", "unstable speed mode"
  double max_modulus = 0;   // max |μ|
  double margin = 0;        // 1 - max |μ| (> 0: stable)
  double slowest_decay_rate = 0;  // -max σ [1/s] (> 0: every disturbance decays at least this fast)
  // The torsional mode's numbers (elastic coupling): largest |μ| among its multipliers,
  // its frequency and damping ratio.
  bool has_torsional = false;
  bool torsional_resolved = true;  // false: |μ| < kResolvedModulus, frequency and ζ unknown (NaN)
  double torsional_modulus = 0, torsional_frequency = 0, torsional_damping_ratio = 0;

  // Undamped natural frequency from the multipliers, √(σ² + ω_d²) = ω_d/√(1 - ζ²): where a forced
  // response peaks.
  double torsionalNaturalFrequency() const {
    const double zeta = torsional_damping_ratio;
    return torsional_frequency / std::sqrt(std::max(1e-12, 1 - zeta * zeta));
  }
};

struct SteadyMotion {
  bool found = false;
  std::string failure;
  bool elastic = false;
  double phi0 = 0;            // crank angle of the section [rad]
  double period = 0;          // T, time of one revolution [s]
  double omega_mean = 0;      // 2π/T [rad/s]
  Eigen::VectorXd x0;         // (φ̇2, ψ, ψ̇) or (φ̇2) at φ2 = phi0
  Eigen::MatrixXd monodromy;
  int newton_iterations = 0;
  long evaluations = 0;
  // Samples over one revolution, φ2 = phi0 + 2πk/samples.
  std::vector<DrivePoint> samples;
  std::vector<double> sample_time;  // t since the section [s]
  std::vector<ClassifiedMultiplier> multipliers;  // largest |μ| first
  FloquetVerdict verdict;
};

struct SteadyMotionOptions {
  int samples = 72;                 // orbit samples per revolution (frozen-angle analysis)
  double reference_frequency = 0;   // torsional frequency branch [rad/s] (frozen-angle mean)
  double rtol = 1e-9;
  // Warm start: a neighbouring orbit's x0 (continuation over a chart); empty: steadyGuess.
  Eigen::VectorXd start;
  int warmup_periods = 3;           // revolutions integrated from the guess before Newton
  int max_newton = 30;              // Newton iterations on the period map before giving up
  // Multibody model with guide friction: the friction normal-force lags are set to the normal
  // forces of each evaluated state (quasi-static, τ_N → 0), since they cannot be held at one
  // value along the orbit.
  bool quasi_static_auxiliary = true;
};

// The steady motion of `drive` (a scene's DriveModel) and its Floquet multipliers. Never throws
// on a drive that does not run steadily: found = false and `failure` says why (stall, no motor,
// no convergence).
SteadyMotion steadyMotion(DriveModel& drive, const Scene& scene, const SteadyMotionOptions& o = {});

// The multipliers of `m` (found) classified and judged again with the torsional frequency's branch
// nearest `reference_frequency` [rad/s] (e.g. the frozen-angle damped frequency's mean over the
// revolution, a better reference than one angle's where the inertia swings much).
void rebranch(SteadyMotion& m, double reference_frequency);

// The scene run at another mean crank speed the way a frequency converter does it (V/f control):
// the motor's torque-speed curve shifted along the speed axis, i.e. synchronous speed
// ω0' = ω0 + u·(omega_target - omega_now) with the slip speed at breakdown s_kr·ω0 kept, so the
// motor carries the same mean load at the same slip speed and the steady crank speed moves from
// omega_now to omega_target (exactly when the mean load does not depend on the speed). The
// equivalent-circuit laws (circuit, Park): supply frequency and voltage scaled by ω0'/ω0 (U/f
// constant), the circuit kept.
// Throws std::invalid_argument when ω0' would not be positive.
Scene sceneAtCrankSpeed(const Scene& scene, double omega_target, double omega_now);

// Classifies and judges multipliers of a drive's monodromy (elastic: states (φ̇2, ψ, ψ̇)). Elastic:
// a complex-conjugate pair is the coupling's (torsional) oscillation; with all three real, the
// torsional ones are those whose twist rate exceeds their crank-speed change.
std::vector<ClassifiedMultiplier> classifyMultipliers(const std::vector<FloquetMultiplier>& m, bool elastic);
FloquetVerdict judge(const std::vector<ClassifiedMultiplier>& m);

}  // namespace rollerdyn::modes
