// Keys a scene gives that change nothing in the run asked for: each is named with why, so a value
// typed into the scene is never silently dropped (a setting the chosen model, motor law or
// starting method does not read, or a lever arm whose forces are zero). Warnings, not errors: one
// scene file serves both models, and a value kept for the other one is no mistake.
#pragma once

#include <string>
#include <vector>

#include "scene/Scene.h"

namespace rollerdyn {

// For `model` "multibody" or "reduced": one sentence per key of scene.given_keys without effect
// on that model's run, e.g. "reduced.guide_normals has no effect on the multibody model: ...".
std::vector<std::string> keysWithoutEffect(const Scene& scene, const std::string& model);

}  // namespace rollerdyn
