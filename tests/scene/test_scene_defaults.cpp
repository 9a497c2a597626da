// A Scene built in code holds, for every key a scene file leaves out, the value the parser gives
// (Scene.h): a file with only the keys it must give, parsed, against Scene{} given the same values
// in code, compared key by key over the whole schema (sceneValues(): every schema key has its
// entry there, so a new key cannot be left out of the comparison). And every word of a choice key
// reads back as itself: the parser and toString() take the words from the schema's one list.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "scene/SceneParser.h"
#include "scene/SceneSchema.h"
#include "scene/SceneValues.h"

namespace rollerdyn {
namespace {

// The keys a file must give: the required ones, and those the rules require with these values
// (the crank offset, the mass of distributed rods, Kloss's M_kr and s_kr, an elastic coupling's c).
const char* const kMinimalScene = R"(
simulation: {t_end: 2.0}
crank: {radius: 0.2, offset_deg: 90}
rods: {model: distributed, length: 0.8, mass: 64}
carts: {count: 4, mass: 1000}
motor: {omega_sync: 104.72, breakdown_torque: 517.14, critical_slip: 0.1146, rotor_inertia: 0.4}
reducer: {ratio: 9.8, efficiency: 0.9}
coupling: {type: elastic, stiffness: 200000}
)";

// The same values set in code on Scene{}, nothing else.
Scene minimalSceneInCode() {
  Scene s{};
  s.simulation.t_end = 2.0;
  s.crank.radius = 0.2;
  s.crank.offset = 90.0 * (M_PI / 180.0);
  s.rods.model = RodModel::Distributed;
  s.rods.length = 0.8;
  s.rods.mass = 64;
  s.carts.count = 4;
  s.carts.mass = 1000;
  s.motor.omega_sync = 104.72;
  s.motor.breakdown_torque = 517.14;
  s.motor.critical_slip = 0.1146;
  s.motor.rotor_inertia = 0.4;
  s.reducer.ratio = 9.8;
  s.reducer.efficiency = 0.9;
  s.coupling.type = CouplingType::Elastic;
  s.coupling.stiffness = 200000;
  return s;
}

std::map<std::string, std::string> valuesOf(const Scene& s) {
  std::map<std::string, std::string> m;
  for (const auto& [key, value] : sceneValues(s)) m[key] = value;
  return m;
}

TEST(SceneDefaults, SceneBuiltInCodeHasTheSchemasDefaults) {
  const Scene from_file = parseSceneText(kMinimalScene, "minimal.yaml");
  const std::map<std::string, std::string> file = valuesOf(from_file), code = valuesOf(minimalSceneInCode());
  // The Conditional keys whose default follows values a Scene built in code sets itself (Scene.h):
  // each is checked against its rule instead.
  const Scene& f = from_file;
  const std::map<std::string, bool> follows_given_values = {
      {"carts.sides", f.carts.side == std::vector<int>(4, +1)},
      {"motor.pole_pairs", f.induction.pole_pairs == std::lround(2.0 * M_PI * 50.0 / 104.72)},
      {"rods.inertia_com", f.rods.inertia_com == 64.0 * 0.8 * 0.8 / 12.0},
  };
  const std::set<std::string> given(f.given_keys.begin(), f.given_keys.end());
  int defaults = 0;
  for (const KeySpec& k : sceneSchema()) {
    const auto rule = follows_given_values.find(k.path);
    if (rule != follows_given_values.end()) {
      EXPECT_EQ(k.presence, Presence::Conditional) << k.path;
      EXPECT_EQ(given.count(k.path), 0u) << k.path;
      EXPECT_TRUE(rule->second) << k.path << " = " << file.at(k.path) << " does not follow its rule: " << k.condition;
      continue;
    }
    EXPECT_EQ(code.at(k.path), file.at(k.path))
        << k.path << (given.count(k.path) ? " (given in the file and in code)" : " (left out)");
    defaults += given.count(k.path) ? 0 : 1;
  }
  // Every key the file left out was compared (or checked against its rule).
  EXPECT_EQ(defaults, int(sceneSchema().size() - given.size() - follows_given_values.size()));
  EXPECT_GT(defaults, 100);
}

// Each word of a choice key, set on the minimal scene (with what that word needs beside it), reads
// back as itself from the Scene the parser built.
TEST(SceneDefaults, EveryChoiceWordReadsBackAsItself) {
  const std::map<std::string, std::vector<std::string>> needs = {
      {"motor.model=circuit", {"motor.voltage=400", "motor.circuit={R_s: 0.1, L_sigma_s: 0.001, L_m: 0.05, "
                                                    "R_r: 0.1, L_sigma_r: 0.001}"}},
      {"motor.model=park", {"motor.voltage=400", "motor.circuit={R_s: 0.1, L_sigma_s: 0.001, L_m: 0.05, "
                                                 "R_r: 0.1, L_sigma_r: 0.001}"}},
      {"motor.start.method=star_delta", {"motor.start.changeover_time=0.5"}},
      {"motor.start.method=soft_starter", {"motor.start.ramp_time=1", "motor.start.initial_voltage=0.4"}},
      {"motor.start.method=frequency_converter", {"motor.start.ramp_time=1", "motor.start.initial_frequency=5"}},
      {"drive.type=cam", {"cam.stroke=0.4"}},
  };
  int words = 0;
  for (const KeySpec& k : sceneSchema()) {
    if (k.kind != KeyKind::Choice) continue;
    for (const std::string& word : k.choices) {
      const std::string set = k.path + "=" + word;
      std::vector<std::string> overrides = {set};
      if (k.path == "simulation.integrator") overrides.push_back("simulation.formulation=constrained");
      if (needs.count(set)) overrides.insert(overrides.end(), needs.at(set).begin(), needs.at(set).end());
      const Scene s = parseSceneText(kMinimalScene, "minimal.yaml", overrides);
      EXPECT_EQ(valuesOf(s).at(k.path), word) << set;
      ++words;
    }
  }
  EXPECT_GT(words, 40);
}

}  // namespace
}  // namespace rollerdyn
