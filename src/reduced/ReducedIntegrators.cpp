// The reduced model's runs: the model built from the scene, its tables set up, then the integrator
// the scene chooses (CVODE, CvodeRun.h, or Baranov's scheme of the papers, BaranovScheme.h).
#include <algorithm>
#include <stdexcept>
#include <string>

#include "physics/CrankInertia.h"
#include "reduced/BaranovScheme.h"
#include "reduced/CvodeRun.h"
#include "reduced/ReducedModel.h"
#include "reduced/ReducedRunRows.h"

namespace rollerdyn {

RunResult runReducedModel(const Scene& scene, const RunControl& control) {
  return runReducedModel(scene, nullptr, control);
}

RunResult runReducedModel(const Scene& scene, std::shared_ptr<const MotorLaw> law, const RunControl& control) {
  // The model's kinematics and loads stay evaluable (tests and studies read them); its motion is
  // not, where the crank side has no inertia at the dead centres (physics/CrankInertia.h).
  const std::string without_inertia = crankWithoutInertia(scene, "reduced model");
  if (!without_inertia.empty()) throw std::invalid_argument(without_inertia);
  const ReducedModel model(scene, std::move(law));
  RunResult res;
  res.model = "reduced";
  res.effects = scene.effects();
  // The papers' crankshaft is rigid: a torsional chain given for the multibody model is not built
  // here (and is named as without effect, KeyEffects.h).
  res.effects.erase(std::remove(res.effects.begin(), res.effects.end(), std::string("crankshaft_torsion")),
                    res.effects.end());
  res.guide_normals = model.guideNormalsDescription();
  setupTables(model, res);
  if (scene.reduced.integrator == ReducedIntegrator::Baranov) {
    res.integrator = "baranov";
    return runBaranov(model, std::move(res), control);
  }
  return runCvode(model, std::move(res), control);
}

}  // namespace rollerdyn
