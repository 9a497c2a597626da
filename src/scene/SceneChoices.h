// The words of a Choice key and the enumeration that stands for them in the Scene (Scene.h,
// MotorSwitching.h) are one list: the schema's (SceneSchema.cpp). Each enumeration lists its values
// in the order of its key's words, so the parser reads a word as its position in the list and
// toString() writes the word at a value's position; a word is written once, in the schema.
#pragma once

#include <string>

#include "scene/SceneSchema.h"

namespace rollerdyn {

// The Choice key `path` of the schema; std::logic_error when the schema has no such Choice key.
const KeySpec& choiceKey(const std::string& path);

// The word at `position` among the words of Choice key `key`; std::logic_error when there is none
// (an enumeration with more values than its key has words).
const char* choiceWord(const KeySpec& key, int position);

template <class Enum>
const char* choiceWord(const KeySpec& key, Enum value) {
  return choiceWord(key, static_cast<int>(value));
}

// The position of `word` among the words of `key`, or -1 when it is none of them.
int choicePosition(const KeySpec& key, const std::string& word);

}  // namespace rollerdyn
