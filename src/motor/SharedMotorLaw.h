// The scene's motor law, built once per distinct motor and shared: building the catalogue
// models fits an equivalent circuit to the catalogue (tens of thousands of evaluations, ~0.3 s),
// and one `simulate` needs the law in the model, the start-up answers and the stall explanation,
// a sweep in every point. Laws are immutable (MotorLaw's members are const), so one object
// serves every caller and thread.
#pragma once

#include <memory>

#include "motor/MotorLaw.h"
#include "scene/Scene.h"

namespace rollerdyn {

// makeMotorLaw(scene) (MotorLawFactory.h), remembered for the process by every field of the
// scene's motor (scene.motor and scene.induction) that a law is built from. Thread-safe.
// Throws what makeMotorLaw throws.
std::shared_ptr<const MotorLaw> sharedMotorLaw(const Scene& scene);

}  // namespace rollerdyn
