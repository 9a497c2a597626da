// What a Scene holds for each key of the scene schema, as text: the parser read backwards. It lets
// a Scene be compared key by key with another (test SceneDefaults: a Scene built in code against
// the same scene read from a file) without a hand-kept list of fields, since every schema key must
// have its entry here.
//
// The text is the Scene's field in the Scene's units (radians where the file gives degrees),
// numbers with 17 significant digits, choices as their words, lists as "[a, b]".
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "scene/Scene.h"

namespace rollerdyn {

// Every leaf key of the schema, in schema order, with the value `scene` holds for it. A key the
// Scene keeps only through another key's field (motor.omega_critical becomes the critical slip)
// has the text "in <other key>". std::logic_error when a schema key has no entry here, or an
// entry names no schema key.
std::vector<std::pair<std::string, std::string>> sceneValues(const Scene& scene);

}  // namespace rollerdyn
