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
  const SteadyGuess g = steadyGuess(s);
  DrivePoint p;
  p.phi = phi0;
  p.omega = g.ok ? g.omega : 1.0;
  p.twist = g.twist;
  o.reference_frequency = frozenModes(*drive, s, p).oscillation_frequency();
  return steadyMotion(*drive, s, o);
}

}  // namespace

GrowthMeasurement measureGrowth(const Scene& scene, int R, int spectrum_revolutions) {
  GrowthMeasurement g;
  if (scene.coupling.type != CouplingType::Elastic) {
    g.failure = "needs an elastic coupling";
    return g;
  }
  // 1. The steady motion and the angle where its twist rate changes sign.
  SteadyMotion m = orbitFrom(scene, scene.initial.crank_angle, 360);
  if (!m.found) {
    g.failure = m.failure;
    return g;
  }
  double phi_a = NAN, phi_b = NAN;
  for (size_t k = 1; k < m.samples.size(); ++k)
    if ((m.samples[k - 1].twist_rate < 0) != (m.samples[k].twist_rate < 0)) {
      phi_a = m.samples[k - 1].phi;
      phi_b = m.samples[k].phi;
      break;
    }
  if (!std::isfinite(phi_a)) {
    g.failure = "the twist rate of the steady motion never changes sign";
    return g;
  }
  // 2. Secant iterations on ψ̇(φ*) = 0 with the orbit re-found from each section.
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
  if (!mb.found) {
    g.failure = mb.failure;
    return g;
  }
  // The branch of the torsional frequency from the frozen-angle damped frequency's mean over the
  // revolution (the first orbit's samples): one angle's is a poor reference where the inertia swings
  // by 67 % (two carts: 23.0 rad/s = 2.47ω was predicted where the run shows order 3.5).
  {
    auto drive = makeReducedDrive(scene);
    double sum = 0;
    int n = 0;
    for (const DrivePoint& q : m.samples) {
      const double f = frozenModes(*drive, scene, q).oscillation_frequency();
      if (std::isfinite(f)) {
        sum += f;
        ++n;
      }
    }
    if (n) rebranch(mb, sum / n);
  }
  g.start_angle = phi_b;
  g.predicted_modulus = mb.verdict.max_modulus;
  g.predicted_order = mb.verdict.torsional_frequency / mb.omega_mean;
  // 3. The run from that state.
  Scene s = scene;
  s.initial.crank_angle = phi_b;
  s.initial.crank_speed = mb.x0(0);
  s.initial.twist = mb.x0(1);
  s.simulation.t_end = R * mb.period;
  s.simulation.output_step = mb.period / 720;
  s.simulation.accuracy = 1e-11;
  s.simulation.steady_window_revolutions = spectrum_revolutions;
  const RunResult run = runReducedModel(s);
  const std::vector<double> t = run.timeseries.column("t"), phi = run.timeseries.column("phi_crank"),
                            psi = run.timeseries.column("twist");
  // Twist at each return to φ* + 2πn.
  size_t row = 1;
  for (int n = 1; n <= R; ++n) {
    const double target = phi_b + 2 * M_PI * n;
    while (row < phi.size() && phi[row] < target) ++row;
    if (row >= phi.size()) break;
    const double w = (target - phi[row - 1]) / (phi[row] - phi[row - 1]);
    const double psi_n = psi[row - 1] + w * (psi[row] - psi[row - 1]);
    g.deviation.push_back(std::abs(psi_n - mb.x0(1)));
  }
  // 4. Growth per revolution: least squares on log|d_n| while the departure is small (< 1 % of the
  // mean twist: linear), from the second revolution on.
  const double limit = 0.01 * std::abs(mb.x0(1)) + 1e-12;
  std::vector<double> xs, ys;
  for (size_t n = 1; n < g.deviation.size(); ++n) {
    if (g.deviation[n] > limit) break;
    if (g.deviation[n] > 0) {
      xs.push_back(double(n));
      ys.push_back(std::log(g.deviation[n]));
    }
  }
  if (xs.size() >= 3) {
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
    g.measured_growth = std::exp(sxy / sxx);
    g.revolutions_fitted = int(xs.size());
  }
  // 5. Spectrum of the last revolutions.
  g.spectrum = orderSpectrum(run.timeseries, run.timeseries, {"coupling_torque", "twist"}, spectrum_revolutions, 64, 24);
  g.peak_order = NAN;
  if (g.spectrum.ok && g.spectrum.signals.size() == 2) {
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
  g.ok = run.stats.complete || !g.deviation.empty();
  if (!run.stats.complete) g.failure = run.stats.status;
  return g;
}

}  // namespace rollerdyn::modes
