#include "scene/Plausibility.h"

#include <cmath>
#include <cstdio>

namespace rollerdyn {

std::vector<std::string> plausibilityWarnings(const Scene& s) {
  std::vector<std::string> out;
  const struct {
    const char* key;
    double value;
  } lengths[] = {
      {"crank.radius", s.crank.radius},          {"rods.length", s.rods.length},
      {"carts.geometry.a", s.carts.geometry.a},  {"carts.geometry.b", s.carts.geometry.b},
      {"carts.geometry.p", s.carts.geometry.p},  {"carts.geometry.e", s.carts.geometry.e},
      {"carts.geometry.D", s.carts.geometry.D},  {"carts.geometry.d", s.carts.geometry.d},
      {"carts.geometry.com_height", s.carts.geometry.com_height},
      {"cam.stroke", s.cam.stroke},              {"cam.pusher_distance", s.cam.pusher_distance},
  };
  for (const auto& l : lengths) {
    if (!(l.value > kImplausibleLength)) continue;
    char buf[300];
    std::snprintf(buf, sizeof buf,
                  "%s = %g m is implausible for a roller forming installation (above %g m): scene lengths are in "
                  "metres; if you meant %g mm, write %g",
                  l.key, l.value, kImplausibleLength, l.value, l.value / 1000.0);
    out.push_back(buf);
  }
  // A crank angle typed in radians under a key in degrees: a value below 2π that is a round angle
  // (a multiple of 5°) in radians and not a whole number of degrees (1.0472 is 60° typed as
  // radians; 3 or 5 degrees are whole and stay silent).
  auto radiansTyped = [&out](const std::string& key, double v) {
    if (!(v > 0.0 && v < 2 * M_PI + 1e-3)) return;
    const double deg = v * 180.0 / M_PI;
    if (std::abs(deg - 5.0 * std::round(deg / 5.0)) > 0.05 || std::abs(v - std::round(v)) < 1e-9) return;
    char buf[300];
    std::snprintf(buf, sizeof buf,
                  "%s = %g is read as %g° (the key is in degrees); as radians it would be %.4g°: if you meant "
                  "%g rad, write %.4g",
                  key.c_str(), v, v, deg, v, deg);
    out.push_back(buf);
  };
  if (s.crank.angles.empty())
    radiansTyped("crank.offset_deg", s.crank.offset * 180.0 / M_PI);
  else
    for (std::size_t j = 1; j < s.crank.angles.size(); ++j)
      radiansTyped("crank.angles_deg[" + std::to_string(j) + "]", s.crank.angles[j] * 180.0 / M_PI);
  // A cart mass typed in tonnes: the papers' carts weigh 1000 kg; a forming cart below 10 kg is no
  // cart (near-zero masses, as a test of a massless cart, are left alone).
  for (int j = 0; j < s.carts.count; ++j) {
    const double m = s.cartMass(j);
    if (!(m >= 0.05 && m < kImplausibleCartMass)) continue;
    const std::string key = s.carts.masses.empty() ? "carts.mass" : "carts.mass[" + std::to_string(j) + "]";
    char buf[300];
    std::snprintf(buf, sizeof buf,
                  "%s = %g kg is implausible for a forming cart (below %g kg; the papers' carts weigh 1000 kg): "
                  "masses are in kilograms; if you meant %g t, write %g",
                  key.c_str(), m, kImplausibleCartMass, m, m * 1000.0);
    out.push_back(buf);
    if (s.carts.masses.empty()) break;
  }
  return out;
}

}  // namespace rollerdyn
