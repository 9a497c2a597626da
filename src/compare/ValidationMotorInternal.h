// Internals of validation section (5), the induction-motor laws (ValidationMotor.cpp; the
// catalogue fits in ValidationMotorCatalogue.cpp): how its numbers are written. Not a public header.
#pragma once

#include <cstdio>
#include <string>

#include "compare/ValidationSuite.h"
#include "io/FieldFormat.h"

namespace rollerdyn::validation::motor_detail {

using Verdict = Finding::Verdict;

inline std::string g(double v, int prec = 4) { return significant(v, prec); }
inline std::string pct(double rel, int prec = 2) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%+.*f %%", prec, 100.0 * rel);
  return buf;
}

// M8, M9: the catalogue fit of a scene's motor (double cage) at every catalogue point, and its
// rated, starting and breakdown torques against the paper's printed ones (each within 3 %).
MotorClaim catalogueFit(const ValidationOptions& o, const std::string& file, const std::string& motor, double m_n_printed,
                        double m_s_printed, double m_k_printed, const std::string& id);

}  // namespace rollerdyn::validation::motor_detail
