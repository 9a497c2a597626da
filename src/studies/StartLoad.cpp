#include "studies/StartLoad.h"

#include <cmath>
#include <algorithm>
#include <limits>
#include <vector>

#include "analysis/StartUp.h"
#include "motor/BreakdownTorque.h"
#include "reduced/ReducedModel.h"

namespace rollerdyn {

namespace {

// The crank speed at which the motor's steady torque (its static curve at the crank, under the
// rated supply) carries the load averaged over a revolution: the running branch's crossing, found
// by bisection between the curve's largest torque and the synchronous speed. NaN when even the
// largest torque cannot carry the mean load.
double steadyCrankSpeed(const ReducedModel& model, const Scene& scene) {
  const double u = scene.reducer.ratio, w0 = scene.motor.omega_sync;
  auto meanLoad = [&](double w) {
    constexpr int kSamples = 360;
    double sum = 0;
    for (int i = 0; i < kSamples; ++i) sum += model.loadTorque(2.0 * M_PI * i / kSamples, w);
    return sum / kSamples;
  };
  // ReducedModel::motorTorque takes the motor side's speed in crank coordinates (ω_r/u).
  const double w_sync = w0 / u;
  const double Q = meanLoad(0.98 * w_sync);
  // The curve's largest torque, where it lies (the law's own search), in crank coordinates.
  const MotorLaw* law = model.motorLaw();
  if (!law) return std::numeric_limits<double>::quiet_NaN();
  const double w_top = largestSteadyTorquePoint(*law, SupplyState{}).speed / u;
  if (!(model.motorTorque(w_top) > Q)) return std::numeric_limits<double>::quiet_NaN();
  double a = w_top, b = w_sync;  // M(a) > Q > M(b) = 0 on the running branch
  for (int it = 0; it < 60; ++it) {
    const double m = 0.5 * (a + b);
    (model.motorTorque(m) > Q ? a : b) = m;
  }
  return 0.5 * (a + b);
}

// Excess work of one revolution at constant crank speed ω (the classical flywheel design by the
// excess work): the driving torque that keeps ω exactly constant is Q(φ) = M_load(φ, ω) +
// ½·J_n2'(φ)·ω² (the Lagrange equation J(φ)·φ̈ + ½·J'(φ)·φ̇² = M - M_load with φ̈ = 0); a motor
// that gives its mean Q̄ instead stores and returns ∫(Q̄ - Q)dφ, and the flywheel holds the speed
// swing that stored energy causes to δ ≈ ΔA/(J·ω²). Trapezoidal rule on 3600 angles.
double excessWork(const ReducedModel& model, double w) {
  constexpr int kSamples = 3600;
  std::vector<double> Q(kSamples + 1);
  double mean = 0;
  for (int i = 0; i <= kSamples; ++i) {
    const double phi = 2.0 * M_PI * i / kSamples;
    Q[i] = model.loadTorque(phi, w) + 0.5 * model.crankSideInertiaDerivative(phi) * w * w;
    if (i < kSamples) mean += Q[i] / kSamples;
  }
  const double h = 2.0 * M_PI / kSamples;
  double W = 0, lo = 0, hi = 0;
  for (int i = 1; i <= kSamples; ++i) {
    W += h * (mean - 0.5 * (Q[i - 1] + Q[i]));
    lo = std::min(lo, W), hi = std::max(hi, W);
  }
  return hi - lo;
}

}  // namespace

StartLoad startLoadOf(const Scene& scene) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  StartLoad l{kNaN, kNaN};
  try {
    const ReducedModel model(scene);
    const double r = scene.hasCamDrive() ? 0.5 * scene.cam.stroke : scene.crank.radius;
    const double omega_probe = 50.0 * scene.loads.velocity_smoothing / r;
    l.at_start_angle = model.loadTorque(scene.initial.crank_angle, omega_probe);
    constexpr int kSamples = 360;
    double sum = 0;
    for (int i = 0; i < kSamples; ++i)
      sum += model.loadTorque(scene.initial.crank_angle + 2.0 * M_PI * i / kSamples, omega_probe);
    l.revolution_mean = sum / kSamples;
    if (scene.motor.enabled && !scene.hasCamDrive()) {
      l.excess_work_speed = steadyCrankSpeed(model, scene);
      if (std::isfinite(l.excess_work_speed)) l.excess_work = excessWork(model, l.excess_work_speed);
    }
  } catch (const std::exception&) {
    // a scene the reduced model rejects: the explanation then says the loads are not known
  }
  return l;
}

}  // namespace rollerdyn
