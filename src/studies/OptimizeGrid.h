// The global stage of `rollerdyn optimize --method auto`: the designs it evaluates over the whole
// ranges of the parameters (Optimizer.cpp).
#pragma once

#include <vector>

#include "studies/Optimizer.h"

namespace rollerdyn {

// The global stage's designs, in the unit box of the parameters' ranges: a uniform grid over the
// whole box (19 values of one parameter, 7 of each of two, 5 of each of three or more), plus, for
// the crank offset, the evenly spread layouts Δφ = k·360°/n of the scene's n carts.
std::vector<std::vector<double>> globalGrid(const OptimizeOptions& o);

}  // namespace rollerdyn
