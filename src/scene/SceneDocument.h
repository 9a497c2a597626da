// A scene file's YAML tree together with where each part of it came from.
//
// The parser needs two things yaml-cpp does not give directly: the --set overrides merged into
// the tree (so they pass the same validation as the file), and, for every key path, whether its
// value came from the file (then: which line) or from the N-th --set argument. This class owns
// both, checks the tree's shape against the schema (unknown keys, duplicate keys, maps where
// maps belong), and turns any complaint about a key path into a correctly located SceneError.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "scene/SceneError.h"

namespace rollerdyn {

struct KeySpec;

class SceneDocument {
 public:
  // Parses `yaml_text`. A YAML syntax error, an empty file, a second document or a top level
  // that is not a map is a SceneError located in `file_label`. Without `line_numbers` (text
  // generated from data, whose lines the user never saw) errors name the label and key only.
  SceneDocument(const std::string& yaml_text, std::string file_label, bool line_numbers = true);

  // Applies the n-th (1-based) --set argument "key.path=value". The key path must be in the
  // schema; the value is parsed as a YAML scalar or flow node and replaces (or adds) that key.
  // "key[i]=value" of a per-cart key (KeySpec::per_cart) replaces element i (from 0: cart i + 1)
  // of its list; a scalar (or an absent optional key's default) is first repeated carts.count
  // times (docs/per-cart.md).
  void applyOverride(int n, const std::string& arg);

  // Rejects duplicate keys, keys not in the schema and non-maps where the schema has a map.
  // Run after all overrides, so keys brought in by a --set map value are checked too.
  void checkStructure() const;

  // The node at dotted `path` (maps only, no [i]); an undefined node if any part is absent.
  YAML::Node find(const std::string& path) const;

  const std::string& file() const { return file_; }

  // Index N of the --set argument that provided `path` (or an enclosing map), 0 if the file did.
  int overrideFor(const std::string& path) const;
  // Where `path` came from, as an error names it: "FILE:LINE" (or "FILE") or "--set #N (ARG)";
  // for a warning about a key that is accepted.
  std::string originOf(const std::string& path) const;

  // Complaint about the value at `path` (may end in [i] for a list element).
  [[noreturn]] void fail(const std::string& path, const std::string& expected,
                         const std::string& got) const;
  // Complaint that required key `path` is absent; located at the line of its parent map's key.
  [[noreturn]] void failMissing(const std::string& path, const std::string& expected) const;

 private:
  struct Override {
    int n;            // 1-based position among the --set arguments
    std::string arg;  // the argument as given, for the message
    std::string path;
  };

  // The override that provided `path` (or an enclosing map), nullptr if the file did.
  const Override* overrideOf(const std::string& path) const;
  // Records the 1-based line of every key and list element of the file tree (first occurrence).
  void recordLines(const YAML::Node& node, const std::string& path);
  // Line of `path`, or of its nearest recorded ancestor; 0 if none.
  int lineOf(const std::string& path) const;
  [[noreturn]] void failAt(const std::string& path, int line, const std::string& expected,
                           const std::string& got) const;
  [[noreturn]] void failOverride(int n, const std::string& arg, const std::string& key,
                                 const std::string& expected, const std::string& got) const;
  void checkMap(const YAML::Node& node, const std::string& path) const;
  // A map key's name: a plain scalar, not given before in the map (`seen`: name -> line of it).
  std::string uniqueKeyName(const YAML::Node& key, const std::string& path, std::map<std::string, int>& seen) const;
  // The complaint about an override whose key path is not in the schema, naming the first unknown
  // part and the keys allowed there.
  [[noreturn]] void failUnknownOverridePath(int n, const std::string& arg, const std::string& path) const;
  // The override's value as YAML: one scalar or flow value, else a complaint.
  YAML::Node overrideValue(int n, const std::string& arg, const std::string& path, const std::string& text) const;
  // The map that holds the last part of `segs`, created where the file omits it (an override may
  // set an optional key of a section the file leaves out entirely).
  YAML::Node parentMapOf(const std::vector<std::string>& segs);
  // The list of per-cart key `spec` with element `element` replaced by `value` (--set key[i]=value).
  YAML::Node listWithElement(int n, const std::string& arg, const std::string& path, const KeySpec& spec,
                             int element, const YAML::Node& value) const;
  // The YAML text scanned: one document that parses, else the complaint where it fails.
  void requireOneDocument(const std::string& yaml_text) const;
  // The list a per-cart key stands for when the file gives one value (or leaves an optional key
  // at its default): that value once per cart (carts.count).
  YAML::Node uniformList(int n, const std::string& arg, const std::string& path, const KeySpec& spec,
                         const YAML::Node& current) const;
  // 1-based line of a mark of this document; 0 for nodes built in memory or without line numbers.
  int lineAt(const YAML::Mark& m) const;
  // `line`, at least 1 (a whole-document complaint points at the top); 0 without line numbers.
  int atLeastLine1(int line) const;

  std::string file_;
  bool line_numbers_ = true;
  YAML::Node root_;
  std::vector<Override> overrides_;
  std::map<std::string, int> lines_;
};

// Dotted path of `key` under map `parent` ("" is the top level).
std::string childPath(const std::string& parent, const std::string& key);

// How a found value reads in a message: the scalar text ("-0.2", "\"10\"" if quoted),
// "a map", "a list" or "nothing (null)".
std::string describeNode(const YAML::Node& node);

}  // namespace rollerdyn
