// The shared pieces of the drive-sizing check by hand (ValidationSizing.cpp: the window, the
// crank speed, the motor, the coupling and flywheel; ValidationSizingJoints.cpp: the joints): a
// run's CSV tables read column-wise, its summary.json, the steady window, trapezoidal integrals
// and the comparison of reported figures with hand-computed ones. Not a public header.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "compare/ValidationItems.h"
#include "io/FieldFormat.h"
#include "scene/Scene.h"

namespace rollerdyn::validation::sizing_by_hand {

using nlohmann::json;
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
inline constexpr double kTwoPi = 6.283185307179586476925286766559;
inline constexpr double kRelative = 1e-9;  // ValidationSizing.cpp's file comment

inline std::string g(double v, int prec = 3) { return significantOr(v, prec, "n/a"); }

// A CSV as rollerdyn writes it (header of `name[unit]` cells, rows of numbers), read column-wise.
struct Csv {
  std::vector<std::string> names;
  std::vector<std::vector<double>> columns;
  bool has(const std::string& n) const { return std::find(names.begin(), names.end(), n) != names.end(); }
  const std::vector<double>& col(const std::string& n) const {
    const auto it = std::find(names.begin(), names.end(), n);
    if (it == names.end()) throw std::runtime_error("CSV has no column " + n);
    return columns[static_cast<std::size_t>(it - names.begin())];
  }
};

// The last `n` whole crank revolutions: revolution k runs from the first time φ reaches
// φ_0 + 2πk to the first time it reaches φ_0 + 2π(k+1) (linear between rows); the window's rows
// are those with t_begin <= t <= t_end.
struct Window {
  double t_begin = kNaN, t_end = kNaN;
  int revolutions = 0;
  std::size_t b = 0, e = 0;      // rows [b, e)
  std::vector<double> crossings; // t of φ_0 + 2πk, k = 0, 1, ... (the run's whole revolutions)
};

// ∫ y dt over rows [b, e) by trapezoids.
inline double integral(const std::vector<double>& t, const std::vector<double>& y, std::size_t b, std::size_t e) {
  double s = 0;
  for (std::size_t i = b + 1; i < e; ++i) s += 0.5 * (y[i] + y[i - 1]) * (t[i] - t[i - 1]);
  return s;
}

// Relative differences of reported figures from the hand-computed ones, the largest kept.
struct Comparison {
  double worst = 0;
  std::string worst_name;
  int count = 0;
  std::vector<std::string> missing;
  // |hand - reported| / scale; `scale`: the size the figure is judged against (its own |value|
  // unless that can be 0, e.g. the mean of a swinging force: then its peak).
  void add(const std::string& name, double hand, const json& reported, double scale) {
    ++count;
    if (!reported.is_number() || !std::isfinite(hand)) {
      if (std::isfinite(hand) || reported.is_number()) missing.push_back(name);
      return;
    }
    const double d = std::abs(hand - reported.get<double>()) / std::max(scale, 1e-300);
    if (d >= worst) {
      worst = d;
      worst_name = name;
    }
  }
  void add(const std::string& name, double hand, const json& reported) { add(name, hand, reported, std::abs(hand)); }
  bool holds() const { return count > 0 && missing.empty() && worst <= kRelative; }
  std::string sentence() const {
    std::string s = std::to_string(count) + " figures, largest relative difference " + g(worst, 2) +
                    (worst_name.empty() ? "" : " (" + worst_name + ")") + ", at most " + g(kRelative) + " required";
    if (!missing.empty()) {
      s += "; null in summary.json but computable by hand, or the reverse:";
      for (const auto& m : missing) s += " " + m;
    }
    return s;
  }
};

// One run's tables as a user gets them, read once, its summary.json, and the steady window found
// by hand on its rows.
struct RunFiles {
  Csv ts, ex, rx;        // timeseries.csv, crank_speed_extrema.csv, reactions.csv (empty without)
  const json& summary;
  const json& sz;        // summary.json's sizing
  Window win;
  std::size_t b = 0, e = 0;  // the window's rows [b, e)
  double span = 0;           // the time its rows span [s]
};

// Joints: every per-cart row of every joint kind in summary.json against the CSV columns
// (ValidationSizingJoints.cpp).
void checkJoints(ValidationSection& s, const Scene& sc, const std::string& who, const RunFiles& f);

}  // namespace rollerdyn::validation::sizing_by_hand
