// The checks of an optimization's options, made before any run (OptimizeOptions.cpp; the
// constraint's parser, parseConstraint, is declared in Optimizer.h).
#pragma once

#include "studies/Optimizer.h"

namespace rollerdyn {

// Throws std::invalid_argument naming the first option that is wrong: no --param, an unknown
// --model, a --param that is no scene key, given twice or with an empty range, an unknown metric
// to minimise or constrain, an unknown --method (bobyqa with constraints), and threads,
// evaluations or tolerance out of range.
void validateOptimizeOptions(const OptimizeOptions& o);

}  // namespace rollerdyn
