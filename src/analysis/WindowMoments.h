// Time mean, RMS and peaks of a column over rows of a run, the drive sizing's reading of a
// window: internal to the drive sizing (DriveSizing.cpp, MotorSizing.cpp).
#pragma once

#include <cstddef>
#include <limits>
#include <vector>

namespace rollerdyn {

// Time mean and RMS of y over rows [b, e) (trapezoidal rule), and max |y|; NaN where the rows do
// not span a time or hold a non-finite value.
struct Moments {
  double mean = std::numeric_limits<double>::quiet_NaN(), rms = std::numeric_limits<double>::quiet_NaN(),
         peak = std::numeric_limits<double>::quiet_NaN(), max = std::numeric_limits<double>::quiet_NaN();
};

Moments moments(const std::vector<double>& t, const std::vector<double>& y, std::size_t b, std::size_t e);

}  // namespace rollerdyn
