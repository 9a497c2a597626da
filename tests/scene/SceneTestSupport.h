// Shared fixtures of the scene tests: a minimal valid scene with known line numbers, and a
// helper that asserts a parse fails with a message containing given fragments.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "scene/SceneParser.h"

namespace rollerdyn::test {

// The smallest valid scene: every required key, nothing else. Tests edit it with
// replaced()/without() and rely on these line numbers:
//   1 source   3 simulation.t_end   5 crank.radius   6 crank.offset_deg   7 rods:
//   8 rods.model   9 rods.length   10 rods.mass   11 carts:   12 carts.count   13 carts.mass
//   14 motor:   15 omega_sync   16 breakdown_torque   17 critical_slip   18 rotor_inertia
//   19 reducer:   20 ratio   21 efficiency   22 coupling:   23 coupling.type
inline const std::string kMinimalScene =
    "source: unit-test scene\n"       // 1
    "simulation:\n"                   // 2
    "  t_end: 1.0\n"                  // 3
    "crank:\n"                        // 4
    "  radius: 0.2\n"                 // 5
    "  offset_deg: 90\n"              // 6
    "rods:\n"                         // 7
    "  model: distributed\n"          // 8
    "  length: 0.8\n"                 // 9
    "  mass: 64\n"                    // 10
    "carts:\n"                        // 11
    "  count: 2\n"                    // 12
    "  mass: 1000\n"                  // 13
    "motor:\n"                        // 14
    "  omega_sync: 104.72\n"          // 15
    "  breakdown_torque: 215.4\n"     // 16
    "  critical_slip: 0.1\n"          // 17
    "  rotor_inertia: 0.138\n"        // 18
    "reducer:\n"                      // 19
    "  ratio: 9.8\n"                  // 20
    "  efficiency: 0.9\n"             // 21
    "coupling:\n"                     // 22
    "  type: rigid\n";                // 23

// kMinimalScene with the line equal to `line` (without its newline) replaced by `by`; fails the
// test if the line is not there, so an edit can never silently do nothing.
inline std::string replaced(const std::string& line, const std::string& by,
                            const std::string& text = kMinimalScene) {
  const std::string needle = line + "\n";
  const size_t at = text.find(needle);
  EXPECT_NE(at, std::string::npos) << "fixture has no line '" << line << "'";
  if (at == std::string::npos) return text;
  return text.substr(0, at) + by + "\n" + text.substr(at + needle.size());
}

// kMinimalScene without the line `line` (shifts later lines up by one).
inline std::string without(const std::string& line, const std::string& text = kMinimalScene) {
  const std::string needle = line + "\n";
  const size_t at = text.find(needle);
  EXPECT_NE(at, std::string::npos) << "fixture has no line '" << line << "'";
  if (at == std::string::npos) return text;
  return text.substr(0, at) + text.substr(at + needle.size());
}

// Parses `yaml` and expects a SceneError whose message contains every fragment. Returns the
// error (default-constructed fields are not available, so a copy of the caught one) for further
// checks of its accessors.
inline SceneError expectSceneError(const std::string& yaml, const std::vector<std::string>& fragments,
                                   const std::vector<std::string>& overrides = {},
                                   const std::string& label = "test.yaml") {
  try {
    parseSceneText(yaml, label, overrides);
  } catch (const SceneError& e) {
    const std::string msg = e.what();
    for (const std::string& f : fragments)
      EXPECT_NE(msg.find(f), std::string::npos) << "message lacks \"" << f << "\":\n  " << msg;
    return e;
  }
  ADD_FAILURE() << "expected a SceneError containing \"" << (fragments.empty() ? "" : fragments[0])
                << "\", but the scene parsed";
  return SceneError::inFile(label, 0, "", "(no error)", "(no error)");
}

}  // namespace rollerdyn::test
