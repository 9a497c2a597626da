#include "python/PyScene.h"

#include <utility>

namespace rollerdyn::python {

PyScene::PyScene(std::shared_ptr<const SceneInput> input, std::vector<std::string> overrides)
    : input_(std::move(input)), overrides_(std::move(overrides)), scene_(parseSceneInput(*input_, overrides_)) {}

PyScene PyScene::load(const std::string& path) {
  return PyScene(std::make_shared<const SceneInput>(readSceneInput(path)), {});
}

PyScene PyScene::fromData(const std::string& yaml_text, const std::string& name) {
  return PyScene(std::make_shared<const SceneInput>(SceneInput{name, yaml_text, true}), {});
}

PyScene PyScene::with(const std::vector<std::string>& more) const {
  std::vector<std::string> all = overrides_;
  all.insert(all.end(), more.begin(), more.end());
  return PyScene(input_, std::move(all));
}

}  // namespace rollerdyn::python
