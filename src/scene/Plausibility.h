// Warnings for scene values that parse and validate but are implausible for a roller forming
// installation, the commonest being a length typed in millimetres where the key is in metres
// (crank.radius: 200 is a 200 m crank), an angle typed in radians under a key in degrees
// (crank.offset_deg: 1.0472) and a cart mass in tonnes (carts.mass: 1). They never stop a run: a
// user may mean it.
#pragma once

#include <string>
#include <vector>

#include "scene/Scene.h"

namespace rollerdyn {

// Lengths above this are taken for millimetres typed as metres [m]: the papers' machines have
// r = 0.2 m, l = 0.8 m and cart dimensions below 1 m; no cart of a forming line is 5 m long.
inline constexpr double kImplausibleLength = 5.0;

// Cart masses below this are taken for tonnes typed as kilograms [kg] (the papers' carts: 1000 kg).
inline constexpr double kImplausibleCartMass = 10.0;

// Output rows per crank revolution below which δ and the peaks read from the rows are
// under-sampled by more than about 1 % (order 2; Plausibility.cpp) [-].
inline constexpr double kFewestRowsPerRevolution = 50.0;

// One sentence per implausible value, naming the key, the value and the unit expected.
std::vector<std::string> plausibilityWarnings(const Scene& scene);

}  // namespace rollerdyn
