// The optimal-reversal motion law of Loveikin and Pochka (cam drive paper) and its cam profile (src/physics/CamMotionLaw.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "physics/CamMotionLaw.h"

namespace rollerdyn {
namespace {

constexpr double kStroke = 0.4;  // Loveikin and Pochka (cam drive paper) example Δx [m]
constexpr double kT3 = 3.0;      // Loveikin and Pochka (cam drive paper) example t3 [s]

double component(const CamMotionSample& s, int k) {
  return k == 0 ? s.x : k == 1 ? s.dx : k == 2 ? s.d2x : s.d3x;
}

// Largest |x^(k)| over one cam turn (fine grid), the scale each derivative is judged against.
double scale(int k) {
  double m = 0;
  for (int i = 0; i <= 72000; ++i) m = std::max(m, std::abs(component(camMotion(2 * M_PI * i / 72000, kStroke), k)));
  return m;
}

TEST(CamMotionLaw, ContinuousUpToJerkWhereSegmentsJoin) {
  // Joins of eq. (32)-(34) and (41)-(43): π/6, 5π/6, π, 7π/6, 11π/6, 2π ≡ 0.
  const double joins[] = {M_PI / 6, 5 * M_PI / 6, M_PI, 7 * M_PI / 6, 11 * M_PI / 6, 2 * M_PI};
  // Either side of a join at ±ε: a continuous x^(k) changes by at most 2ε·max|x^(k+1)|, and the
  // ratio max|x^(k+1)|/max|x^(k)| is ~ 1/(segment angle π/6·…) < 100 rad⁻¹ here, so with
  // ε = 1e-9 rad the change is < 2e-7 of the scale; a step would be of the order of the scale
  // itself. Tolerance 1e-6 of each derivative's scale.
  const double eps = 1e-9;
  for (int k = 0; k <= 3; ++k) {
    const double tol = 1e-6 * scale(k);
    for (double th : joins) {
      const double left = component(camMotion(th - eps, kStroke), k);
      const double right = component(camMotion(th + eps, kStroke), k);
      EXPECT_NEAR(left, right, tol) << "derivative " << k << " at theta = " << th;
    }
  }
  // Acceleration and jerk are zero at every join (eq. (28)-(31): ẍ = x⃛ = 0 where start, constant
  // speed and braking meet).
  for (double th : joins) {
    EXPECT_NEAR(camMotion(th, kStroke).d2x, 0.0, 1e-9 * scale(2)) << th;
    EXPECT_NEAR(camMotion(th, kStroke).d3x, 0.0, 1e-9 * scale(3)) << th;
  }
}

TEST(CamMotionLaw, FourthDerivativeJumpsSoTheLawIsExactlyC3) {
  // Snap from central differences of the jerk on either side of θ = π/6: 15552Δx·(216τ² - 36τ + 1)
  // /π⁴ at τ = 1/6 from the start segment (= 15552Δx/π⁴), 0 on the constant-speed segment.
  const double h = 1e-6, th = M_PI / 6;
  const double snap_left = (camMotion(th - h, kStroke).d3x - camMotion(th - 3 * h, kStroke).d3x) / (2 * h);
  const double snap_right = (camMotion(th + 3 * h, kStroke).d3x - camMotion(th + h, kStroke).d3x) / (2 * h);
  const double expected = 15552 * kStroke / std::pow(M_PI, 4);
  EXPECT_NEAR(snap_left, expected, 1e-3 * expected);
  EXPECT_NEAR(snap_right, 0.0, 1e-9);
}

TEST(CamMotionLaw, DerivativesAreThoseOfThePosition) {
  // Central differences, h = 1e-4 rad, away from the joins: truncation h²/6·|x^(k+3)| ≤ 1e-8·
  // max|x^(k+3)| and round-off ~1e-16·|x|/h are far below 1e-5 of each scale.
  const double h = 1e-4;
  for (double th : {0.1, 0.3, 1.0, 2.0, 2.8, 3.3, 3.9, 5.0, 6.0}) {
    const CamMotionSample p = camMotion(th + h, kStroke), m = camMotion(th - h, kStroke), c = camMotion(th, kStroke);
    EXPECT_NEAR((p.x - m.x) / (2 * h), c.dx, 1e-5 * scale(1)) << th;
    EXPECT_NEAR((p.dx - m.dx) / (2 * h), c.d2x, 1e-5 * scale(2)) << th;
    EXPECT_NEAR((p.d2x - m.d2x) / (2 * h), c.d3x, 1e-5 * scale(3)) << th;
  }
}

TEST(CamMotionLaw, KeyValuesOfCamDrivePaper) {
  // Ends of the stroke, x1 = Δx/10 (eq. (28)), constant speed 6Δx/(5t3) (eq. (28)), i.e.
  // 6Δx/(5π) per radian of cam.
  EXPECT_NEAR(camMotion(0, kStroke).x, -kStroke / 2, 1e-15);
  EXPECT_NEAR(camMotion(M_PI, kStroke).x, kStroke / 2, 1e-15);
  EXPECT_NEAR(camMotion(M_PI / 6, kStroke).x, -kStroke / 2 + kStroke / 10, 1e-15);
  EXPECT_NEAR(camMotion(5 * M_PI / 6, kStroke).x, kStroke / 2 - kStroke / 10, 1e-15);
  EXPECT_NEAR(camMotion(M_PI / 2, kStroke).dx, 6 * kStroke / (5 * M_PI), 1e-15);
  EXPECT_NEAR(camMotion(3 * M_PI / 2, kStroke).dx, -6 * kStroke / (5 * M_PI), 1e-15);
  // Periodic and mirrored: x(θ + 2π) = x(θ), x(θ + π) = -x(θ) (eq. (41)-(43)).
  for (double th : {0.2, 1.1, 2.9}) {
    EXPECT_NEAR(camMotion(th + 2 * M_PI, kStroke).x, camMotion(th, kStroke).x, 1e-14);
    EXPECT_NEAR(camMotion(th - 2 * M_PI, kStroke).x, camMotion(th, kStroke).x, 1e-14);
    EXPECT_NEAR(camMotion(th + M_PI, kStroke).x, -camMotion(th, kStroke).x, 1e-14);
  }
}

TEST(CamMotionLaw, CamAngleFormIsThePrintedTimeLawAtConstantSpeed) {
  // θ = πt/t3 (text after eq. (37)): eq. (29)-(31), printed with their own v, a, jerk, must equal
  // the cam-angle law and its θ-derivatives times (π/t3)^k, shifted by Δx/2 (eq. (32)-(34)).
  const double w = M_PI / kT3;
  for (int i = 0; i <= 600; ++i) {
    const double t = kT3 * i / 600.0;
    const CamTimeSample ts = camMotionTime(t, kStroke, kT3);
    const CamMotionSample cs = camMotion(w * t, kStroke);
    EXPECT_NEAR(ts.x - kStroke / 2, cs.x, 1e-12) << t;
    EXPECT_NEAR(ts.v, cs.dx * w, 1e-12) << t;
    EXPECT_NEAR(ts.a, cs.d2x * w * w, 1e-11) << t;
    EXPECT_NEAR(ts.jerk, cs.d3x * w * w * w, 1e-10) << t;
  }
}

TEST(CamProfile, ConstantDiameterAndPrintedFormulas) {
  const double b = 0.8;
  // Literal eq. (38)-(43).
  auto printed = [&](double f) {
    const double dx = kStroke, P = M_PI;
    if (f <= P / 6) return b / 2 + 648 * dx / 5 * (72 * std::pow(f / P, 6) - 36 * std::pow(f / P, 5) + 5 * std::pow(f / P, 4)) - dx / 2;
    if (f < 5 * P / 6) return b / 2 + 2 * dx / 5 * (3 * (f - P / 6) / P - 1);
    if (f <= P) {
      const double s = (f - 5 * P / 6) / P;
      return b / 2 + dx / 2 - 3 * dx / 5 * (15552 * std::pow(s, 6) - 7776 * std::pow(s, 5) + 1080 * std::pow(s, 4) - 2 * s + 1.0 / 6);
    }
    if (f <= 7 * P / 6) {
      const double s = (f - P) / P;
      return b / 2 - 648 * dx / 5 * (72 * std::pow(s, 6) - 36 * std::pow(s, 5) + 5 * std::pow(s, 4)) + dx / 2;
    }
    // eq. (42) corrected: printed as b/2 - (2Δx/5)[1 - 3(φ - 7π/6)/π] + Δx/2, which starts at
    // b/2 + 0.1Δx where (41) ends at b/2 + 0.4Δx and ends at b/2 + 0.9Δx, beyond the cam's
    // largest radius b/2 + Δx/2; ρ(φ + π) = b - ρ(φ) applied to (39) gives the line below.
    if (f < 11 * P / 6) return b / 2 + 2 * dx / 5 * (1 - 3 * (f - 7 * P / 6) / P);
    const double s = (f - 11 * P / 6) / P;
    return b / 2 - dx / 2 + 3 * dx / 5 * (15552 * std::pow(s, 6) - 7776 * std::pow(s, 5) + 1080 * std::pow(s, 4) - 2 * s + 1.0 / 6);
  };
  // The misprint of eq. (42): its printed form does not join (41) at 7π/6 nor (43) at 11π/6.
  auto printed42 = [&](double f) { return b / 2 - 2 * kStroke / 5 * (1 - 3 * (f - 7 * M_PI / 6) / M_PI) + kStroke / 2; };
  EXPECT_NEAR(printed42(7 * M_PI / 6), b / 2 + 0.1 * kStroke, 1e-12);
  EXPECT_NEAR(printed(7 * M_PI / 6), b / 2 + 0.4 * kStroke, 1e-12);  // (41) at its end
  EXPECT_NEAR(printed42(11 * M_PI / 6), b / 2 + 0.9 * kStroke, 1e-12);
  for (int i = 0; i <= 720; ++i) {
    const double th = 2 * M_PI * i / 720;
    EXPECT_NEAR(camProfileRadius(th, kStroke, b), printed(th), 1e-12) << th;
    // The diameter through the cam centre is b in every position (text after eq. (43)): both
    // pushers stay in contact and the cam cannot knock.
    EXPECT_NEAR(camProfileRadius(th, kStroke, b) + camProfileRadius(th + M_PI, kStroke, b), b, 1e-12) << th;
  }
}

}  // namespace
}  // namespace rollerdyn
