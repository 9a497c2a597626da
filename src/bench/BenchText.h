// Names and number formatting shared by the bench studies and their reports.
#pragma once

#include <cmath>
#include <sstream>
#include <string>

#include "bench/BenchRun.h"
#include "io/FieldFormat.h"

namespace rollerdyn::bench {

inline constexpr const char* kMultibody = "multibody";  // constrained formulation
inline constexpr const char* kReduced = "reduced";
inline constexpr const char* kMinimal = kMultibodyMinimal;

// A run that produced comparable tables (a stall is a physical end of the run).
inline bool usable(Outcome o) { return o == Outcome::Ok || o == Outcome::Stalled; }

// A number for the reports ("—" when not finite).
inline std::string num(double v, int precision = 3) { return significantOr(v, precision, "—"); }

}  // namespace rollerdyn::bench
