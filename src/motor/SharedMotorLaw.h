// The scene's motor law, built once per distinct motor and shared: building the catalogue
// models fits an equivalent circuit to the catalogue (tens of thousands of evaluations, 1-2 s, or
// a file read when an earlier process kept it: FitCache.h), and one `simulate` needs the law in
// the model, the start-up answers and the stall explanation, a sweep in every point. Laws are immutable (MotorLaw's members are const), so one object
// serves every caller and thread.
#pragma once

#include <memory>

#include "motor/MotorLaw.h"
#include "scene/Scene.h"

namespace rollerdyn {

// makeMotorLaw(scene) (MotorLawFactory.h), remembered for the process by every field of the
// scene's motor (motorLawKey: scene.motor and scene.induction, all a law is built from).
// Thread-safe. A catalogue fit behind the law is also kept on disk for later processes
// (FitCache.h).
// Throws what makeMotorLaw throws.
std::shared_ptr<const MotorLaw> sharedMotorLaw(const Scene& scene);

}  // namespace rollerdyn
