// The scene-file schema as data: every key path a scene file may contain, its type, unit,
// whether it is required, its default and its allowed range.
//
// One table serves four readers, so they cannot drift apart: the parser rejects any key not in
// it (a typo is never silently ignored), the --set override checks its key path against it
// before touching the tree, the report and the Python interface show it beside the values, and
// the scene file reference (docs/scene-reference.md, `rollerdyn schema --markdown`,
// SceneReference.h) is generated from it; a test fails when the committed reference differs.
// Rules that couple several keys (l > r, one way to give the critical slip, b > 0 with guide
// friction, ...) are not expressible per key and live in SceneParser.cpp.
#pragma once

#include <string>
#include <vector>

namespace rollerdyn {

enum class KeyKind {
  Number,   // finite real, plain (unquoted) YAML scalar
  Integer,  // whole number
  Text,     // any scalar, read as a string
  Choice,   // one of a fixed list of words
  Flag,     // true | false
  Sides,    // carts.sides: list of same/opposite, or the shorthand same | opposite | alternate
  NumberList,  // a list of finite reals, each in the key's range (its length checked by the parser)
};

enum class Presence {
  Required,     // must be in the file (or given by --set)
  Optional,     // has a fixed default
  Conditional,  // required or defaulted depending on other keys; decided in SceneParser.cpp
};

// Allowed interval of a Number / Integer key; infinite ends mean "unbounded".
struct Range {
  double lo;
  bool lo_inclusive;
  double hi;
  bool hi_inclusive;
};

struct KeySpec {
  std::string path;                  // dotted key path, e.g. "carts.geometry.b"
  KeyKind kind;
  std::string unit;                  // SI unit (deg only under *_deg keys); "-" if dimensionless
  Presence presence;
  Range range;                       // Number / Integer only
  double default_number;             // Optional Number / Integer / Flag (0 or 1)
  std::string default_text;          // Optional Text / Choice
  std::vector<std::string> choices;  // Choice only
  std::string meaning;               // one or two sentences, for messages, the report and the docs
  std::string source{};              // where the quantity is defined: paper, equation, figure
                                     // ("" for numerical settings of rollerdyn itself)
  std::string condition{};           // Conditional keys: when required, or how the default follows
                                     // from other keys (e.g. "m·l²/12")
  bool per_cart = false;             // Number key that may also be a list with one value per cart
                                     // (docs/per-cart.md); its scalar form is the uniform value

  // Builders for the table: number(...).from("Loveikin and Pochka (2007) eq. (7)").
  KeySpec from(std::string paper) && {
    source = std::move(paper);
    return std::move(*this);
  }
  KeySpec when(std::string text) && {
    condition = std::move(text);
    return std::move(*this);
  }
};

// One sentence about a map of the schema (e.g. "carts.geometry"), for the docs; "" if none.
std::string sceneMapDescription(const std::string& map_path);

// Every leaf key, in documentation order.
const std::vector<KeySpec>& sceneSchema();

// The leaf spec of `path`, or nullptr if `path` is not a leaf key of the schema.
const KeySpec* findSceneKey(const std::string& path);

// A key path as the command line may name it (--set, --param): a leaf key, or one element
// "key[i]" (i counted from 0: cart i + 1) of a per-cart key. The leaf's spec, or nullptr;
// `element` (optional) receives i, or -1 for a whole key.
const KeySpec* findSceneKeyOrElement(const std::string& path, int* element = nullptr);

// Whether `path` names a map of the schema ("" is the top level, "carts.geometry" a nested map).
bool isSceneMap(const std::string& path);

// The keys directly under map `map_path`, in schema order (e.g. "carts" -> count, sides, mass,
// geometry).
std::vector<std::string> sceneChildKeys(const std::string& map_path);

// The expected-clause for a single value of `spec`, e.g. "a number > 0 [m]",
// "an integer in [1, 1000]", "one of: elastic, rigid".
std::string describeExpected(const KeySpec& spec);

// The expected-clause of a per-cart key's list, e.g. "a list of 4 numbers > 0 [kg], one per
// cart (carts.count = 4)".
std::string describeExpectedList(const KeySpec& spec, int count);

// What a value may be, without the unit: "> 0", "in (0, 1]", "any finite number",
// "an integer in [1, 1000]", "one of: elastic, rigid", "true or false", "text".
std::string describeAllowed(const KeySpec& spec);

// The default of an Optional key as text ("1e-06", "true", "crankshaft"); "" for other keys.
std::string defaultText(const KeySpec& spec);

// Throws std::invalid_argument "<what>: expected a key of the scene schema
// (docs/scene-reference.md), got an unknown key (did you mean '...'?)" unless `key` is a leaf key
// of the schema (a sweep or optimization parameter): the same hint as --set gives, before
// anything runs.
void requireSceneKey(const std::string& what, const std::string& key);

// Compact, round-trippable text of a number for messages ("0.2", "1e-06", "200000").
std::string formatNumber(double v);

}  // namespace rollerdyn
