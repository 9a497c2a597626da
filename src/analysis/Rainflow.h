// Rainflow counting after ASTM E1049-85 (reapproved 2017), "Standard Practices for Cycle Counting
// in Fatigue Analysis", section 5.4.4 (rainflow counting, the three-point method): the history is
// first reduced to its turning points (peaks and valleys; the first and last points count as
// turning points, repeated values as one), then
//   X = the range of the latest two points, Y = the range before it;
//   X < Y: read the next point; X >= Y: if Y holds the starting point S, Y is a half cycle, its
//   first point is dropped and S moves to its second; otherwise Y is one cycle and both its points
//   are dropped; compare again;
//   at the end every range left (the residue) counts as a half cycle.
// Pure functions of the samples: no time, no units (a cycle has the signal's unit).
#pragma once

#include <vector>

namespace rollerdyn {

struct RainflowCycle {
  double range = 0;  // |b - a| [signal's unit]
  double mean = 0;   // (a + b)/2 [signal's unit]
  double count = 0;  // 1 (a closed cycle) or 0.5 (a half cycle: the start's or the residue's)
};

// The peaks and valleys of y, in order: a point is kept where the signal turns; the first and the
// last point are kept; runs of equal values count once.
std::vector<double> turningPoints(const std::vector<double>& y);

// Rainflow cycles of y (turning points extracted first), in the order they are counted.
std::vector<RainflowCycle> rainflow(const std::vector<double>& y);

}  // namespace rollerdyn
