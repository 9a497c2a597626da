// The Python interface's scene: immutable, the CLI's concepts (a scene file and --set overrides),
// parsed by the same parser. A PyScene keeps its input (file text, or a dict written as YAML) and
// its overrides, so that a sweep or an optimization can apply further overrides to it, and
// `with_` makes a new scene instead of changing this one.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "scene/Scene.h"
#include "scene/SceneParser.h"

namespace rollerdyn::python {

class PyScene {
 public:
  // Scene.load(path): the file as the CLI reads it (errors name the path as given).
  static PyScene load(const std::string& path);
  // Scene.from_dict(d): `yaml_text` is the dict written as YAML flow text (PyConvert.h);
  // errors name `name` and the key, but no line.
  static PyScene fromData(const std::string& yaml_text, const std::string& name);

  // A new scene with `more` ("key=value" YAML text, as --set) applied after this one's overrides.
  PyScene with(const std::vector<std::string>& more) const;

  const Scene& scene() const { return scene_; }
  const SceneInput& input() const { return *input_; }
  std::shared_ptr<const SceneInput> sharedInput() const { return input_; }
  const std::vector<std::string>& overrides() const { return overrides_; }
  // The scene file as given, or "" for a scene from data (summary.json's scene_path is then null).
  std::string file() const { return input_->from_data ? std::string() : input_->label; }

 private:
  PyScene(std::shared_ptr<const SceneInput> input, std::vector<std::string> overrides);

  std::shared_ptr<const SceneInput> input_;
  std::vector<std::string> overrides_;
  Scene scene_;
};

}  // namespace rollerdyn::python
