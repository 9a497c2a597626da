// Stability chart: the Floquet verdict of the steady motion (DriveOrbit.h) over a grid of
// coupling stiffness c × crank speed ω (at one coupling damping k), or c × k (at the scene's
// speed). Each point is the scene with that coupling (a rigid scene gets an elastic coupling
// there: the chart then says what an elastic coupling would do) and, over ω, the motor's curve
// shifted as a frequency converter shifts it (sceneAtCrankSpeed). The value at each point is the
// largest multiplier modulus max|μ| (> 1: unstable) and the torsional mode's damping ratio
// implied by its multipliers; unstable points are grouped into zones (grid neighbours).
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "scene/Scene.h"

namespace rollerdyn::modes {

struct StabilityPoint {
  double c = 0, y = 0;          // stiffness [N·m/rad] and the second axis' value
  bool found = false;           // steady motion found
  double omega_mean = NAN;      // [rad/s]
  double max_modulus = NAN;     // max |μ|
  double torsional_damping_ratio = NAN;  // ζ implied by the torsional multipliers
  double torsional_frequency = NAN;      // [rad/s]
  bool stable = false;
  std::string verdict;          // "stable", "parametrically unstable", "unstable speed mode", "no steady running"
};

struct StabilityZone {
  int points = 0;
  double c_min = 0, c_max = 0, y_min = 0, y_max = 0;  // bounding box of the zone's grid points
  double worst_modulus = 0;
};

struct StabilityChart {
  std::string y_key;            // "omega" (crank speed [rad/s]) or "damping" (k [N·m·s/rad])
  double fixed_damping = NAN;   // k of a c × ω chart [N·m·s/rad]
  double fixed_speed = NAN;     // ω of a c × k chart [rad/s]
  std::vector<double> c, y;
  std::vector<std::vector<StabilityPoint>> grid;  // [iy][ic]
  double operating_c = NAN, operating_y = NAN;    // the scene's point
  std::vector<double> marked;                     // values of the second axis to mark (a paper's)
  std::vector<StabilityZone> zones;               // unstable regions
  std::string y_key_label() const { return y_key == "omega" ? "ω" : "k"; }
  int unstable_points = 0, failed_points = 0;
};

// c × ω at coupling damping k; omega_operating is the scene's steady mean crank speed.
// The rows of the grid are computed on `threads` threads (0: one per processor); the chart is the
// same bit for bit for any number (each row warm-starts only from its own points).
StabilityChart chartOverSpeed(const Scene& scene, double omega_operating, const std::vector<double>& c,
                              const std::vector<double>& omega, double damping, int threads = 0);
// c × k at the scene's own speed (omega_operating: its steady mean crank speed, the chart's label).
StabilityChart chartOverDamping(const Scene& scene, double omega_operating, const std::vector<double>& c,
                                const std::vector<double>& k, int threads = 0);

// Grids: n values from a to b, geometric (log) or linear.
std::vector<double> geometricGrid(double a, double b, int n);
std::vector<double> linearGrid(double a, double b, int n);

}  // namespace rollerdyn::modes
