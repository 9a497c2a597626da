// Reading and validating scene files (YAML) into the immutable Scene.
//
// The schema (every allowed key, its unit, default and range) is in SceneSchema.h and is
// documented in docs/scene-reference.md (generated from it). Parsing is all-or-nothing: either a fully validated Scene comes
// back or a SceneError naming file, line, key path and what was expected. Unknown keys, wrong
// types, missing required keys, physically impossible values, a second YAML document, duplicate
// keys and non-finite numbers are all rejected; nothing is silently ignored or guessed.
#pragma once

#include <string>
#include <vector>

#include "scene/Scene.h"
#include "scene/SceneError.h"

namespace rollerdyn {

// Reads, overrides and validates the scene file at `path`. Scene::name is the file's stem,
// Scene::source_path is `path` as given. An unreadable file is a SceneError too.
//
// `overrides` are "key.path=value" strings (the CLI's repeatable --set). The value is parsed as a
// YAML scalar or flow node, so `carts.sides=[same,opposite]` sets a list. Each key path must be
// in the schema (a leaf or a whole map); it may set an optional key the file omits. Overrides
// are applied to the YAML tree in order (later wins) BEFORE validation, so an overridden value
// passes exactly the same checks as one written in the file; a rejected override is reported as
// "--set #N (key=value): key: expected ..., got ...".
Scene parseSceneFile(const std::string& path, const std::vector<std::string>& overrides = {});

// Same, from YAML text already in memory. `file_label` stands for the file in error messages and
// its stem becomes Scene::name.
Scene parseSceneText(const std::string& yaml_text, const std::string& file_label,
                     const std::vector<std::string>& overrides = {});

// A scene's input, kept so that the same scene can be parsed again with further overrides (the
// points of a sweep, the designs of an optimization, the Python interface's immutable scenes).
struct SceneInput {
  std::string label;       // the file as given; for data, the name standing for it in messages
  std::string text;        // the YAML text
  bool from_data = false;  // generated from data, not written by a person (the Python interface
                           // writes a dict as JSON, which is YAML): messages name no line
};

// The file at `path` as a SceneInput; a SceneError when it cannot be read.
SceneInput readSceneInput(const std::string& path);

// Parses `input` with `overrides`, exactly as parseSceneFile() parses a file. For data,
// Scene::name and Scene::source_path are the label.
Scene parseSceneInput(const SceneInput& input, const std::vector<std::string>& overrides = {});

// The name Scene.h's header comment uses.
inline Scene parseScene(const std::string& path, const std::vector<std::string>& overrides = {}) {
  return parseSceneFile(path, overrides);
}

}  // namespace rollerdyn
