// The scene file reference, generated from the schema (SceneSchema.h) so that it cannot drift
// from what the parser accepts: one row per key for the Python interface (scene_keys()) and
// `rollerdyn schema`, and the Markdown page docs/scene-reference.md (`rollerdyn schema
// --markdown`; a test fails when the committed page differs from this text).
#pragma once

#include <string>
#include <vector>

namespace rollerdyn {

struct SceneKeyDoc {
  std::string key;          // dotted key path, e.g. "coupling.damping"
  std::string section;      // the map it sits in, e.g. "coupling", "carts.geometry"; "" at the top
  std::string unit;         // SI unit; "-" when dimensionless
  std::string presence;     // "required", "optional" or "conditional"
  std::string default_value;  // the default of an optional key as text; "" otherwise
  std::string condition;    // conditional keys: when required / how the default follows
  std::string allowed;      // what a value may be, e.g. "> 0", "one of: elastic, rigid"
  std::string meaning;      // one or two sentences
  std::string source;       // paper and equation; "" for numerical settings
};

// Every key of the schema, in schema order.
std::vector<SceneKeyDoc> sceneKeyDocs();

// docs/scene-reference.md: a header, then one section per map of the schema (in schema order)
// with a table of its keys: key, meaning, unit, default, allowed values, source.
std::string sceneReferenceMarkdown();

// Plain text for a terminal: per key one line "key [unit] default — meaning" (and the allowed
// values), for the keys whose path is `prefix` or starts with `prefix.` ("" for all).
std::string sceneKeysText(const std::string& prefix);

}  // namespace rollerdyn
