#include "analysis/RunResult.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace rollerdyn {

double EnergyAudit::residualRelative() const {
  const double scale = std::max({std::abs(motor_work), std::abs(kinetic_initial),
                                 std::abs(kinetic_final), std::abs(load_work), 1e-300});
  return residual() / scale;
}

bool rowIsFinite(const std::vector<double>& row) {
  return std::all_of(row.begin(), row.end(), [](double v) { return std::isfinite(v); });
}

std::string statusAt(const char* what, double t) {
  std::ostringstream os;
  os.precision(4);
  os << what << " at t = " << t << " s";
  return os.str();
}

}  // namespace rollerdyn
