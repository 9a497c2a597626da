#include "analysis/BearingLoad.h"

#include <Eigen/Core>
#include <cmath>
#include <limits>

namespace rollerdyn {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kTwoPi = 6.283185307179586476925286766559;

using ConstVecMap = Eigen::Map<const Eigen::ArrayXd>;

// ∫ y dt over the rows by the trapezoidal rule.
double trapezoid(const Eigen::ArrayXd& t, const Eigen::ArrayXd& y) {
  const Eigen::Index m = t.size();
  const Eigen::ArrayXd dt = t.tail(m - 1) - t.head(m - 1);
  return (0.5 * (y.head(m - 1) + y.tail(m - 1)) * dt).sum();
}

}  // namespace

JointLoad jointLoad(const std::vector<double>& t, const std::vector<double>& force,
                    const std::vector<double>& speed, std::size_t begin, std::size_t end) {
  JointLoad j{kNaN, kNaN, kNaN, kNaN, kNaN};
  const bool rotating = !speed.empty();
  if (end > t.size() || end > force.size() || (rotating && end > speed.size()) || end < begin + 2)
    return j;
  const Eigen::Index m = static_cast<Eigen::Index>(end - begin);
  const ConstVecMap ts(t.data() + begin, m), f(force.data() + begin, m);
  const Eigen::ArrayXd n = rotating ? Eigen::ArrayXd(ConstVecMap(speed.data() + begin, m).abs())
                                    : Eigen::ArrayXd::Ones(m);
  if (!ts.allFinite() || !f.allFinite() || !n.allFinite()) return j;
  const double span = ts(m - 1) - ts(0);
  if (!(span > 0)) return j;
  j.mean = trapezoid(ts, f) / span;
  j.amplitude = 0.5 * (f.maxCoeff() - f.minCoeff());
  j.peak = f.abs().maxCoeff();
  const double weight = trapezoid(ts, n);
  if (!(weight > 0)) return {j.mean, j.amplitude, j.peak, kNaN, kNaN};
  const Eigen::ArrayXd cubed = f.abs().pow(kBearingLifeExponent) * n;
  j.equivalent = std::pow(trapezoid(ts, cubed) / weight, 1.0 / kBearingLifeExponent);
  j.mean_speed = rotating ? weight / span : kNaN;
  return j;
}

double ratingLifeRevolutions(double C, double P, double p) {
  if (!(C > 0) || !(P > 0)) return kNaN;
  return std::pow(C / P, p) * 1e6;
}

double ratingLifeHours(double C, double P, double mean_speed, double p) {
  const double rev = ratingLifeRevolutions(C, P, p);
  if (!std::isfinite(rev) || !(mean_speed > 0)) return kNaN;
  return rev / (mean_speed / kTwoPi * 3600.0);
}

double rodSwingAmplitude(double r, double l) {
  if (!(r > 0) || !(l > r)) return kNaN;
  return std::asin(r / l);
}

double oscillationLife(double life_revolutions, double full_angle) {
  if (!std::isfinite(life_revolutions) || !(full_angle > 0)) return kNaN;
  return life_revolutions * (0.5 * kTwoPi) / full_angle;
}

double rollingElementsForOscillation(double full_angle) {
  if (!(full_angle > 0)) return kNaN;
  return 2.0 * kTwoPi / full_angle;
}

}  // namespace rollerdyn
