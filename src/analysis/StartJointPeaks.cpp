#include "analysis/StartJointPeaks.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace rollerdyn {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The joint reactions of one kind at row i: the largest |force| over the carts, and its column.
struct JointKind {
  const char* joint;
  std::vector<std::vector<double>> x, y;  // per cart: component columns (y empty: a scalar force)
  std::vector<std::string> names;
};

std::vector<JointKind> jointKinds(const Table& r) {
  std::vector<JointKind> kinds;
  auto scalar = [&](const char* joint, const std::string& prefix) {
    JointKind k{joint, {}, {}, {}};
    for (int j = 1; r.has(prefix + std::to_string(j)); ++j) {
      k.x.push_back(r.column(prefix + std::to_string(j)));
      k.names.push_back(prefix + std::to_string(j));
    }
    if (!k.x.empty()) kinds.push_back(std::move(k));
  };
  scalar("guide_roller_front", "N_front_");
  scalar("guide_roller_rear", "N_rear_");
  scalar("rod_force", "F_rod_");
  JointKind pin{"crank_pin", {}, {}, {}};
  for (int j = 1; r.has("crankpin_x_" + std::to_string(j)); ++j) {
    pin.x.push_back(r.column("crankpin_x_" + std::to_string(j)));
    pin.y.push_back(r.column("crankpin_y_" + std::to_string(j)));
    pin.names.push_back("crankpin_x_" + std::to_string(j) + "|crankpin_y_" + std::to_string(j));
  }
  if (!pin.x.empty()) kinds.push_back(std::move(pin));
  JointKind each{"main_bearing", {}, {}, {}};  // each bearing when crankshaft.bearing_positions places them
  for (int k = 1; r.has("bearing_x_" + std::to_string(k)); ++k) {
    each.x.push_back(r.column("bearing_x_" + std::to_string(k)));
    each.y.push_back(r.column("bearing_y_" + std::to_string(k)));
    each.names.push_back("bearing_x_" + std::to_string(k) + "|bearing_y_" + std::to_string(k));
  }
  if (!each.x.empty())
    kinds.push_back(std::move(each));
  else if (r.has("bearing_x") && r.has("bearing_y"))
    kinds.push_back({"main_bearing", {r.column("bearing_x")}, {r.column("bearing_y")}, {"bearing_x|bearing_y"}});
  return kinds;
}

double magnitude(const JointKind& k, std::size_t cart, std::size_t i) {
  const double x = k.x[cart][i];
  return k.y.empty() ? std::abs(x) : std::hypot(x, k.y[cart][i]);
}

}  // namespace

void addStartJointPeaks(const Table& reactions, RowSpan start, RowSpan steady, StartUp& r) {
  for (const JointKind& k : jointKinds(reactions)) {
    StartJointPeak p;
    p.joint = k.joint;
    double best = -1, largest_steady = 0;
    for (std::size_t j = 0; j < k.x.size(); ++j) {
      for (std::size_t i = start.begin; i < start.end; ++i)
        if (magnitude(k, j, i) > best) best = magnitude(k, j, i), p.column = k.names[j];
      for (std::size_t i = steady.begin; i < steady.end; ++i) largest_steady = std::max(largest_steady, magnitude(k, j, i));
    }
    p.start_peak = best;
    p.steady_peak = largest_steady;
    p.ratio = largest_steady > 0 ? best / largest_steady : kNaN;
    r.joints.push_back(p);
  }
}

}  // namespace rollerdyn
