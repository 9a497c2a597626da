#include "modes/GrowthCheck.h"

#include <cmath>

#include "modes/DriveOrbit.h"
#include "modes/FrozenModes.h"
#include "reduced/ReducedModel.h"

namespace rollerdyn::modes {

namespace {

SteadyMotion orbitFrom(const Scene& scene, double phi0, int samples) {
  Scene s = scene;
  s.initial.crank_angle = phi0;
  auto drive = makeReducedDrive(s);
  SteadyMotionOptions o;
  o.samples = samples;
  o.rtol = 1e-11;
  const SteadyGuess g = steadyGuess(drive->reducedModel());
  DrivePoint p;
  p.phi = phi0;
  p.omega = g.ok ? g.omega : 1.0;
  p.twist = g.twist;
  o.reference_frequency = frozenModes(*drive, s, p).oscillation_frequency();
  return steadyMotion(*drive, s, o);
}

// The two neighbouring sample angles of the steady motion between which its twist rate changes
// sign; false where it never does.
bool twistRateSignChange(const SteadyMotion& m, double& phi_a, double& phi_b) {
  for (size_t k = 1; k < m.samples.size(); ++k)
    if ((m.samples[k - 1].twist_rate < 0) != (m.samples[k].twist_rate < 0)) {
      phi_a = m.samples[k - 1].phi;
      phi_b = m.samples[k].phi;
      return true;
    }
  return false;
}

// Secant iterations on ψ̇(φ*) = 0 with the orbit re-found from each section, from the angles
// phi_a, phi_b; phi_b becomes the section angle φ*, the result the orbit from it.
SteadyMotion orbitAtZeroTwistRate(const Scene& scene, double phi_a, double& phi_b) {
  SteadyMotion ma = orbitFrom(scene, phi_a, 0), mb = orbitFrom(scene, phi_b, 0);
  for (int it = 0; it < 8 && ma.found && mb.found; ++it) {
    const double fa = ma.x0(2), fb = mb.x0(2);
    if (fb == fa || std::abs(fb) < 1e-13) break;
    const double phi_c = phi_b - fb * (phi_b - phi_a) / (fb - fa);
    phi_a = phi_b;
    ma = mb;
    phi_b = phi_c;
    mb = orbitFrom(scene, phi_b, 0);
  }
  return mb;
}

// The branch of the torsional frequency from the frozen-angle damped frequency's mean over the
// revolution (the first orbit's samples): one angle's is a poor reference where the inertia swings
// by 67 % (two carts: 23.0 rad/s = 2.47ω was predicted where the run shows order 3.5).
void rebranchByFrozenMean(const Scene& scene, const SteadyMotion& first, SteadyMotion& mb) {
  auto drive = makeReducedDrive(scene);
  double sum = 0;
  int n = 0;
  for (const DrivePoint& q : first.samples) {
    const double f = frozenModes(*drive, scene, q).oscillation_frequency();
    if (std::isfinite(f)) {
      sum += f;
      ++n;
    }
  }
  if (n) rebranch(mb, sum / n);
}

// The run of R revolutions from the steady motion's state at the section angle phi_b.
RunResult runFromSection(const Scene& scene, const SteadyMotion& mb, double phi_b, int R, int spectrum_revolutions) {
  Scene s = scene;
  s.initial.crank_angle = phi_b;
  s.initial.crank_speed = mb.x0(0);
  s.initial.twist = mb.x0(1);
  s.simulation.t_end = R * mb.period;
  s.simulation.output_step = mb.period / 720;
  s.simulation.accuracy = 1e-11;
  s.simulation.steady_window_revolutions = spectrum_revolutions;
  return runReducedModel(s);
}

// The twist's departure from the steady motion's, |ψ - ψ*|, at each return to φ* + 2πn, n = 1 ... R.
std::vector<double> departuresAtSection(const RunResult& run, double phi_b, double psi_steady, int R) {
  const std::vector<double> phi = run.timeseries.column("phi_crank"), psi = run.timeseries.column("twist");
  std::vector<double> deviation;
  size_t row = 1;
  for (int n = 1; n <= R; ++n) {
    const double target = phi_b + 2 * M_PI * n;
    while (row < phi.size() && phi[row] < target) ++row;
    if (row >= phi.size()) break;
    const double w = (target - phi[row - 1]) / (phi[row] - phi[row - 1]);
    const double psi_n = psi[row - 1] + w * (psi[row] - psi[row - 1]);
    deviation.push_back(std::abs(psi_n - psi_steady));
  }
  return deviation;
}

// The slope of the least-squares line through the points (xs, ys).
double leastSquaresSlope(const std::vector<double>& xs, const std::vector<double>& ys) {
  double mx = 0, my = 0;
  for (size_t i = 0; i < xs.size(); ++i) {
    mx += xs[i];
    my += ys[i];
  }
  mx /= xs.size();
  my /= xs.size();
  double sxy = 0, sxx = 0;
  for (size_t i = 0; i < xs.size(); ++i) {
    sxy += (xs[i] - mx) * (ys[i] - my);
    sxx += (xs[i] - mx) * (xs[i] - mx);
  }
  return sxy / sxx;
}

// Growth per revolution: least squares on log|d_n| while the departure is small (< 1 % of the
// mean twist: linear), from the second revolution on. Sets g.measured_growth and
// g.revolutions_fitted where at least three revolutions fit.
void fitGrowth(double psi_steady, GrowthMeasurement& g) {
  const double limit = 0.01 * std::abs(psi_steady) + 1e-12;
  std::vector<double> xs, ys;
  for (size_t n = 1; n < g.deviation.size(); ++n) {
    if (g.deviation[n] > limit) break;
    if (g.deviation[n] > 0) {
      xs.push_back(double(n));
      ys.push_back(std::log(g.deviation[n]));
    }
  }
  if (xs.size() < 3) return;
  g.measured_growth = std::exp(leastSquaresSlope(xs, ys));
  g.revolutions_fitted = int(xs.size());
}

// The order spectrum of the run's last revolutions, its strongest order of the twist off the
// whole orders, and the whole orders' share.
void addSpectrum(const RunResult& run, int spectrum_revolutions, GrowthMeasurement& g) {
  g.spectrum = orderSpectrum(run.timeseries, run.timeseries, {"coupling_torque", "twist"}, spectrum_revolutions, 64, 24);
  g.peak_order = NAN;
  if (!g.spectrum.ok || g.spectrum.signals.size() != 2) return;
  const std::vector<double>& a = g.spectrum.amplitude[1];
  const int Rs = g.spectrum.revolutions;
  double best = 0;
  for (size_t b = 1; b < a.size(); ++b)
    if (b % Rs != 0 && a[b] > best) {
      best = a[b];
      g.peak_order = g.spectrum.orders[b];
    }
  g.whole_order_share = g.spectrum.whole_order_share[1];
}

// 1. The steady motion and the angle where its twist rate changes sign; 2. the orbit from the
// section where the twist rate is zero, rebranched by the frozen mean. False, with g.failure, when
// there is none.
bool orbitAtZeroTwistRateSection(const Scene& scene, SteadyMotion& mb, double& phi_b, GrowthMeasurement& g) {
  const SteadyMotion m = orbitFrom(scene, scene.initial.crank_angle, 360);
  double phi_a = NAN;
  if (!m.found || !twistRateSignChange(m, phi_a, phi_b)) {
    g.failure = !m.found ? m.failure : "the twist rate of the steady motion never changes sign";
    return false;
  }
  mb = orbitAtZeroTwistRate(scene, phi_a, phi_b);
  if (!mb.found) {
    g.failure = mb.failure;
    return false;
  }
  rebranchByFrozenMean(scene, m, mb);
  return true;
}

}  // namespace

GrowthMeasurement measureGrowth(const Scene& scene, int R, int spectrum_revolutions) {
  GrowthMeasurement g;
  if (scene.coupling.type != CouplingType::Elastic) {
    g.failure = "needs an elastic coupling";
    return g;
  }
  SteadyMotion mb;
  double phi_b = NAN;
  if (!orbitAtZeroTwistRateSection(scene, mb, phi_b, g)) return g;
  g.start_angle = phi_b;
  g.predicted_modulus = mb.verdict.max_modulus;
  g.predicted_order = mb.verdict.torsional_frequency / mb.omega_mean;
  // 3. The run from that state, 4. its growth per revolution, 5. its spectrum.
  const RunResult run = runFromSection(scene, mb, phi_b, R, spectrum_revolutions);
  g.deviation = departuresAtSection(run, phi_b, mb.x0(1), R);
  fitGrowth(mb.x0(1), g);
  addSpectrum(run, spectrum_revolutions, g);
  g.ok = run.stats.complete || !g.deviation.empty();
  if (!run.stats.complete) g.failure = run.stats.status;
  return g;
}

}  // namespace rollerdyn::modes
