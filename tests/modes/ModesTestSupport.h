// The modal analysis of the shipped four-cart scene with --set overrides, reduced model only, no
// Campbell diagram or charts, 36 crank angles: the cheap analysis the resonance, margin and
// backlash tests read.
#pragma once

#include <string>
#include <vector>

#include "modes/ModalAnalysis.h"
#include "scene/SceneParser.h"

namespace rollerdyn::modes::test {

inline ModesReport lightModes(const std::vector<std::string>& overrides) {
  ModesOptions o;
  o.multibody = false;
  o.campbell = false;
  o.charts = false;
  o.angles = 36;
  return analyseModes(parseSceneFile(std::string(ROLLERDYN_SOURCE_DIR) + "/model/balanced-4cart.yaml", overrides), o);
}

}  // namespace rollerdyn::modes::test
