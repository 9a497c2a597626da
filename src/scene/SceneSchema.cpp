#include "scene/SceneSchema.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "scene/DidYouMean.h"
#include "scene/SchemaSections.h"

namespace rollerdyn {

namespace {

using namespace schema_builders;

// The sections in the order of the reference (docs/scene-reference.md is generated from it).
using SchemaSection = std::vector<KeySpec> (*)();
const SchemaSection kSchemaSections[] = {
    runSchemaKeys,
    initialStateSchemaKeys,
    crankSchemaKeys,
    crankshaftSchemaKeys,
    rodSchemaKeys,
    driveSchemaKeys,
    cartSchemaKeys,
    motorSchemaKeys,
    motorCircuitSchemaKeys,
    motorCatalogueSchemaKeys,
    motorSwitchingSchemaKeys,
    reducerSchemaKeys,
    couplingSchemaKeys,
    flywheelSchemaKeys,
    loadSchemaKeys,
    sizingSchemaKeys,
    signOffSchemaKeys,
    reducedModelSchemaKeys,
};

std::vector<KeySpec> buildSchema() {
  std::vector<KeySpec> keys;
  for (SchemaSection section : kSchemaSections) {
    std::vector<KeySpec> part = section();
    keys.insert(keys.end(), std::make_move_iterator(part.begin()), std::make_move_iterator(part.end()));
  }
  return keys;
}

// One sentence per map of the schema, for the reference's section headings.
const std::vector<std::pair<std::string, std::string>>& mapDescriptions() {
  static const std::vector<std::pair<std::string, std::string>> d = {
      {"simulation", "How the run is integrated and what it writes."},
      {"initial", "The state at t = 0."},
      {"crank", "The crankshaft and its cranks."},
      {"crankshaft",
       "The crankshaft as a beam along its axis: where each crank throw and each main bearing sits "
       "(optional; without it the main bearings are known only as their resultant)."},
      {"rods", "The connecting rods, crank pin to cart hinge B."},
      {"drive", "Crank-slider or cam drive of the carts."},
      {"cam", "The cam drive of Loveikin and Pochka (cam drive paper), used when drive.type is cam."},
      {"carts", "The carts, all alike."},
      {"carts.geometry",
       "Measured from the rod hinge B in the cart's own direction (+x' away from the shaft; "
       "mirrored for an opposite cart), Loveikin, Pochka, Romasevych (2018) fig. 3."},
      {"motor",
       "The induction motor: Kloss's formula of the papers, or the law motor.model names (motor.md); "
       "Kloss's critical slip is given exactly one of three ways."},
      {"motor.circuit",
       "The equivalent circuit per phase of the equivalent star (circuit and park models); left out, "
       "it is fitted to motor.catalogue."},
      {"motor.catalogue", "The motor's data sheet at the rated supply, to which the circuit is fitted."},
      {"reducer", "The reducer between motor and crankshaft."},
      {"coupling", "The coupling between motor side and crank side, reduced to the crank axis."},
      {"flywheel", "An optional flywheel."},
      {"loads", "Technological loads on the compacting rollers, guide friction and gravity."},
      {"loads.guide_friction", "Friction of the guide rollers from the dynamic guide reactions."},
      {"sizing",
       "Ratings and targets the run is compared with (the drive-sizing answers); they change "
       "nothing in the simulation, and a figure whose rating is left out is null (n/a)."},
      {"sizing.bearing_rating", "Basic dynamic load ratings C of the joints' bearings."},
      {"sizing.fatigue",
       "S-N curves of the parts for the fatigue damage per start and per hour (rainflow counting after "
       "ASTM E1049-85 and Miner's rule)."},
      {"sizing.fatigue.coupling_torque", "S-N curve of the coupling, in amplitudes of its torque at the crank axis."},
      {"sizing.fatigue.rod_force", "S-N curve of a connecting rod, in amplitudes of its axial force."},
      {"sizing.coupling",
       "Catalogue ratings and selection factors of a flexible coupling, checked by the manufacturers' method "
       "after DIN 740-2."},
      {"reduced", "Settings of the papers' reduced-mass model only."},
  };
  return d;
}

std::string joinChoices(const std::vector<std::string>& words) {
  std::string s;
  for (size_t i = 0; i < words.size(); ++i) s += (i ? ", " : "") + words[i];
  return s;
}

std::string describeRange(const Range& r) {
  const bool has_lo = std::isfinite(r.lo);
  const bool has_hi = std::isfinite(r.hi);
  if (has_lo && has_hi) {
    return std::string("in ") + (r.lo_inclusive ? "[" : "(") + formatNumber(r.lo) + ", " +
           formatNumber(r.hi) + (r.hi_inclusive ? "]" : ")");
  }
  if (has_lo) return std::string(r.lo_inclusive ? ">= " : "> ") + formatNumber(r.lo);
  if (has_hi) return std::string(r.hi_inclusive ? "<= " : "< ") + formatNumber(r.hi);
  return "";
}

}  // namespace

const std::vector<KeySpec>& sceneSchema() {
  static const std::vector<KeySpec> schema = buildSchema();
  return schema;
}

const KeySpec* findSceneKey(const std::string& path) {
  for (const KeySpec& k : sceneSchema())
    if (k.path == path) return &k;
  return nullptr;
}

const KeySpec* findSceneKeyOrElement(const std::string& path, int* element) {
  if (element) *element = -1;
  if (const KeySpec* k = findSceneKey(path)) return k;
  // "key[i]": digits only between the brackets, at the end of the path.
  const size_t open = path.rfind('[');
  if (open == std::string::npos || open == 0 || path.back() != ']' || open + 2 > path.size() - 1) return nullptr;
  const std::string digits = path.substr(open + 1, path.size() - open - 2);
  if (digits.empty() || digits.size() > 6 || digits.find_first_not_of("0123456789") != std::string::npos)
    return nullptr;
  const KeySpec* k = findSceneKey(path.substr(0, open));
  if (!k || !k->per_cart) return nullptr;
  if (element) *element = std::stoi(digits);
  return k;
}

bool isSceneMap(const std::string& path) {
  if (path.empty()) return true;
  const std::string prefix = path + ".";
  for (const KeySpec& k : sceneSchema())
    if (k.path.compare(0, prefix.size(), prefix) == 0) return true;
  return false;
}

std::vector<std::string> sceneChildKeys(const std::string& map_path) {
  const std::string prefix = map_path.empty() ? "" : map_path + ".";
  std::vector<std::string> children;
  for (const KeySpec& k : sceneSchema()) {
    if (k.path.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string rest = k.path.substr(prefix.size());
    const std::string child = rest.substr(0, rest.find('.'));
    bool seen = false;
    for (const std::string& c : children) seen = seen || c == child;
    if (!seen) children.push_back(child);
  }
  return children;
}

std::string describeExpected(const KeySpec& spec) {
  const std::string unit = (spec.unit.empty() || spec.unit == "-") ? "" : " [" + spec.unit + "]";
  switch (spec.kind) {
    case KeyKind::Number: {
      const std::string range = describeRange(spec.range);
      return (range.empty() ? "a finite number" : "a number " + range) + unit;
    }
    case KeyKind::Integer: {
      const std::string range = describeRange(spec.range);
      return range.empty() ? "an integer" : "an integer " + range;
    }
    case KeyKind::Text: return "a text scalar";
    case KeyKind::Choice: return "one of: " + joinChoices(spec.choices);
    case KeyKind::Flag: return "true or false";
    case KeyKind::Sides:
      return "a list of same/opposite with one entry per cart, or one of the words "
             "same, opposite, alternate";
    case KeyKind::NumberList: {
      const std::string range = describeRange(spec.range);
      return "a list of numbers" + (range.empty() ? std::string() : " " + range) + unit;
    }
  }
  return "?";
}

std::string describeExpectedList(const KeySpec& spec, int count) {
  const std::string unit = (spec.unit.empty() || spec.unit == "-") ? "" : " [" + spec.unit + "]";
  const std::string range = describeRange(spec.range);
  return "a list of " + std::to_string(count) + " numbers" + (range.empty() ? "" : " " + range) + unit +
         ", one per cart (carts.count = " + std::to_string(count) + ")";
}

std::string sceneMapDescription(const std::string& map_path) {
  for (const auto& [path, text] : mapDescriptions())
    if (path == map_path) return text;
  return "";
}

std::string describeAllowed(const KeySpec& spec) {
  switch (spec.kind) {
    case KeyKind::Number: {
      const std::string range = describeRange(spec.range);
      const std::string one = range.empty() ? "any finite number" : range;
      if (spec.path == "crank.angles_deg") return "a list of carts.count values " + one + ", one per cart, the first 0";
      if (spec.path == "crankshaft.throw_positions") return "a list of carts.count values " + one + ", one per cart";
      return spec.per_cart ? one + "; or a list of carts.count such values, one per cart" : one;
    }
    case KeyKind::Integer: {
      const std::string range = describeRange(spec.range);
      return range.empty() ? "an integer" : "an integer " + range;
    }
    case KeyKind::Text: return "text";
    case KeyKind::Choice: return "one of: " + joinChoices(spec.choices);
    case KeyKind::Flag: return "true or false";
    case KeyKind::Sides: return "a list of same/opposite (one per cart), or same, opposite, alternate";
    case KeyKind::NumberList: return "a list of two or more numbers, ascending";
  }
  return "?";
}

std::string defaultText(const KeySpec& spec) {
  if (spec.presence != Presence::Optional) return "";
  const Range& r = spec.range;
  const double d = spec.default_number;
  switch (spec.kind) {
    case KeyKind::Number:
    case KeyKind::Integer:
      // A default the key's own range refuses (0 for a rating that must be > 0) stands for "absent":
      // shown as a value, a user would type it and be refused.
      if (!((d > r.lo || (r.lo_inclusive && d == r.lo)) && (d < r.hi || (r.hi_inclusive && d == r.hi))))
        return "not given";
      return formatNumber(d);
    case KeyKind::Flag: return spec.default_number != 0 ? "true" : "false";
    default: return spec.default_text;
  }
}

void requireSceneKey(const std::string& what, const std::string& key) {
  if (findSceneKey(key)) return;
  std::vector<std::string> keys;
  for (const KeySpec& k : sceneSchema()) keys.push_back(k.path);
  throw std::invalid_argument(what + ": expected a key of the scene schema (docs/scene-reference.md), got an "
                              "unknown key" + didYouMean(key, keys));
}

std::string formatNumber(double v) {
  std::ostringstream os;
  os.precision(12);
  os << v;
  return os.str();
}

}  // namespace rollerdyn
