#include "compare/RunModel.h"

#include <stdexcept>

#include "reduced/ReducedModel.h"

namespace rollerdyn {

RunResult runModel(const Scene& scene, const std::string& model, const RunControl& control) {
  if (model == "multibody") return runMultibodyModel(scene, control);
  if (model == "reduced") return runReducedModel(scene, control);
  throw std::invalid_argument("model: expected multibody or reduced, got '" + model + "'");
}

}  // namespace rollerdyn
