#include "physics/CouplingLaw.h"

#include "scene/Scene.h"

namespace rollerdyn {

CouplingLaw couplingLaw(const Scene& scene) {
  CouplingLaw law;
  if (scene.coupling.type != CouplingType::Elastic) return law;
  law.stiffness = scene.coupling.stiffness;
  law.damping = scene.coupling.damping;
  law.half_gap = 0.5 * scene.reducer.backlash;
  return law;
}

}  // namespace rollerdyn
