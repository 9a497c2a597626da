#include "scene/Plausibility.h"

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
  return out;
}

}  // namespace rollerdyn
