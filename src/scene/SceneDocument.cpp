#include "scene/SceneDocument.h"

#include <algorithm>
#include <sstream>
#include <utility>

#include <yaml-cpp/eventhandler.h>

#include "scene/DidYouMean.h"
#include "scene/SceneSchema.h"

namespace rollerdyn {

namespace {

// 1-based line of a yaml-cpp mark (which counts from 0); 0 for nodes built in memory.
int lineOfMark(const YAML::Mark& m) { return m.is_null() ? 0 : m.line + 1; }

std::string joined(const std::vector<std::string>& words) {
  std::string s;
  for (size_t i = 0; i < words.size(); ++i) s += (i ? ", " : "") + words[i];
  return s;
}

// The expected-clause for a key under map `map_path`: the list of allowed keys at that level.
std::string allowedKeys(const std::string& map_path) {
  const std::string where =
      map_path.empty() ? "one of the top-level keys" : "one of the keys allowed under " + map_path;
  return where + ": " + joined(sceneChildKeys(map_path));
}

// "unknown key 'cuont' (did you mean 'count'?)"
std::string unknownKey(const std::string& map_path, const std::string& key) {
  return "unknown key '" + key + "'" + didYouMean(key, sceneChildKeys(map_path));
}

bool pathWithin(const std::string& path, const std::string& prefix) {
  if (path.compare(0, prefix.size(), prefix) != 0) return false;
  return path.size() == prefix.size() || path[prefix.size()] == '.' || path[prefix.size()] == '[';
}

std::string parentOf(const std::string& path) {
  const size_t dot = path.find_last_of(".[");
  return dot == std::string::npos ? "" : path.substr(0, dot);
}

// yaml-cpp 0.7 (Debian 12) loops forever, allocating, in YAML::LoadAll() when a ',' stands
// outside any flow collection (e.g. a file starting with ","; jbeder/yaml-cpp#1040, fixed
// upstream by #1319 after 0.8.0): the parser reports a null document without consuming the
// token, again and again. Found by fuzz/scene_fuzzer.cpp. So documents are first counted with
// the event parser, reading at most three, and two consecutive documents whose roots start at
// the same place mean the parser is stuck on such a token; only then is the tree built with
// YAML::Load() (first document). YAML::Load() alone never loops but silently drops what follows
// the first node ("[1]," loads as [1]), which this scan catches as well.
class RootMark : public YAML::EventHandler {
 public:
  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& m, YAML::anchor_t) override { node(m); }
  void OnAlias(const YAML::Mark& m, YAML::anchor_t) override { node(m); }
  void OnScalar(const YAML::Mark& m, const std::string&, YAML::anchor_t,
                const std::string&) override {
    node(m);
  }
  void OnSequenceStart(const YAML::Mark& m, const std::string&, YAML::anchor_t,
                       YAML::EmitterStyle::value) override {
    node(m);
  }
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark& m, const std::string&, YAML::anchor_t,
                  YAML::EmitterStyle::value) override {
    node(m);
  }
  void OnMapEnd() override {}

  YAML::Mark root = YAML::Mark::null_mark();  // mark of the document's first node
  bool seen = false;

 private:
  void node(const YAML::Mark& m) {
    if (!seen) root = m;
    seen = true;
  }
};

struct DocumentScan {
  int documents = 0;                                 // documents read (at most 2 counted)
  YAML::Mark second = YAML::Mark::null_mark();       // root of the second document
  bool stuck = false;                                // a token that belongs to no node
  YAML::Mark stuck_at = YAML::Mark::null_mark();
};

bool sameMark(const YAML::Mark& a, const YAML::Mark& b) {
  return a.pos == b.pos && a.line == b.line && a.column == b.column;
}

// Throws YAML::ParserException for a syntax error in the first two documents.
DocumentScan scanDocuments(const std::string& text) {
  std::istringstream in(text);
  YAML::Parser parser(in);
  DocumentScan scan;
  YAML::Mark previous = YAML::Mark::null_mark();
  for (int read = 0; read < 3; ++read) {
    RootMark doc;
    if (!parser.HandleNextDocument(doc)) break;
    if (read > 0 && sameMark(doc.root, previous)) {
      scan.stuck = true;
      scan.stuck_at = doc.root;
      --scan.documents;  // the previous "document" was the stuck token, not a document
      break;
    }
    previous = doc.root;
    if (++scan.documents == 2) scan.second = doc.root;
  }
  if (scan.documents < 2) scan.second = YAML::Mark::null_mark();
  return scan;
}

// "a ',' outside a flow list or map" when the stuck token is a comma (it always has been so
// far), a general description otherwise.
std::string strayToken(const std::string& text, const YAML::Mark& at) {
  if (at.pos >= 0 && static_cast<size_t>(at.pos) < text.size() && text[at.pos] == ',')
    return "a ',' outside a flow list or map";
  return "a token that belongs to no YAML node";
}

std::string trim(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  const size_t e = s.find_last_not_of(" \t");
  return s.substr(b, e - b + 1);
}

std::vector<std::string> splitPath(const std::string& path) {
  std::vector<std::string> parts;
  size_t start = 0;
  while (true) {
    const size_t dot = path.find('.', start);
    parts.push_back(path.substr(start, dot - start));
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  return parts;
}

}  // namespace

std::string childPath(const std::string& parent, const std::string& key) {
  return parent.empty() ? key : parent + "." + key;
}

std::string describeNode(const YAML::Node& node) {
  if (!node.IsDefined()) return "nothing (key missing)";
  switch (node.Type()) {
    case YAML::NodeType::Null: return "nothing (null)";
    case YAML::NodeType::Map: return "a map";
    case YAML::NodeType::Sequence: return "a list of " + std::to_string(node.size());
    case YAML::NodeType::Scalar:
      // A quoted scalar is a string in YAML even if it looks like a number; show the quotes.
      return node.Tag() == "!" ? "\"" + node.Scalar() + "\"" : node.Scalar();
    case YAML::NodeType::Undefined: break;
  }
  return "nothing";
}

void SceneDocument::requireOneDocument(const std::string& yaml_text) const {
  DocumentScan scan;
  try {
    scan = scanDocuments(yaml_text);  // never YAML::LoadAll(): see scanDocuments()
  } catch (const YAML::ParserException& e) {
    throw SceneError::inFile(file_, lineAt(e.mark), "", "valid YAML",
                             "a syntax error: " + e.msg);
  }
  if (scan.stuck) {
    throw SceneError::inFile(file_, atLeastLine1(lineAt(scan.stuck_at)), "", "valid YAML",
                             "a syntax error: " + strayToken(yaml_text, scan.stuck_at));
  }
  if (scan.documents == 0) {
    throw SceneError::inFile(file_, 1, "", "a map of scene keys (" + allowedKeys("") + ")",
                             "an empty document");
  }
  if (scan.documents > 1) {
    // A second document would be silently dropped by a single-document loader.
    throw SceneError::inFile(file_, lineAt(scan.second), "",
                             "exactly one YAML document per scene file",
                             "a second document (after '---')");
  }
}

SceneDocument::SceneDocument(const std::string& yaml_text, std::string file_label, bool line_numbers)
    : file_(std::move(file_label)), line_numbers_(line_numbers) {
  requireOneDocument(yaml_text);
  try {
    root_ = YAML::Load(yaml_text);
  } catch (const YAML::ParserException& e) {  // not expected: the scan parsed the same text
    throw SceneError::inFile(file_, lineAt(e.mark), "", "valid YAML",
                             "a syntax error: " + e.msg);
  }
  if (!root_.IsMap()) {
    throw SceneError::inFile(file_, atLeastLine1(lineAt(root_.Mark())), "",
                             "a map of scene keys (" + allowedKeys("") + ")",
                             describeNode(root_));
  }
  lines_[""] = atLeastLine1(lineAt(root_.Mark()));
  recordLines(root_, "");
}

void SceneDocument::recordLines(const YAML::Node& node, const std::string& path) {
  if (node.IsMap()) {
    for (auto it = node.begin(); it != node.end(); ++it) {
      if (!it->first.IsScalar()) continue;  // checkStructure() rejects it with its line
      const std::string child = childPath(path, it->first.Scalar());
      lines_.emplace(child, lineAt(it->first.Mark()));  // first occurrence wins
      recordLines(it->second, child);
    }
  } else if (node.IsSequence()) {
    for (size_t i = 0; i < node.size(); ++i) {
      const std::string child = path + "[" + std::to_string(i) + "]";
      lines_.emplace(child, lineAt(node[i].Mark()));
      recordLines(node[i], child);
    }
  }
}

int SceneDocument::lineAt(const YAML::Mark& m) const { return line_numbers_ ? lineOfMark(m) : 0; }

int SceneDocument::atLeastLine1(int line) const { return line_numbers_ ? std::max(1, line) : 0; }

int SceneDocument::lineOf(const std::string& path) const {
  std::string p = path;
  while (true) {
    const auto it = lines_.find(p);
    if (it != lines_.end() && it->second > 0) return it->second;
    if (p.empty()) return 0;
    p = parentOf(p);
  }
}

const SceneDocument::Override* SceneDocument::overrideOf(const std::string& path) const {
  // The latest override whose path encloses `path` set it last: a later --set of a whole map
  // replaces an earlier --set of one of its keys, and a later --set of a key inside an earlier
  // --set map replaces just that key.
  for (auto it = overrides_.rbegin(); it != overrides_.rend(); ++it)
    if (pathWithin(path, it->path)) return &*it;
  return nullptr;
}

int SceneDocument::overrideFor(const std::string& path) const {
  const Override* o = overrideOf(path);
  return o ? o->n : 0;
}

void SceneDocument::failAt(const std::string& path, int line, const std::string& expected,
                           const std::string& got) const {
  if (const Override* o = overrideOf(path)) failOverride(o->n, o->arg, path, expected, got);
  throw SceneError::inFile(file_, line, path, expected, got);
}

void SceneDocument::failOverride(int n, const std::string& arg, const std::string& key,
                                 const std::string& expected, const std::string& got) const {
  throw SceneError::inOverride(file_, n, arg, key, expected, got);
}

std::string SceneDocument::originOf(const std::string& path) const {
  if (const Override* o = overrideOf(path)) return SceneError::inOverride(file_, o->n, o->arg, path, "", "").origin();
  return SceneError::inFile(file_, lineOf(path), path, "", "").origin();
}

void SceneDocument::fail(const std::string& path, const std::string& expected,
                         const std::string& got) const {
  failAt(path, lineOf(path), expected, got);
}

void SceneDocument::failMissing(const std::string& path, const std::string& expected) const {
  failAt(path, lineOf(parentOf(path)), expected, "nothing (key missing)");
}

YAML::Node SceneDocument::find(const std::string& path) const {
  YAML::Node cur = root_;
  for (const std::string& seg : splitPath(path)) {
    if (!cur.IsMap()) return YAML::Node(YAML::NodeType::Undefined);
    const YAML::Node& as_const = cur;  // const lookup never inserts the key
    YAML::Node next = as_const[seg];
    if (!next.IsDefined()) return next;
    cur.reset(next);  // reset, not '=': assignment would overwrite the node inside the tree
  }
  return cur;
}

void SceneDocument::failUnknownOverridePath(int n, const std::string& arg, const std::string& path) const {
  std::string map_path;
  std::string missing = path;
  for (const std::string& seg : splitPath(path)) {
    const std::string next = childPath(map_path, seg);
    if (findSceneKey(next)) {
      failOverride(n, arg, path, "no key below leaf key " + next,
                   "unknown key path '" + path + "'");
    }
    if (seg.empty() || !isSceneMap(next)) {
      missing = seg;
      break;
    }
    map_path = next;
  }
  failOverride(n, arg, path, "a key path of the scene schema; " + allowedKeys(map_path),
               unknownKey(map_path, missing));
}

YAML::Node SceneDocument::overrideValue(int n, const std::string& arg, const std::string& path,
                                        const std::string& text) const {
  try {
    const DocumentScan scan = scanDocuments(text);
    if (scan.stuck) {
      failOverride(n, arg, path, "a YAML scalar or flow value",
                   "'" + text + "' (" + strayToken(text, scan.stuck_at) + ")");
    }
    if (scan.documents > 1) {
      failOverride(n, arg, path, "a YAML scalar or flow value",
                   "'" + text + "' (more than one YAML document)");
    }
    return YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    failOverride(n, arg, path, "a YAML scalar or flow value", "'" + text + "' (" + e.msg + ")");
  }
}

YAML::Node SceneDocument::parentMapOf(const std::vector<std::string>& segs) {
  YAML::Node cur = root_;
  std::string cur_path;
  for (size_t i = 0; i + 1 < segs.size(); ++i) {
    cur_path = childPath(cur_path, segs[i]);
    YAML::Node next = cur[segs[i]];
    if (!next.IsDefined() || next.IsNull()) {
      cur[segs[i]] = YAML::Node(YAML::NodeType::Map);
      next.reset(cur[segs[i]]);
    } else if (!next.IsMap()) {
      // The file itself is wrong here; report it where it is, not as the override's fault.
      fail(cur_path, "a map (" + allowedKeys(cur_path) + ")", describeNode(next));
    }
    cur.reset(next);
  }
  return cur;
}

void SceneDocument::applyOverride(int n, const std::string& arg) {
  const size_t eq = arg.find('=');
  if (eq == std::string::npos) {
    failOverride(n, arg, arg, "KEY.PATH=VALUE, e.g. coupling.damping=8000", "no '='");
  }
  const std::string path = trim(arg.substr(0, eq));
  const std::string text = trim(arg.substr(eq + 1));
  // The key path must exist in the schema before anything is touched.
  int element = -1;  // key[i] of a per-cart key: i
  const KeySpec* leaf = findSceneKeyOrElement(path, &element);
  if (path.empty() || !(leaf || isSceneMap(path))) failUnknownOverridePath(n, arg, path);
  YAML::Node value = overrideValue(n, arg, path, text);
  if (element >= 0) value = listWithElement(n, arg, path, *leaf, element, value);
  const std::vector<std::string> segs = splitPath(element >= 0 ? leaf->path : path);
  YAML::Node parent = parentMapOf(segs);
  parent[segs.back()] = value;
  overrides_.push_back({n, arg, path});
}

YAML::Node SceneDocument::uniformList(int n, const std::string& arg, const std::string& path, const KeySpec& spec,
                                      const YAML::Node& current) const {
  const YAML::Node count_node = find("carts.count");
  long long count = 0;
  if (!count_node.IsDefined() || !count_node.IsScalar() || !YAML::convert<long long>::decode(count_node, count) ||
      count < 1 || count > 1000)
    failOverride(n, arg, path, "a scene with a valid carts.count (a list element needs the number of carts)",
                 describeNode(count_node));
  YAML::Node uniform;
  if (current.IsDefined() && current.IsScalar()) {
    uniform = YAML::Clone(current);
  } else if (spec.presence == Presence::Optional) {
    uniform = YAML::Node(formatNumber(spec.default_number));
  } else {
    failOverride(n, arg, path, "a scene that gives " + spec.path + " (an element replaces one of its values)",
                 current.IsDefined() ? describeNode(current) : "no " + spec.path);
  }
  YAML::Node list(YAML::NodeType::Sequence);
  for (long long i = 0; i < count; ++i) list.push_back(YAML::Clone(uniform));
  return list;
}

YAML::Node SceneDocument::listWithElement(int n, const std::string& arg, const std::string& path,
                                          const KeySpec& spec, int element, const YAML::Node& value) const {
  if (!value.IsScalar())
    failOverride(n, arg, path, "one value for one cart (the whole list: --set " + spec.path + "=[...])",
                 describeNode(value));
  const YAML::Node current = find(spec.path);
  // A scalar (or an optional key's default) is the uniform value: repeated for every cart.
  const bool given_list = current.IsDefined() && current.IsSequence();
  YAML::Node list = given_list ? YAML::Node(YAML::NodeType::Sequence) : uniformList(n, arg, path, spec, current);
  if (given_list)
    for (size_t i = 0; i < current.size(); ++i) list.push_back(YAML::Clone(current[i]));
  if (static_cast<size_t>(element) >= list.size())
    failOverride(n, arg, path,
                 "an index from 0 to " + std::to_string(list.size() - 1) + " (" + spec.path + " has " +
                     std::to_string(list.size()) + " values, one per cart; [0] is cart 1)",
                 std::to_string(element));
  list[static_cast<size_t>(element)] = value;
  list.SetStyle(YAML::EmitterStyle::Flow);
  return list;
}

void SceneDocument::checkStructure() const { checkMap(root_, ""); }

void SceneDocument::checkMap(const YAML::Node& node, const std::string& path) const {
  if (node.IsNull()) return;  // an empty section: every key in it takes its default
  if (!node.IsMap()) fail(path, "a map (" + allowedKeys(path) + ")", describeNode(node));

  std::map<std::string, int> seen;  // key -> line of its first occurrence
  for (auto it = node.begin(); it != node.end(); ++it) {
    const std::string key = uniqueKeyName(it->first, path, seen);
    const std::string child = childPath(path, key);
    if (isSceneMap(child)) {
      checkMap(it->second, child);
    } else if (!findSceneKey(child)) {
      failAt(child, lineAt(it->first.Mark()), allowedKeys(path), unknownKey(path, key));
    }
  }
}

std::string SceneDocument::uniqueKeyName(const YAML::Node& key_node, const std::string& path,
                                         std::map<std::string, int>& seen) const {
  const int key_line = lineAt(key_node.Mark());
  if (!key_node.IsScalar()) {
    failAt(childPath(path, "?"), key_line, "a plain key name (" + allowedKeys(path) + ")", describeNode(key_node));
  }
  const std::string key = key_node.Scalar();
  const auto first = seen.find(key);
  if (first != seen.end()) {
    // yaml-cpp keeps both entries and lookups see only the first: never let one hide.
    failAt(childPath(path, key), key_line,
           "each key at most once (first given at line " + std::to_string(first->second) + ")",
           "a second '" + key + "'");
  }
  seen.emplace(key, key_line);
  return key;
}

}  // namespace rollerdyn
