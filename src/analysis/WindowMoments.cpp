#include "analysis/WindowMoments.h"

#include <Eigen/Core>
#include <cmath>

namespace rollerdyn {

Moments moments(const std::vector<double>& t, const std::vector<double>& y, std::size_t b,
                std::size_t e) {
  Moments m;
  if (e < b + 2 || e > t.size() || e > y.size()) return m;
  const Eigen::Index n = static_cast<Eigen::Index>(e - b);
  const Eigen::Map<const Eigen::ArrayXd> ts(t.data() + b, n), ys(y.data() + b, n);
  if (!ts.allFinite() || !ys.allFinite()) return m;
  const double span = ts(n - 1) - ts(0);
  if (!(span > 0)) return m;
  const Eigen::ArrayXd dt = ts.tail(n - 1) - ts.head(n - 1);
  m.mean = (0.5 * (ys.head(n - 1) + ys.tail(n - 1)) * dt).sum() / span;
  const Eigen::ArrayXd sq = ys.square();
  m.rms = std::sqrt((0.5 * (sq.head(n - 1) + sq.tail(n - 1)) * dt).sum() / span);
  m.peak = ys.abs().maxCoeff();
  m.max = ys.maxCoeff();
  return m;
}

}  // namespace rollerdyn
