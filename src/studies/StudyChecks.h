// Validation items of the studies layer (src/compare/ValidationItems.h): every row of a sweep and
// every evaluation of an optimization against a separate run of its own point.
#pragma once

#include "compare/ValidationItems.h"

namespace rollerdyn::validation {

// A sweep over four crank offsets and a short optimization, both with the reduced model; each
// row's metrics against the summary of the same point run on its own (StudyChecks.cpp).
ValidationSection sweepRowChecks(const ItemContext& ctx);

}  // namespace rollerdyn::validation
