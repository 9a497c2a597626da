#include "scene/SceneChoices.h"

#include <stdexcept>

namespace rollerdyn {

const KeySpec& choiceKey(const std::string& path) {
  const KeySpec* k = findSceneKey(path);
  if (!k || k->kind != KeyKind::Choice) throw std::logic_error("'" + path + "' is no choice key of the scene schema");
  return *k;
}

const char* choiceWord(const KeySpec& key, int position) {
  if (position < 0 || position >= static_cast<int>(key.choices.size()))
    throw std::logic_error(key.path + " has no word at position " + std::to_string(position) +
                           " (its enumeration and the schema's words differ)");
  return key.choices[static_cast<size_t>(position)].c_str();
}

int choicePosition(const KeySpec& key, const std::string& word) {
  for (size_t i = 0; i < key.choices.size(); ++i)
    if (key.choices[i] == word) return static_cast<int>(i);
  return -1;
}

}  // namespace rollerdyn
