// The joints' reaction peaks over a start in the start-up answers (StartUp.h): internal to StartUp.cpp.
#pragma once

#include "analysis/StartUp.h"
#include "analysis/StartUpRows.h"
#include "io/Table.h"

namespace rollerdyn {

// Appends to r.joints, per kind of joint in the reactions table (guide rollers front and rear,
// rods, crank pins, main bearings), the largest reaction over the carts in the start's rows, the
// column it came from, the largest in the steady rows, and their ratio. The reactions table shares
// the timeseries' output grid (same rows).
void addStartJointPeaks(const Table& reactions, RowSpan start, RowSpan steady, StartUp& r);

}  // namespace rollerdyn
