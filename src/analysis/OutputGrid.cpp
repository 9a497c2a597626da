#include "analysis/OutputGrid.h"

#include <cmath>
#include <stdexcept>

namespace rollerdyn {

std::vector<double> outputTimes(const SimulationSettings& s) {
  if (!(s.output_step > 0.0) || !(s.t_end > 0.0))
    throw std::invalid_argument("simulation.t_end and output_step must be > 0");
  std::vector<double> t;
  // The 1e-9 keeps t_end itself on the grid when round-off puts t_end/h just below an integer.
  const long n = static_cast<long>(std::floor(s.t_end / s.output_step + 1e-9));
  for (long k = 0; k <= n; ++k) t.push_back(k * s.output_step);
  if (s.t_end - t.back() > 1e-9 * s.output_step) t.push_back(s.t_end);
  return t;
}

}  // namespace rollerdyn
