// Cam drive with optimal reversal of Loveikin and Pochka (Loveikin, Pochka, "Optimisation of the reversal of a roller forming
// installation by the third-order acceleration"): the cart follows the optimal-reversal motion
// law, start-up and braking each over 1/6 of a stroke, constant speed in between, every stroke
// made by half a turn of the cam.
//
// Time form, one stroke of duration t3 (the half-cycle time), position from the starting end
// (Loveikin and Pochka (cam drive paper) eq. (29)-(31), with x1 = Δx/10 and ẋ_y = 6Δx/(5·t3), eq. (28)):
//   start    0 <= t <= t3/6:      x = (648Δx/5)(72τ⁶ - 36τ⁵ + 5τ⁴),  τ = t/t3        (29)
//   constant t3/6 <= t <= 5t3/6:  x = (Δx/10)(1 + 12τ'),  τ' = (t - t3/6)/t3           (30)
//   braking  5t3/6 <= t <= t3:    x = Δx - (3Δx/5)(15552τ''⁶ - 7776τ''⁵ + 1080τ''⁴
//                                        - 2τ'' + 1/6),  τ'' = (t - 5t3/6)/t3         (31)
// (each segment of (29)-(31) runs on its own local time; eq. (33) and (39) confirm it.)
//
// Cam-angle form: one cam turn is one full cycle, t = θ/ω and t3 = π/ω at constant cam speed ω
// (text after eq. (37)), so τ = θ/π and the law becomes a function of the cam angle θ alone,
// measured about mid-stroke (eq. (32)-(34)) on the forward half 0 <= θ <= π, and mirrored,
// x(θ) = -x(θ - π), on the return half π <= θ <= 2π (eq. (41)-(43)). The cam radius touching the
// pusher is ρ(θ) = b/2 + x(θ) (eq. (38)-(43)), b = distance between the two pushers; the cam has
// constant diameter ρ(θ) + ρ(θ + π) = b (text after eq. (43)). Eq. (42) is misprinted: as
// printed, ρ = b/2 - (2Δx/5)[1 - 3(φ - 7π/6)/π] + Δx/2 starts at b/2 + 0.1Δx where (41) ends at
// b/2 + 0.4Δx; ρ = b/2 + x(θ) is (38)-(41), (43) exactly and (42) without the misprint.

//
// The law is C³: position, speed, acceleration and jerk are continuous where the segments join
// (acceleration and jerk are zero there); the fourth derivative (snap) jumps.
//
// Terminology: Loveikin and Pochka's (cam drive) "acceleration of the third order" is the FOURTH derivative of position
// (first order ẍ, second order x⃛, third order x⁗). Its criterion I_Z = (m/2)∫(x⁗)² dt (eq. (1),
// (2), (11)) has the Euler-Poisson equation x⁽⁸⁾ = 0 (eq. (3)-(5)); eq. (10) and (16) are x⁗ of
// braking and start, and eq. (5)'s printed dots are garbled (its chain x⁽⁸⁾ ... x⁗, x⃛, ẍ, ẋ, x
// with constants C1 ... C8 fixes the orders). The fourth quantity listed in eq. (23), (25),
// (29)-(31) is x⃛ (jerk), the derivative of the listed ẍ.
#pragma once

#include "physics/SliderCrank.h"

namespace rollerdyn {

// Position about mid-stroke and its derivatives with respect to the cam angle θ.
struct CamMotionSample {
  double x;    // [m], in [-Δx/2, +Δx/2]; θ = 0 at the -Δx/2 end, moving towards +x
  double dx;   // ∂x/∂θ [m/rad]
  double d2x;  // ∂²x/∂θ² [m/rad²]
  double d3x;  // ∂³x/∂θ³ [m/rad³]
};

// x(θ) of Loveikin and Pochka (cam drive paper) eq. (32)-(34) / (41)-(43), 2π-periodic in θ (any finite θ). stroke = Δx > 0.
CamMotionSample camMotion(double theta, double stroke);

// The cam drive in the slider-crank's terms, so both models can use it where they use the
// transfer functions: x_B = σ·x(θ), ∂x_B/∂θ = σ·x', ∂²x_B/∂θ² = σ·x''; there is no rod, so β and
// the rod's centre-of-mass terms are 0 (the cam force on the cart is horizontal).
// Preconditions (checked, std::invalid_argument): stroke > 0, σ = ±1.
SliderCrankPose camDrivePose(double theta, double stroke, int side);

// Position from the starting end (0 ... Δx), speed, acceleration and jerk at time t within one
// stroke, 0 <= t <= t3 (Loveikin and Pochka (cam drive paper) eq. (29)-(31)); derivatives are with respect to time.
struct CamTimeSample {
  double x, v, a, jerk;  // [m], [m/s], [m/s²], [m/s³]
  double snap;           // x⁗ [m/s⁴]: d/dt of the printed jerk, the integrand of eq. (1)-(2)
};
CamTimeSample camMotionTime(double t, double stroke, double t3);

// Cam radius ρ(θ) = b/2 + x(θ) [m], Loveikin and Pochka (cam drive paper) eq. (38)-(43). b = pusher_distance > stroke.
double camProfileRadius(double theta, double stroke, double pusher_distance);

// Segment boundaries of one stroke as fractions of it: start ends at 1/6, braking begins at 5/6.
inline constexpr double kCamStartFraction = 1.0 / 6.0;
inline constexpr double kCamBrakeFraction = 5.0 / 6.0;

// --- Optimality criterion of the reversal (Loveikin and Pochka (cam drive paper) eq. (1)-(2): I_Z = (m/2)∫ (x⁗)² dt) ---

// x⁗ during braking from speed ẋ_y at x = -x1 to rest at x = 0 in time t2, with ẍ = x⃛ = 0 at
// both ends, for any x1 (Loveikin and Pochka (cam drive paper) eq. (6)-(10)) [m/s⁴].
double brakingSnap(double t, double x1, double speed, double t2);
// x⁗ during the start from rest at x = 0 to speed -ẋ_y at x = -x1 in time tn (eq. (12)-(16)).
double startSnap(double t, double x1, double speed, double tn);
// Closed-form criterion of one braking, eq. (11) (eq. (17) for a start has the same form)
// [kg·m²/s⁵].
double reversalCriterionPart(double mass, double x1, double speed, double t_part);
// Criterion of a whole reversal with t2 = tn = t1, eq. (19).
double reversalCriterion(double mass, double x1, double speed, double t1);
// The x1 that minimises eq. (19): x1 = ẋ_y·t1/2 (eq. (20)-(21)).
inline double optimalReversalDistance(double speed, double t1) { return 0.5 * speed * t1; }

}  // namespace rollerdyn
