// The one place a run chooses its model by name: "multibody" (Simbody, either formulation, as the
// scene's simulation.formulation says) or "reduced" (the papers' reduced-mass model). Every study,
// validation item and binding that runs "the model the user chose" calls this, so a third model
// or a changed rule is added once.
#pragma once

#include <string>

#include "analysis/RunResult.h"
#include "multibody/MultibodySimulation.h"
#include "scene/Scene.h"

namespace rollerdyn {

// Runs `scene` with `model`; `control` (Ctrl-C, progress) reaches either model. Throws
// std::invalid_argument naming the model when it is neither "multibody" nor "reduced".
RunResult runModel(const Scene& scene, const std::string& model, const RunControl& control = {});

}  // namespace rollerdyn
