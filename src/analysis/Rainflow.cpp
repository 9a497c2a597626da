#include "analysis/Rainflow.h"

#include <cmath>

namespace rollerdyn {

std::vector<double> turningPoints(const std::vector<double>& y) {
  std::vector<double> tp;
  for (double v : y) {
    if (!std::isfinite(v)) continue;
    if (!tp.empty() && v == tp.back()) continue;  // a plateau counts once
    // The last kept point is no turning point when the signal goes on the same way through it.
    if (tp.size() >= 2 && (tp.back() - tp[tp.size() - 2]) * (v - tp.back()) > 0) tp.back() = v;
    else tp.push_back(v);
  }
  return tp;
}

namespace {

RainflowCycle cycleOf(double a, double b, double count) { return {std::abs(b - a), 0.5 * (a + b), count}; }

// ASTM E1049-85 5.4.4, steps 2 to 5, after a point is pushed onto the stack (the points not yet
// discarded; stack[0] is the starting point S): count each range X that is not smaller than Y.
void countClosedRanges(std::vector<double>& stack, std::vector<RainflowCycle>& out) {
  while (stack.size() >= 3) {
    const std::size_t n = stack.size();
    const double X = std::abs(stack[n - 1] - stack[n - 2]);
    const double Y = std::abs(stack[n - 2] - stack[n - 3]);
    if (X < Y) break;
    if (n == 3) {
      // Y holds the starting point: a half cycle, S moves to Y's second point.
      out.push_back(cycleOf(stack[0], stack[1], 0.5));
      stack.erase(stack.begin());
    } else {
      out.push_back(cycleOf(stack[n - 3], stack[n - 2], 1.0));
      stack.erase(stack.begin() + static_cast<long>(n) - 3, stack.begin() + static_cast<long>(n) - 1);
    }
  }
}

}  // namespace

std::vector<RainflowCycle> rainflow(const std::vector<double>& y) {
  const std::vector<double> tp = turningPoints(y);
  std::vector<RainflowCycle> out;
  std::vector<double> stack;  // the points not yet discarded; stack[0] is the starting point S
  for (double p : tp) {
    stack.push_back(p);
    countClosedRanges(stack, out);
  }
  // Step 6: the residue, each range a half cycle.
  for (std::size_t i = 0; i + 1 < stack.size(); ++i) out.push_back(cycleOf(stack[i], stack[i + 1], 0.5));
  return out;
}

}  // namespace rollerdyn
