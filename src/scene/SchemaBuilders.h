// The builders of the scene schema's key table (SceneSchema.cpp and the files that hold parts of
// it, e.g. SceneSchemaSignOff.cpp); internal to the schema.
#pragma once

#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "scene/SceneSchema.h"

namespace rollerdyn {
namespace schema_builders {

inline constexpr double kInf = std::numeric_limits<double>::infinity();

// Interval helpers; names read as the condition they enforce.
inline Range anyFinite() { return {-kInf, false, kInf, false}; }
inline Range positive() { return {0.0, false, kInf, false}; }
inline Range nonNegative() { return {0.0, true, kInf, false}; }
inline Range between(double lo, bool lo_in, double hi, bool hi_in) { return {lo, lo_in, hi, hi_in}; }

inline KeySpec number(std::string path, std::string unit, Presence presence, Range range, double def,
               std::string meaning) {
  return {std::move(path), KeyKind::Number, std::move(unit), presence, range, def, "", {},
          std::move(meaning)};
}

inline KeySpec integer(std::string path, Presence presence, Range range, double def,
                std::string meaning) {
  return {std::move(path), KeyKind::Integer, "-", presence, range, def, "", {},
          std::move(meaning)};
}

inline KeySpec choice(std::string path, Presence presence, std::vector<std::string> choices,
               std::string def, std::string meaning) {
  return {std::move(path), KeyKind::Choice, "-", presence, anyFinite(), 0.0, std::move(def),
          std::move(choices), std::move(meaning)};
}

// A number key that may also be given per cart as a list (KeySpec::per_cart).
inline KeySpec perCart(KeySpec spec) {
  spec.per_cart = true;
  return spec;
}

}  // namespace schema_builders

// The keys of the fatigue and coupling-selection sign-off (sizing.fatigue.*, sizing.coupling.*),
// in reference order (SceneSchemaSignOff.cpp).
std::vector<KeySpec> signOffSchemaKeys();

}  // namespace rollerdyn
