// Warnings for scene values that parse and validate but are implausible for a roller forming
// installation, the commonest being a length typed in millimetres where the key is in metres
// (crank.radius: 200 is a 200 m crank). They never stop a run: a user may mean it.
#pragma once

#include <string>
#include <vector>

#include "scene/Scene.h"

namespace rollerdyn {

// Lengths above this are taken for millimetres typed as metres [m]: the papers' machines have
// r = 0.2 m, l = 0.8 m and cart dimensions below 1 m; no cart of a forming line is 5 m long.
inline constexpr double kImplausibleLength = 5.0;

// One sentence per implausible value, naming the key, the value and the unit expected.
std::vector<std::string> plausibilityWarnings(const Scene& scene);

}  // namespace rollerdyn
