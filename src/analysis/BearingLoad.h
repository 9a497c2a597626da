// What a designer picks a rolling bearing or a pin with, from a joint force history: mean,
// amplitude and peak of the force, and the equivalent dynamic load of ISO 281 style for a
// varying load, each instant weighted by the joint's rotation speed,
//   P = ( ∫ |F|^p · n dt / ∫ n dt )^(1/p),   p = 3 (ball bearings; ISO 281 uses 10/3 for rollers),
// and the basic rating life L10 = (C/P)^p · 10⁶ revolutions, in hours at the mean speed n̄:
//   L10h = L10 / (n̄/(2π) · 3600),   n̄ = ∫ n dt / ∫ dt  [rad/s].
// A joint that oscillates through the full angle 2γ (end to end) f times a second is weighted by
// its swing speed, and its life converted (Harris and Kotzalas (2007); SKF rolling bearings
// catalogue, "oscillating movements"):
//   L10_osc = L10·180°/(2γ) oscillations,   L10h = L10_osc/(3600·f),
// valid while 2γ exceeds the critical angle 720°/Z of a bearing with Z rolling elements (below it
// the rolling elements' loaded zones do not overlap: the conversion does not hold). Without a
// speed every instant counts equally (n ≡ 1). Integrals use the trapezoidal rule on the output
// rows, as the other window metrics (Metrics.h), so unevenly spaced rows do not bias them.
#pragma once

#include <cstddef>
#include <vector>

namespace rollerdyn {

inline constexpr double kBearingLifeExponent = 3.0;  // p of L10 = (C/P)^p, ball bearings [-]

struct JointLoad {
  double mean = 0;        // time mean of the signed force [N]
  double amplitude = 0;   // (max - min)/2 [N]
  double peak = 0;        // max |F| [N]
  double equivalent = 0;  // P, speed-weighted cubic mean of |F| [N]
  double mean_speed = 0;  // n̄, time mean of the joint's rotation speed [rad/s]; NaN when not rotating
};

// Rows [begin, end) of t, force and speed (speed empty: the joint does not rotate, n ≡ 1).
// Every field is NaN when the window has fewer than two rows, a non-finite value, or (with a
// speed) no rotation at all.
JointLoad jointLoad(const std::vector<double>& t, const std::vector<double>& force,
                    const std::vector<double>& speed, std::size_t begin, std::size_t end);

// L10 in revolutions, (C/P)^p·10⁶ [-]; NaN unless C > 0 and P > 0.
double ratingLifeRevolutions(double dynamic_rating, double equivalent_load,
                             double exponent = kBearingLifeExponent);
// L10 in hours at mean speed n̄ [rad/s]; NaN unless n̄ > 0 and the life in revolutions is finite.
double ratingLifeHours(double dynamic_rating, double equivalent_load, double mean_speed,
                       double exponent = kBearingLifeExponent);

// The swing amplitude γ = β_max = asin(r/l) of the rod about the cart's pin of a centred
// crank-slider (sin β = (r/l)·sin θ) [rad]; NaN unless 0 < r < l.
double rodSwingAmplitude(double crank_radius, double rod_length);
// L10 in oscillations through the full angle 2γ [rad]: L10·180°/(2γ) = L10·π/(2γ) [-]; NaN unless
// the life is finite and 2γ > 0.
double oscillationLife(double life_revolutions, double full_angle);
// The least number of rolling elements Z for which the full swing 2γ [rad] reaches the critical
// angle 720°/Z (the conversion above holds): 4π/(2γ) [-]; NaN unless 2γ > 0.
double rollingElementsForOscillation(double full_angle);

}  // namespace rollerdyn
