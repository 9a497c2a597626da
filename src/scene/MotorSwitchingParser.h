// Reading the motor.start and motor.stop sections (scene/MotorSwitching.h) with the rules that
// couple their keys: which keys each starting method needs, one way to give the star-delta
// changeover, the order of the switching times. Internal to the scene parser.
#pragma once

#include "scene/Scene.h"
#include "scene/SceneReader.h"

namespace rollerdyn {

// Fills scene.motor_start and scene.motor_stop. Keys of a method other than the chosen one are
// validated but not used, so `--set motor.start.method=...` works on a scene written for another
// method (as a rigid coupling keeps its stiffness key). Needs scene.motor read already (the
// changeover speed must lie below the synchronous speed).
void readMotorSwitching(const scene_detail::Reader& in, Scene& scene);

}  // namespace rollerdyn
