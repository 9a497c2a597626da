#include "physics/SliderCrank.h"

#include <cmath>
#include <stdexcept>

namespace rollerdyn {
namespace {

void checkPreconditions(double r, double l, int side) {
  if (!(r > 0.0)) throw std::invalid_argument("slider-crank: crank radius r must be > 0");
  if (!(l > r)) throw std::invalid_argument("slider-crank: rod length l must exceed r");
  if (side != 1 && side != -1) throw std::invalid_argument("slider-crank: side must be +1 or -1");
}

// Rod angle and its derivatives; shared by both forms (eq. (31), (44)).
void fillRod(double theta, double r, double l, int side, SliderCrankPose& p) {
  const double lam = r / l, S = std::sin(theta), C = std::cos(theta);
  const double w = std::sqrt(1.0 - lam * lam * S * S);  // cos β
  p.beta = std::asin(lam * S);
  p.dbeta = lam * C / w;
  p.d2beta = -lam * S * (1.0 - lam * lam) / (w * w * w);
  (void)side;
  // Rod centre of mass is mid-way between A and B.
  p.x_S = 0.5 * (r * C + p.x_B);
  p.y_S = 0.5 * r * S;
  p.dx_S = 0.5 * (-r * S + p.dx_B);
  p.dy_S = 0.5 * r * C;
  p.d2x_S = 0.5 * (-r * C + p.d2x_B);
  p.d2y_S = -0.5 * r * S;
}

}  // namespace

SliderCrankPose sliderCrankExact(double theta, double r, double l, int side) {
  checkPreconditions(r, l, side);
  const double lam = r / l, S = std::sin(theta), C = std::cos(theta), sg = side;
  const double w = std::sqrt(1.0 - lam * lam * S * S);
  SliderCrankPose p{};
  p.x_B = r * C + sg * l * w;
  // Loveikin and Pochka (2007) eq. (6): ∂x/∂φ = -r·sin θ·(1 ± (r/l)·cos θ / √(1 - (r/l)² sin² θ))
  p.dx_B = -r * S - sg * r * lam * S * C / w;
  // d/dθ (S·C/w) = (C² - S²)/w + λ²·S²·C²/w³
  p.d2x_B = -r * C - sg * r * lam * ((C * C - S * S) / w + lam * lam * S * S * C * C / (w * w * w));
  fillRod(theta, r, l, side, p);
  return p;
}

SliderCrankPose sliderCrankTruncated(double theta, double r, double l, int side) {
  checkPreconditions(r, l, side);
  const double lam = r / l, S = std::sin(theta), C = std::cos(theta), sg = side;
  SliderCrankPose p{};
  // eq. (52): x_B = r·cos θ + l·[1 - ½(r/l)² sin² θ]   (σ = -1 mirrors the rod term)
  p.x_B = r * C + sg * l * (1.0 - 0.5 * lam * lam * S * S);
  // eq. (56): ∂x_B/∂θ = -r·(sin θ + r/(2l)·sin 2θ)
  p.dx_B = -r * (S + sg * 0.5 * lam * std::sin(2.0 * theta));
  // eq. (57): ∂²x_B/∂θ² = -r·(cos θ + (r/l)·cos 2θ)
  p.d2x_B = -r * (C + sg * lam * std::cos(2.0 * theta));
  fillRod(theta, r, l, side, p);
  return p;
}

}  // namespace rollerdyn
