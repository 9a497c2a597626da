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

// A scalar force per cart: columns prefix1, prefix2, ...
JointKind scalarKind(const Table& r, const char* joint, const std::string& prefix) {
  JointKind k{joint, {}, {}, {}};
  for (int j = 1; r.has(prefix + std::to_string(j)); ++j) {
    k.x.push_back(r.column(prefix + std::to_string(j)));
    k.names.push_back(prefix + std::to_string(j));
  }
  return k;
}

// A force of two components per joint: columns <x>1, <y>1, <x>2, <y>2, ... (named "<x>j|<y>j").
JointKind planarKind(const Table& r, const char* joint, const std::string& x, const std::string& y) {
  JointKind k{joint, {}, {}, {}};
  for (int j = 1; r.has(x + std::to_string(j)); ++j) {
    k.x.push_back(r.column(x + std::to_string(j)));
    k.y.push_back(r.column(y + std::to_string(j)));
    k.names.push_back(x + std::to_string(j) + "|" + y + std::to_string(j));
  }
  return k;
}

std::vector<JointKind> jointKinds(const Table& r) {
  std::vector<JointKind> kinds, per_cart;
  per_cart.push_back(scalarKind(r, "guide_roller_front", "N_front_"));
  per_cart.push_back(scalarKind(r, "guide_roller_rear", "N_rear_"));
  per_cart.push_back(scalarKind(r, "rod_force", "F_rod_"));
  per_cart.push_back(planarKind(r, "crank_pin", "crankpin_x_", "crankpin_y_"));
  for (JointKind& k : per_cart)
    if (!k.x.empty()) kinds.push_back(std::move(k));
  // Each bearing when crankshaft.bearing_positions places them, else their resultant.
  JointKind each = planarKind(r, "main_bearing", "bearing_x_", "bearing_y_");
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
