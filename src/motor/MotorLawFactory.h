// The one place a scene's motor.model becomes a MotorLaw: both drive models, the start-up
// analysis and `rollerdyn motor` call this, so each model runs the same law.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "motor/CatalogueFit.h"
#include "motor/InductionMachine.h"
#include "motor/MotorLaw.h"
#include "scene/Scene.h"

namespace rollerdyn {

// The law of the scene's motor.model.
std::unique_ptr<MotorLaw> makeMotorLaw(const Scene& scene);
// The law of `model` for the scene's motor (e.g. every model side by side in `rollerdyn motor`).
// Throws std::invalid_argument when the scene lacks what that model needs.
std::unique_ptr<MotorLaw> makeMotorLaw(const Scene& scene, MotorModel model);

// The equivalent circuit of the scene's machine: motor.circuit.* when given, else fitted to
// motor.catalogue.* (motor.catalogue.cages). Throws std::invalid_argument when there is neither.
InductionMachineParameters sceneMachine(const Scene& scene);
// The catalogue fit of the scene's motor (motor.catalogue.*, rated supply, pole pairs).
CatalogueFit fitSceneCatalogue(const Scene& scene, int cages);
// Its key (catalogueFitKey, CatalogueFit.h): what that fit reads of the scene.
std::string sceneCatalogueFitKey(const Scene& scene, int cages);
// Where the circuit of the scene's law comes from when it is fitted to the catalogue (motor.model
// circuit or park without motor.circuit); nullopt when no fit is behind the law.
std::optional<FitOrigin> sceneFitOrigin(const Scene& scene);

// Every value a law is built from, exactly (ExactKey.h): all fields of scene.motor and
// scene.induction, which are all makeMotorLaw reads of the scene. Each field is named by a
// structured binding, so a field added to KlossMotor, InductionMotor, MotorCircuit or
// MotorCatalogue fails to compile until it is keyed. The key of sharedMotorLaw's memory.
std::string motorLawKey(const Scene& scene);

}  // namespace rollerdyn
