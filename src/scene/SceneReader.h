// Internals of the scene parser shared by its source files (SceneParser.cpp: the installation;
// MotorSceneParser.cpp: the motor section). Not a public header: everything else reads a Scene.
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "scene/DidYouMean.h"
#include "scene/Scene.h"
#include "scene/SceneChoices.h"
#include "scene/SceneDocument.h"
#include "scene/SceneSchema.h"

namespace rollerdyn::scene_detail {

// Whichever of two coupled keys came from a --set is the one to blame, so that an override that
// breaks a cross-key rule is reported as that override's fault.
inline bool blameSecond(const SceneDocument& doc, const std::string& first, const std::string& second) {
  return doc.overrideFor(second) > doc.overrideFor(first);
}

// Typed, range-checked access to single keys of a SceneDocument, driven by the schema table:
// each read checks the YAML type, finiteness and the key's range and either returns the value,
// the key's default, or throws a located SceneError.
class Reader {
 public:
  explicit Reader(const SceneDocument& doc) : doc_(doc) {}

  bool has(const std::string& path) const { return doc_.find(path).IsDefined(); }

  // A Number key: its value, or its default when Optional and absent.
  double number(const std::string& path) const {
    const KeySpec& s = spec(path);
    if (!has(path)) return absent(s);
    return checkedNumber(s, doc_.find(path));
  }
  // A Number key that must be present here for a reason the schema cannot express.
  double requiredNumber(const std::string& path, const std::string& why) const {
    const KeySpec& s = spec(path);
    if (!has(path)) doc_.failMissing(path, describeExpected(s) + " (" + why + ")");
    return checkedNumber(s, doc_.find(path));
  }
  // A Conditional Number key with a fallback decided by the caller.
  double numberOr(const std::string& path, double fallback) const {
    return has(path) ? checkedNumber(spec(path), doc_.find(path)) : fallback;
  }

  // A per-cart Number key (KeySpec::per_cart, docs/per-cart.md). A scalar (or the default when
  // absent): `uniform` gets it and the list returned is empty. A list: it must hold `count`
  // numbers, one per cart, each in the key's range; `uniform` gets NaN and the list is returned.
  // A wrong length blames carts.count instead when a later --set changed it; a bad element is
  // named key[i] (i from 0) with its cart number.
  std::vector<double> perCartNumbers(const std::string& path, int count, double& uniform) const {
    const KeySpec& s = spec(path);
    const YAML::Node node = doc_.find(path);
    if (!node.IsDefined() || !node.IsSequence()) {
      if (node.IsDefined() && !node.IsScalar())
        doc_.fail(path, describeExpected(s) + ", or " + describeExpectedList(s, count), describeNode(node));
      uniform = number(path);
      return {};
    }
    if (node.size() != static_cast<size_t>(count)) {
      if (blameSecond(doc_, path, "carts.count"))
        doc_.fail("carts.count",
                  "an integer equal to the length of " + path + " (" + std::to_string(node.size()) + ")",
                  std::to_string(count));
      doc_.fail(path, describeExpectedList(s, count), describeNode(node));
    }
    std::vector<double> values(node.size());
    for (size_t j = 0; j < node.size(); ++j)
      values[j] = checkedNumber(s, node[j], path + "[" + std::to_string(j) + "]",
                                " for cart " + std::to_string(j + 1));
    uniform = std::nan("");
    return values;
  }

  // A NumberList key: every element in the key's range, element i named key[i]; empty when absent.
  std::vector<double> numberList(const std::string& path) const {
    const KeySpec& s = spec(path);
    const YAML::Node node = doc_.find(path);
    if (!node.IsDefined()) return {};
    if (!node.IsSequence()) fail(s, describeNode(node));
    std::vector<double> values(node.size());
    for (size_t i = 0; i < node.size(); ++i)
      values[i] = checkedNumber(s, node[i], path + "[" + std::to_string(i) + "]", "");
    return values;
  }

  int integer(const std::string& path) const {
    const KeySpec& s = spec(path);
    if (!has(path)) return static_cast<int>(absent(s));
    const YAML::Node n = scalar(s, doc_.find(path));
    long long v = 0;
    if (n.Tag() == "!" || !YAML::convert<long long>::decode(n, v)) fail(s, describeNode(n));
    if (!inRange(s.range, static_cast<double>(v))) fail(s, describeNode(n));
    return static_cast<int>(v);
  }

  std::string text(const std::string& path) const {
    const KeySpec& s = spec(path);
    if (!has(path)) {
      if (s.presence == Presence::Required) doc_.failMissing(path, describeExpected(s));
      return s.default_text;
    }
    return scalar(s, doc_.find(path)).Scalar();
  }

  // A Choice key: one of its words (case-sensitive, so a misspelling is never taken for one), with
  // the closest word suggested (motor.model: parkk, motor.start.method: star-delta).
  std::string choice(const std::string& path) const {
    const std::string word = text(path);
    const KeySpec& s = spec(path);
    for (const std::string& c : s.choices)
      if (c == word) return word;
    fail(s, describeNode(doc_.find(path)) + didYouMean(word, s.choices));
  }

  // A Choice key read as the value of its enumeration in the Scene: the word's position among the
  // schema's words (SceneChoices.h).
  template <class Enum>
  Enum choiceOf(const std::string& path) const {
    return static_cast<Enum>(choicePosition(spec(path), choice(path)));
  }

  bool flag(const std::string& path) const {
    const KeySpec& s = spec(path);
    if (!has(path)) return absent(s) != 0.0;
    const std::string v = scalar(s, doc_.find(path)).Scalar();
    // YAML 1.2 core booleans only; yaml-cpp would also take yes/no/on/off/y/n.
    if (v == "true" || v == "True" || v == "TRUE") return true;
    if (v == "false" || v == "False" || v == "FALSE") return false;
    fail(s, describeNode(doc_.find(path)));
  }

  [[noreturn]] void fail(const KeySpec& s, const std::string& got) const {
    doc_.fail(s.path, describeExpected(s), got);
  }

  const SceneDocument& doc() const { return doc_; }

 private:
  static const KeySpec& spec(const std::string& path) {
    const KeySpec* s = findSceneKey(path);
    if (!s) throw std::logic_error("SceneParser reads key '" + path + "' missing from the schema");
    return *s;
  }

  static bool inRange(const Range& r, double v) {
    if (r.lo_inclusive ? v < r.lo : v <= r.lo) return false;
    if (r.hi_inclusive ? v > r.hi : v >= r.hi) return false;
    return true;
  }

  double absent(const KeySpec& s) const {
    if (s.presence != Presence::Optional) doc_.failMissing(s.path, describeExpected(s));
    return s.default_number;
  }

  // The node itself if it is a scalar; otherwise a "got a map / a list / null" error.
  YAML::Node scalar(const KeySpec& s, const YAML::Node& n) const {
    if (!n.IsScalar()) fail(s, describeNode(n));
    return n;
  }

  double checkedNumber(const KeySpec& s, const YAML::Node& node) const {
    const YAML::Node n = scalar(s, node);
    double v = 0.0;
    // A quoted "10" is a string in YAML; a number must be written as a number.
    if (n.Tag() == "!" || !YAML::convert<double>::decode(n, v)) fail(s, describeNode(n));
    if (!std::isfinite(v)) doc_.fail(s.path, finite(describeExpected(s)), n.Scalar());
    if (!inRange(s.range, v)) fail(s, describeNode(n));
    return v;
  }

  // The same check for one element of a per-cart list, located at `where` (key[i]), the
  // expected-clause ending in `which` (" for cart 3").
  double checkedNumber(const KeySpec& s, const YAML::Node& n, const std::string& where,
                       const std::string& which) const {
    const std::string expected = describeExpected(s) + which;
    double v = 0.0;
    if (!n.IsScalar() || n.Tag() == "!" || !YAML::convert<double>::decode(n, v))
      doc_.fail(where, expected, describeNode(n));
    if (!std::isfinite(v)) doc_.fail(where, finite(expected), n.Scalar());
    if (!inRange(s.range, v)) doc_.fail(where, expected, describeNode(n));
    return v;
  }

  // "a number > 0 [m]" -> "a finite number > 0 [m]": .nan and .inf parse as doubles in YAML.
  static std::string finite(const std::string& expected) {
    const std::string a_number = "a number";
    if (expected.compare(0, a_number.size(), a_number) == 0)
      return "a finite number" + expected.substr(a_number.size());
    return expected;
  }

  const SceneDocument& doc_;
};


// The motor section: Kloss's M_kr, s_kr (`motor`) and the machine behind the other laws
// (`induction`: motor.model, rated supply, motor.circuit.*, motor.catalogue.*), validated together.
void readMotor(const Reader& in, KlossMotor& motor, InductionMotor& induction);

// The crankshaft's layout (crankshaft.*): throws and main bearings along the shaft, validated
// against the number of carts (CrankshaftSceneParser.cpp).
CrankshaftLayout readCrankshaft(const Reader& in, int cart_count);
// Refuses a torsional chain (crankshaft.torsional_stiffness) where it cannot be built.
void checkTorsionalChain(const Reader& in, const Scene& s);
// sizing.*, with the ratings that could contradict each other refused (SignOffSceneParser.cpp).
SizingInputs readSizing(const Reader& in);

}  // namespace rollerdyn::scene_detail
