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

// Q's harmonic k: M_k + ½·ω²·(J')_k, (J')_k = i·k·J_k (J = Σ Re(J_k·exp(i·k·φ))), its amplitude.
double excitingHarmonic(const std::vector<std::complex<double>>& cM, const std::vector<std::complex<double>>& cJ,
                        size_t k, double omega) {
  return std::abs(cM[k] + 0.5 * omega * omega * std::complex<double>(0.0, double(k)) * cJ[k]);
}

// The crank side's inertia J(φ) and load torque M(φ) over a revolution (n samples), their
// harmonics' amplitudes, those of the exciting torque Q and the inertia's range.
struct DriveHarmonics {
  static constexpr int n = 256;
  std::vector<double> hJ, hM, hQ;
  double j_min = 0, j_max = 0;
  double largest_J = 0, largest_M = 0;  // over the orders k ≥ 1
};

DriveHarmonics driveHarmonics(const ReducedModel& model, double omega) {
  const int n = DriveHarmonics::n;
  std::vector<double> J(n), M(n);
  for (int i = 0; i < n; ++i) {
    const double phi = 2 * M_PI * i / n;
    J[i] = model.crankSideInertia(phi);
    M[i] = model.loadTorque(phi, omega);
  }
  DriveHarmonics h;
  const auto [jmin, jmax] = std::minmax_element(J.begin(), J.end());
  h.j_min = *jmin;
  h.j_max = *jmax;
  const std::vector<std::complex<double>> cJ = complexHarmonics(J), cM = complexHarmonics(M);
  h.hJ = amplitudes(cJ);
  h.hM = amplitudes(cM);
  h.hQ.assign(cJ.size(), 0.0);
  for (size_t k = 1; k < cJ.size(); ++k) h.hQ[k] = excitingHarmonic(cM, cJ, k, omega);
  for (int k = 1; k < n / 2; ++k) {
    h.largest_J = std::max(h.largest_J, h.hJ[k]);
    h.largest_M = std::max(h.largest_M, h.hM[k]);
  }
  return h;
}

// Order k's row and the lists it belongs to: forced (drives the coupling), layout (the carts'
// phases do not cancel it), inertia and load (above their floors), all.
void addOrder(ExcitationOrders& e, const DriveHarmonics& h, const Scene& scene, int k, double floorJ, double floorM) {
  OrderContent c;
  c.order = k;
  c.layout_factor = layoutFactor(scene, k);
  c.inertia_amplitude = h.hJ[k];
  c.load_amplitude = h.hM[k];
  c.exciting_torque = h.hQ[k];
  e.table.push_back(c);
  if (e.exciting_largest > 0 && h.hQ[k] >= kForcedOrderShare * e.exciting_largest) e.forced.push_back(k);
  // Carts of different masses or loads each bring their own harmonics: no phase sum cancels them.
  if (c.layout_factor > 1e-9 || !scene.cartsIdentical()) e.layout.push_back(k);
  const bool inJ = h.largest_J > 0 && h.hJ[k] > floorJ, inM = h.largest_M > 0 && h.hM[k] > floorM;
  if (inJ) e.inertia.push_back(k);
  if (inM) e.load.push_back(k);
  if (inJ || inM) e.all.push_back(k);
}

}  // namespace

ExcitationOrders excitationOrders(const ReducedModel& model, double omega, int max_order) {
  const int n = DriveHarmonics::n;
  const DriveHarmonics h = driveHarmonics(model, omega);
  ExcitationOrders e;
  e.omega = omega;
  for (int k = 1; k <= max_order && k < n / 2; ++k) e.exciting_largest = std::max(e.exciting_largest, h.hQ[k]);
  e.inertia_mean = h.hJ[0];
  e.inertia_relative_swing = h.hJ[0] > 0 ? (h.j_max - h.j_min) / h.hJ[0] : 0;
  // Floors: round-off of 256 samples of a smooth function is ~1e-15 of its size; 1e-9 of the
  // largest harmonic keeps every physical order (the slider-crank's decay as (r/l)^k reaches
  // 1e-9 only past order 15 at r/l = 0.25) and drops the cancelled ones.
  const double floorJ = std::max(1e-9 * h.largest_J, 1e-12 * h.hJ[0]), floorM = 1e-9 * h.largest_M;
  for (int k = 1; k <= max_order && k < n / 2; ++k) addOrder(e, h, model.scene(), k, floorJ, floorM);
  return e;
}

namespace {

// Each cart's reduced inertia J_j(φ) and load torque M_j(φ) at n crank angles over a revolution.
struct ThrowSamples {
  std::vector<std::vector<double>> J, M;
};

ThrowSamples throwSamples(const ReducedModel& model, double omega, int n) {
  const Scene& scene = model.scene();
  const int carts = scene.carts.count;
  ThrowSamples s{std::vector<std::vector<double>>(carts, std::vector<double>(n)),
                 std::vector<std::vector<double>>(carts, std::vector<double>(n))};
  std::vector<CartEvaluation> eval;
  for (int i = 0; i < n; ++i) {
    model.loadTorque(2 * M_PI * i / n, omega, &eval);
    for (int j = 0; j < carts; ++j) {
      s.M[j][i] = -eval[j].generalized_force;
      s.J[j][i] = cartReducedInertia(scene.cartMassWithRodShare(j), scene.rods, eval[j].pose);
    }
  }
  return s;
}

}  // namespace

std::vector<double> throwOrderShares(const ReducedModel& model, double omega, int max_order) {
  int n = 256;
  while (n < 4 * max_order) n *= 2;  // well above the highest order asked for
  const ThrowSamples samples = throwSamples(model, omega, n);
  std::vector<double> share(max_order, 0.0);
  for (size_t j = 0; j < samples.J.size(); ++j) {
    const std::vector<std::complex<double>> cJ = complexHarmonics(samples.J[j]), cM = complexHarmonics(samples.M[j]);
    std::vector<double> hQ(max_order + 1, 0.0);
    double largest = 0;
    for (int k = 1; k <= max_order; ++k) {
      hQ[k] = excitingHarmonic(cM, cJ, size_t(k), omega);
      largest = std::max(largest, hQ[k]);
    }
    if (largest > 0)
      for (int k = 1; k <= max_order; ++k) share[k - 1] = std::max(share[k - 1], hQ[k] / largest);
  }
  return share;
}

}  // namespace rollerdyn::modes
