#include "modes/Floquet.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

namespace rollerdyn::modes {

double frequencyBranch(std::complex<double> mu, double T, double ref) {
  const double theta = std::abs(std::arg(mu));  // [0, π]
  if (theta == 0.0 && ref <= 0) return 0.0;
  const double base = 2 * M_PI / T;
  double best = theta / T, best_dist = std::abs(theta / T - ref);
  const int m_max = int(std::max(0.0, ref) / base) + 2;
  for (int m = 0; m <= m_max; ++m) {
    for (double w : {(theta + 2 * M_PI * m) / T, (2 * M_PI * m - theta) / T}) {
      if (w < 0) continue;
      const double d = std::abs(w - ref);
      if (d < best_dist) {
        best = w;
        best_dist = d;
      }
    }
  }
  return best;
}

std::vector<FloquetMultiplier> floquetMultipliers(const Eigen::MatrixXd& M, double T, double ref) {
  std::vector<FloquetMultiplier> out;
  if (M.rows() == 0 || !M.allFinite()) return out;
  Eigen::EigenSolver<Eigen::MatrixXd> es(M, true);
  if (es.info() != Eigen::Success) return out;
  for (int i = 0; i < M.rows(); ++i) {
    FloquetMultiplier f;
    f.mu = es.eigenvalues()(i);
    f.vector = es.eigenvectors().col(i);
    f.modulus = std::abs(f.mu);
    f.growth_rate = std::log(f.modulus) / T;
    // A real positive multiplier is a non-oscillating (or order-synchronous) mode; its branch is
    // still chosen by the reference, which may put it at a whole order of the crank speed.
    f.frequency = (std::abs(f.mu.imag()) <= 1e-12 * f.modulus && f.mu.real() > 0 && ref <= 0)
                      ? 0.0
                      : frequencyBranch(f.mu, T, ref);
    const double wn = std::hypot(f.growth_rate, f.frequency);
    f.damping_ratio = wn > 0 ? -f.growth_rate / wn : std::nan("");
    out.push_back(f);
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const FloquetMultiplier& a, const FloquetMultiplier& b) { return a.modulus > b.modulus; });
  return out;
}

}  // namespace rollerdyn::modes
