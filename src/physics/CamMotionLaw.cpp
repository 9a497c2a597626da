#include "physics/CamMotionLaw.h"

#include <cmath>
#include <stdexcept>

namespace rollerdyn {

namespace {

// Forward half (0 <= u <= 1, u = θ/π), about mid-stroke, per unit stroke; derivatives in u.
// Obtained from eq. (32)-(34) by differentiation (the time forms (29)-(31) print the same
// derivatives, which tests/studies check against this).
CamMotionSample forwardHalf(double u) {
  if (u <= kCamStartFraction) {  // start, eq. (32)
    const double u2 = u * u, u3 = u2 * u, u4 = u3 * u;
    const double k = 648.0 / 5.0;
    return {k * (72 * u4 * u2 - 36 * u4 * u + 5 * u4) - 0.5, k * (432 * u4 * u - 180 * u4 + 20 * u3),
            k * (2160 * u4 - 720 * u3 + 60 * u2), k * (8640 * u3 - 2160 * u2 + 120 * u)};
  }
  if (u < kCamBrakeFraction) {  // constant speed, eq. (33) in the segment's own time
    const double s = u - kCamStartFraction;
    return {0.4 * (3 * s - 1), 1.2, 0.0, 0.0};
  }
  // braking, eq. (34) in the segment's own time
  const double s = u - kCamBrakeFraction;
  const double s2 = s * s, s3 = s2 * s, s4 = s3 * s;
  const double k = 3.0 / 5.0;
  return {0.5 - k * (15552 * s4 * s2 - 7776 * s4 * s + 1080 * s4 - 2 * s + 1.0 / 6.0),
          -k * (93312 * s4 * s - 38880 * s4 + 4320 * s3 - 2),
          -k * (466560 * s4 - 155520 * s3 + 12960 * s2),
          -k * (1866240 * s3 - 466560 * s2 + 25920 * s)};
}

}  // namespace

CamMotionSample camMotion(double theta, double stroke) {
  const double two_pi = 2.0 * M_PI;
  double th = std::fmod(theta, two_pi);
  if (th < 0) th += two_pi;
  const bool ret = th >= M_PI;  // return half: x(θ) = -x(θ - π), eq. (41)-(43)
  const double u = (ret ? th - M_PI : th) / M_PI;
  CamMotionSample s = forwardHalf(u < 0 ? 0 : (u > 1 ? 1 : u));
  const double sign = ret ? -stroke : stroke;
  const double p = M_PI;
  return {sign * s.x, sign * s.dx / p, sign * s.d2x / (p * p), sign * s.d3x / (p * p * p)};
}

SliderCrankPose camDrivePose(double theta, double stroke, int side) {
  if (!(stroke > 0.0)) throw std::invalid_argument("cam drive: stroke must be > 0");
  if (side != 1 && side != -1) throw std::invalid_argument("cam drive: side must be +1 or -1");
  const CamMotionSample c = camMotion(theta, stroke);
  SliderCrankPose p{};
  p.x_B = side * c.x;
  p.dx_B = side * c.dx;
  p.d2x_B = side * c.d2x;
  return p;  // β, rod centre-of-mass terms: 0 (no rod)
}

CamTimeSample camMotionTime(double t, double dx, double t3) {
  // Loveikin and Pochka (cam drive paper) eq. (29)-(31) exactly as printed, each segment in its own local time.
  const double T2 = t3 * t3, T3 = T2 * t3, T4 = T3 * t3, T5 = T4 * t3, T6 = T5 * t3;
  if (t <= t3 / 6.0) {  // eq. (29)
    const double t2 = t * t, tt3 = t2 * t, tt4 = tt3 * t, tt5 = tt4 * t, tt6 = tt5 * t;
    return {648.0 * dx / 5.0 * (72 * tt6 / T6 - 36 * tt5 / T5 + 5 * tt4 / T4),
            2592.0 * dx / 5.0 * (108 * tt5 / T6 - 45 * tt4 / T5 + 5 * tt3 / T4),
            7776.0 * dx * (36 * tt4 / T6 - 12 * tt3 / T5 + t2 / T4),
            15552.0 * dx * (72 * tt3 / T6 - 18 * t2 / T5 + t / T4),
            15552.0 * dx * (216 * t2 / T6 - 36 * t / T5 + 1 / T4)};
  }
  if (t < 5.0 * t3 / 6.0) {  // eq. (30)
    const double s = t - t3 / 6.0;
    return {dx / 10.0 * (1 + 12 * s / t3), 6.0 * dx / (5.0 * t3), 0.0, 0.0, 0.0};
  }
  const double s = t - 5.0 * t3 / 6.0;  // eq. (31)
  const double s2 = s * s, s3 = s2 * s, s4 = s3 * s, s5 = s4 * s, s6 = s5 * s;
  return {dx - 3.0 * dx / 5.0 * (15552 * s6 / T6 - 7776 * s5 / T5 + 1080 * s4 / T4 - 2 * s / t3 + 1.0 / 6.0),
          -6.0 * dx / 5.0 * (46656 * s5 / T6 - 19440 * s4 / T5 + 2160 * s3 / T4 - 1.0 / t3),
          -7776.0 * dx * (36 * s4 / T6 - 12 * s3 / T5 + s2 / T4),
          -15552.0 * dx * (72 * s3 / T6 - 18 * s2 / T5 + s / T4),
          -15552.0 * dx * (216 * s2 / T6 - 36 * s / T5 + 1 / T4)};
}

double camProfileRadius(double theta, double stroke, double b) {
  return 0.5 * b + camMotion(theta, stroke).x;  // eq. (38)-(43)
}

double brakingSnap(double t, double x1, double v, double t2) {
  const double T = t / t2, q = x1 / t2;  // eq. (10)
  return 120.0 / (t2 * t2 * t2) *
         (70 * (v - 2 * q) * T * T * T + 6 * (35 * q - 18 * v) * T * T + 3 * (15 * v - 28 * q) * T +
          (7 * q - 4 * v));
}

double startSnap(double t, double x1, double v, double tn) {
  const double T = t / tn, q = x1 / tn;  // eq. (16)
  return 120.0 / (tn * tn * tn) *
         (70 * (2 * q - v) * T * T * T + 6 * (17 * v - 35 * q) * T * T + 3 * (28 * q - 13 * v) * T +
          (3 * v - 7 * q));
}

double reversalCriterionPart(double m, double x1, double v, double tp) {
  const double q = x1 / tp;  // eq. (11) / (17)
  return 7200.0 * m / std::pow(tp, 5) * (7 * q * q - 7 * q * v + 1.8 * v * v);
}

double reversalCriterion(double m, double x1, double v, double t1) {
  const double q = x1 / t1;  // eq. (19)
  return 7200.0 * m / std::pow(t1, 5) * (14 * q * q - 14 * q * v + 3.6 * v * v);
}

}  // namespace rollerdyn
