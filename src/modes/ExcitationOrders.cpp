#include "modes/ExcitationOrders.h"

#include <algorithm>
#include <cmath>
#include <complex>

#include <unsupported/Eigen/FFT>

#include "physics/CartReducedInertia.h"
#include "reduced/ReducedModel.h"

namespace rollerdyn::modes {

double layoutFactor(const Scene& scene, int k) {
  std::complex<double> sum = 0;
  const int n = scene.carts.count;
  for (int j = 0; j < n; ++j) {
    const double theta = scene.crankPhase(j) + (scene.carts.side[j] < 0 ? M_PI : 0.0);
    sum += std::polar(1.0, k * theta);
  }
  return std::abs(sum) / n;
}

namespace {

// One-sided complex harmonics: samples = Σ Re(c_k·exp(i·k·φ)), c_0 the mean.
std::vector<std::complex<double>> complexHarmonics(const std::vector<double>& samples) {
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> spec;
  fft.fwd(spec, samples);
  const int n = int(samples.size());
  std::vector<std::complex<double>> c(n / 2);
  for (int k = 0; k < n / 2; ++k) c[k] = (k == 0 ? 1.0 : 2.0) * spec[k] / double(n);
  return c;
}

std::vector<double> amplitudes(const std::vector<std::complex<double>>& c) {
  std::vector<double> a(c.size());
  for (size_t k = 0; k < c.size(); ++k) a[k] = std::abs(c[k]);
  return a;
}

}  // namespace

ExcitationOrders excitationOrders(const ReducedModel& model, double omega, int max_order) {
  const Scene& scene = model.scene();
  ExcitationOrders e;
  const int n = 256;
  std::vector<double> J(n), M(n);
  for (int i = 0; i < n; ++i) {
    const double phi = 2 * M_PI * i / n;
    J[i] = model.crankSideInertia(phi);
    M[i] = model.loadTorque(phi, omega);
  }
  const auto [jmin, jmax] = std::minmax_element(J.begin(), J.end());
  const std::vector<std::complex<double>> cJ = complexHarmonics(J), cM = complexHarmonics(M);
  const std::vector<double> hJ = amplitudes(cJ), hM = amplitudes(cM);
  // Q's harmonic k: M_k + ½·ω²·(J')_k, (J')_k = i·k·J_k (J = Σ Re(J_k·exp(i·k·φ))).
  std::vector<double> hQ(cJ.size(), 0.0);
  for (size_t k = 1; k < cJ.size(); ++k)
    hQ[k] = std::abs(cM[k] + 0.5 * omega * omega * std::complex<double>(0.0, double(k)) * cJ[k]);
  e.omega = omega;
  for (int k = 1; k <= max_order && k < n / 2; ++k) e.exciting_largest = std::max(e.exciting_largest, hQ[k]);
  e.inertia_mean = hJ[0];
  e.inertia_relative_swing = hJ[0] > 0 ? (*jmax - *jmin) / hJ[0] : 0;
  double maxJ = 0, maxM = 0;
  for (int k = 1; k < n / 2; ++k) {
    maxJ = std::max(maxJ, hJ[k]);
    maxM = std::max(maxM, hM[k]);
  }
  // Floors: round-off of 256 samples of a smooth function is ~1e-15 of its size; 1e-9 of the
  // largest harmonic keeps every physical order (the slider-crank's decay as (r/l)^k reaches
  // 1e-9 only past order 15 at r/l = 0.25) and drops the cancelled ones.
  const double floorJ = std::max(1e-9 * maxJ, 1e-12 * hJ[0]), floorM = 1e-9 * maxM;
  for (int k = 1; k <= max_order && k < n / 2; ++k) {
    OrderContent c;
    c.order = k;
    c.layout_factor = layoutFactor(scene, k);
    c.inertia_amplitude = hJ[k];
    c.load_amplitude = hM[k];
    c.exciting_torque = hQ[k];
    e.table.push_back(c);
    if (e.exciting_largest > 0 && hQ[k] >= kForcedOrderShare * e.exciting_largest) e.forced.push_back(k);
    // Carts of different masses or loads each bring their own harmonics: no phase sum cancels them.
    if (c.layout_factor > 1e-9 || !scene.cartsIdentical()) e.layout.push_back(k);
    const bool inJ = maxJ > 0 && hJ[k] > floorJ, inM = maxM > 0 && hM[k] > floorM;
    if (inJ) e.inertia.push_back(k);
    if (inM) e.load.push_back(k);
    if (inJ || inM) e.all.push_back(k);
  }
  return e;
}

std::vector<double> throwOrderShares(const ReducedModel& model, double omega, int max_order) {
  const Scene& scene = model.scene();
  int n = 256;
  while (n < 4 * max_order) n *= 2;  // well above the highest order asked for
  const int carts = scene.carts.count;
  std::vector<std::vector<double>> J(carts, std::vector<double>(n)), M(carts, std::vector<double>(n));
  std::vector<CartEvaluation> eval;
  for (int i = 0; i < n; ++i) {
    model.loadTorque(2 * M_PI * i / n, omega, &eval);
    for (int j = 0; j < carts; ++j) {
      M[j][i] = -eval[j].generalized_force;
      J[j][i] = cartReducedInertia(scene.cartMassWithRodShare(j), scene.rods, eval[j].pose);
    }
  }
  std::vector<double> share(max_order, 0.0);
  for (int j = 0; j < carts; ++j) {
    const std::vector<std::complex<double>> cJ = complexHarmonics(J[j]), cM = complexHarmonics(M[j]);
    std::vector<double> hQ(max_order + 1, 0.0);
    double largest = 0;
    for (int k = 1; k <= max_order; ++k) {
      hQ[k] = std::abs(cM[k] + 0.5 * omega * omega * std::complex<double>(0.0, double(k)) * cJ[k]);
      largest = std::max(largest, hQ[k]);
    }
    if (largest > 0)
      for (int k = 1; k <= max_order; ++k) share[k - 1] = std::max(share[k - 1], hQ[k] / largest);
  }
  return share;
}

}  // namespace rollerdyn::modes
