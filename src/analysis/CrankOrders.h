// Harmonics of a quantity in orders of the crank rotation, measured on a run's output: the
// amplitude of order k (k cycles per crank revolution) of y over the last whole revolutions.
//
// The crank angle, not time, is the variable: y(φ) is expanded over φ in [φ_end - 2π·R, φ_end]
// (R whole revolutions ending at the last row),
//   a_k = 1/(π·R) ∫ y cos(kφ) dφ,   b_k = 1/(π·R) ∫ y sin(kφ) dφ,   A_k = √(a_k² + b_k²),
// by the trapezoidal rule on the output rows (the first row is interpolated to the window's
// start). So A_k is the amplitude of y = A_0 + Σ A_k cos(kφ + ·) [units of y], whatever the speed
// fluctuation, and a steady drive's order content (the layout's phase sums,
// studies/ResonanceCheck.h) reads directly. Bound used by the validation: for two series y, z on
// the same rows, |A_k(y) - A_k(z)| <= A_k(y - z) <= 2·max|y - z|.
#pragma once

#include <string>
#include <vector>

#include "io/Table.h"

namespace rollerdyn {

struct CrankOrderAmplitudes {
  bool valid = false;             // false: the crank did not turn R whole revolutions forward
  int revolutions = 0;            // R
  double t_begin = 0, t_end = 0;  // the window [s]
  std::vector<double> amplitude;  // A_0 (the mean), A_1, ..., A_max_order [units of y]
};

// Orders 0..max_order of column `column` of `ts` against its "phi_crank" column over the last
// `revolutions` crank revolutions. The crank must turn forward over the window (φ increasing);
// otherwise `valid` is false and the amplitudes are empty.
CrankOrderAmplitudes crankOrderAmplitudes(const Table& ts, const std::string& column, int revolutions,
                                          int max_order);

}  // namespace rollerdyn
