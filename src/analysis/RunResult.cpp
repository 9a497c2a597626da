#include "analysis/RunResult.h"

#include <algorithm>
#include <cmath>

namespace rollerdyn {

double EnergyAudit::residualRelative() const {
  const double scale = std::max({std::abs(motor_work), std::abs(kinetic_initial),
                                 std::abs(kinetic_final), std::abs(load_work), 1e-300});
  return residual() / scale;
}

}  // namespace rollerdyn
