#include "studies/ResonanceCheck.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "reduced/ReducedModel.h"

namespace rollerdyn {

double naturalFrequency(double c, double J1, double J2) {
  return std::sqrt(c * (J1 + J2) / (J1 * J2));  // Dyomin (two rotors) eq. (10)
}

double meanCrankSideInertia(const Scene& scene) {
  const ReducedModel model(scene);
  const int n = 720;
  double sum = 0;
  for (int i = 0; i < n; ++i) sum += model.crankSideInertia(2.0 * M_PI * i / n);
  return sum / n;
}

std::vector<int> excitationOrders(const Scene& scene) {
  const int n = std::max(1, scene.carts.count);
  const int k_max = std::max(12, 2 * n);
  bool one_side = true;
  for (int j = 0; j < n && j < int(scene.carts.side.size()); ++j) one_side = one_side && scene.carts.side[j] == scene.carts.side[0];
  std::vector<int> orders;
  for (int k = 1; k <= k_max; ++k) {
    // Carts on both sides, or carts of different masses or loads (Scene::cartsIdentical): their
    // harmonics do not cancel by the phase sum.
    if (!one_side || !scene.cartsIdentical()) {
      orders.push_back(k);
      continue;
    }
    // |Σ_j exp(i·k·θ_j)| against n: zero to round-off where the layout cancels order k.
    double re = 0, im = 0;
    for (int j = 0; j < n; ++j) {
      re += std::cos(k * scene.crankPhase(j));
      im += std::sin(k * scene.crankPhase(j));
    }
    if (std::hypot(re, im) > 1e-6 * n) orders.push_back(k);
  }
  return orders;
}

std::vector<ResonanceHit> resonanceHits(double p0, double omega, double tolerance, const std::vector<int>& orders) {
  std::vector<ResonanceHit> hits;
  const double w = std::abs(omega);
  if (!(w > 0) || !std::isfinite(w) || !std::isfinite(p0)) return hits;
  for (int n : orders) {
    const double ratio = p0 / (n * w);
    if (std::abs(ratio - 1.0) <= tolerance) hits.push_back({n, ratio});
  }
  return hits;
}

ResonanceReport checkResonance(const Scene& scene, double omega_mean, double tolerance) {
  ResonanceReport r;
  r.omega = omega_mean;
  if (scene.coupling.type != CouplingType::Elastic) return r;
  r.J1 = scene.motorSideInertia();
  r.J2_mean = meanCrankSideInertia(scene);
  r.stiffness = scene.coupling.stiffness;
  r.p0 = naturalFrequency(r.stiffness, r.J1, r.J2_mean);
  r.orders = excitationOrders(scene);
  r.applicable = std::isfinite(omega_mean) && std::abs(omega_mean) > 0;
  if (!r.applicable) return r;
  r.hits = resonanceHits(r.p0, omega_mean, tolerance, r.orders);
  for (const ResonanceHit& h : r.hits) {
    char buf[320];
    std::snprintf(buf, sizeof buf,
                  "torsional resonance: coupling natural frequency p0 = %.4g rad/s is within %.0f %% "
                  "of %d·ω = %.4g rad/s (p0/(k·ω) = %.3f; Dyomin (two rotors) eq. (10), (16)-(21)), an order "
                  "the cart layout excites; the coupling torque may be amplified",
                  r.p0, 100 * tolerance, h.harmonic, h.harmonic * std::abs(omega_mean), h.ratio);
    r.warnings.push_back(buf);
  }
  return r;
}

std::vector<std::string> addResonanceWarnings(const Scene& scene, nlohmann::json& summary) {
  double omega = std::nan("");
  if (summary.contains("omega_crank") && summary["omega_crank"].contains("mean") &&
      summary["omega_crank"]["mean"].is_number())
    omega = summary["omega_crank"]["mean"].get<double>();
  if (!summary.contains("warnings") || !summary["warnings"].is_array())
    summary["warnings"] = nlohmann::json::array();
  if (scene.coupling.type != CouplingType::Elastic) {
    summary["resonance"] = {{"applicable", false}, {"note", "rigid coupling: no torsional mode"}};
    return {};
  }
  const ResonanceReport r = checkResonance(scene, omega);
  nlohmann::json hits = nlohmann::json::array();
  for (const ResonanceHit& h : r.hits) hits.push_back({{"harmonic", h.harmonic}, {"ratio", h.ratio}});
  auto num = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
  summary["resonance"] = {{"applicable", r.applicable},
                          {"J1", num(r.J1)},
                          {"J2_mean", num(r.J2_mean)},
                          {"stiffness", num(r.stiffness)},
                          {"p0", num(r.p0)},
                          {"omega", num(r.omega)},
                          {"p0_over_omega", num(r.p0 / r.omega)},
                          {"tolerance", kResonanceTolerance},
                          {"harmonics_checked", r.orders},
                          {"harmonics_basis",
                           "orders of the crank speed the cart layout excites: multiples of n for n carts on one "
                           "side at equal offsets spread over the turn, every order otherwise (also when the carts' "
                           "masses or loads differ)"},
                          {"hits", hits}};
  for (const std::string& w : r.warnings) summary["warnings"].push_back(w);
  return r.warnings;
}

}  // namespace rollerdyn
