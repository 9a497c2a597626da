// The scene's parameter table for the HTML report: every key of the scene schema
// (src/scene/SceneSchema.h) with the value the run used, its unit, meaning and where the value
// came from (the file's line, a --set argument, or the schema default), plus the derived
// quantities both models compute from them (src/scene/Scene.h).
#pragma once

#include <string>
#include <vector>

#include "scene/Scene.h"
#include "scene/SceneParser.h"

namespace rollerdyn {

struct SceneParameterRow {
  std::string key;      // dotted key path, e.g. "coupling.stiffness"
  std::string value;    // as written ("90", "[same, opposite]") or the default
  std::string unit;     // SI unit, "-" for dimensionless
  std::string meaning;  // one line from the schema
  std::string origin;   // "file", "--set #N", "default", "derived"
};

// Rows in schema order. Reads `scene_path` again and applies `overrides` exactly as the parser
// does, so the table shows what the run used. Keys the file omits appear with their default
// (Optional keys) or not at all (keys whose default depends on other keys: see derived rows).
// Throws SceneError like parseSceneFile() for a bad file.
std::vector<SceneParameterRow> sceneParameterRows(const std::string& scene_path,
                                                  const std::vector<std::string>& overrides);
// The same for a scene input kept in memory (scene/SceneParser.h).
std::vector<SceneParameterRow> sceneParameterRows(const SceneInput& input,
                                                  const std::vector<std::string>& overrides);

// Quantities derived from the scene: critical slip, synchronous crank speed, breakdown torque at
// the crank, reduced motor-side inertia, crank-side inertia, rod inertia, cart mass with rod share.
std::vector<SceneParameterRow> derivedParameterRows(const Scene& scene);

}  // namespace rollerdyn
