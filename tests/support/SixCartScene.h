// The six-cart trial's machine: the shipped balanced drive (model/balanced-4cart.yaml) with six
// carts at 60°, plus any further overrides. Shared by the tests that check what the trials found.
#pragma once

#include <string>
#include <vector>

#include "scene/SceneParser.h"

namespace rollerdyn::test_scenes {

inline Scene sixCartsAt60(const std::vector<std::string>& more = {}) {
  std::vector<std::string> o = {"carts.count=6", "crank.offset_deg=60"};
  o.insert(o.end(), more.begin(), more.end());
  return parseSceneFile(std::string(ROLLERDYN_SOURCE_DIR) + "/model/balanced-4cart.yaml", o);
}

}  // namespace rollerdyn::test_scenes
