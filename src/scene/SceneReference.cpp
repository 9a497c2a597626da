#include "scene/SceneReference.h"

#include <algorithm>
#include <sstream>

#include "scene/SceneSchema.h"

namespace rollerdyn {

namespace {

std::string parentMap(const std::string& path) {
  const std::size_t dot = path.rfind('.');
  return dot == std::string::npos ? "" : path.substr(0, dot);
}

const char* presenceWord(Presence p) {
  switch (p) {
    case Presence::Required: return "required";
    case Presence::Optional: return "optional";
    case Presence::Conditional: return "conditional";
  }
  return "?";
}

// A table cell: '|' would end the cell, a line break the row.
std::string cell(const std::string& text) {
  std::string s;
  for (char c : text) {
    if (c == '|') s += "\\|";
    else if (c == '\n') s += ' ';
    else s += c;
  }
  return s;
}

std::string defaultCell(const SceneKeyDoc& k) {
  if (k.presence == "required") return "*required*";
  if (k.presence == "conditional")
    return "*conditional*" + (k.condition.empty() ? std::string() : ": " + cell(k.condition));
  if (k.default_value.empty()) return "*none*";  // free text left out (source)
  return "`" + cell(k.default_value) + "`";
}

}  // namespace

std::vector<SceneKeyDoc> sceneKeyDocs() {
  std::vector<SceneKeyDoc> docs;
  for (const KeySpec& s : sceneSchema())
    docs.push_back({s.path, parentMap(s.path), s.unit, presenceWord(s.presence), defaultText(s), s.condition,
                    describeAllowed(s), s.meaning, s.source});
  return docs;
}

namespace {

// The sections in the order of their first key.
std::vector<std::string> sectionsInOrder(const std::vector<SceneKeyDoc>& keys) {
  std::vector<std::string> sections;
  for (const SceneKeyDoc& k : keys)
    if (std::find(sections.begin(), sections.end(), k.section) == sections.end()) sections.push_back(k.section);
  return sections;
}

// The page's head: how it is made, and how to read its columns.
void referenceIntroduction(std::ostringstream& md, std::size_t key_count, std::size_t section_count) {
  md << "# Scene file reference\n\n"
     << "<!-- Generated from the scene schema by `rollerdyn schema --markdown`; do not edit by hand.\n"
     << "     A test fails when this file differs from the generated text. After changing the schema:\n"
     << "     ./build/rollerdyn schema --markdown > docs/scene-reference.md -->\n\n"
     << "Every key a scene file may contain, with its meaning, unit, default, the values allowed and the\n"
     << "paper it comes from: " << key_count << " keys in " << section_count << " sections. "
     << "A key that is not listed here is an error\n"
     << "naming the closest key. How scene files work (rules, frames and geometry, the cam drive, the\n"
     << "three ways to give the critical slip, the sizing keys): [scene files](scene-files.md).\n\n"
     << "- **unit**: SI; angles in radians except in keys ending in `_deg`; – for dimensionless.\n"
     << "- **default**: the value a key takes when the file leaves it out; *required*: the file must\n"
     << "  give it; *conditional*: required or defaulted depending on other keys, as the cell says;\n"
     << "  *none*: the key may be left out and then has no value.\n"
     << "- **allowed**: intervals in interval notation, (0, 1] means 0 < x ≤ 1. Rules that tie\n"
     << "  several keys together (l > r, one way to give the critical slip) are in the meaning.\n"
     << "- **source**: where the quantity is defined; – for rollerdyn's own numerical settings.\n"
     << "- Any key can be overridden on the command line with `--set key.path=value` and in Python\n"
     << "  with `scene.with_({\"key.path\": value})`; an override passes the same checks as the file.\n";
}

// One section: its heading, what it describes and the table of its keys.
void referenceSection(std::ostringstream& md, const std::string& section, const std::vector<SceneKeyDoc>& keys) {
  const bool nested = section.find('.') != std::string::npos;
  md << "\n" << (nested ? "### " : "## ") << (section.empty() ? "Top level" : "`" + section + "`") << "\n\n";
  const std::string about = section.empty() ? std::string("Keys at the top level of the file.")
                                            : sceneMapDescription(section);
  if (!about.empty()) md << about << "\n\n";
  md << "| key | meaning | unit | default | allowed | source |\n|---|---|---|---|---|---|\n";
  for (const SceneKeyDoc& k : keys) {
    if (k.section != section) continue;
    md << "| `" << k.key << "` | " << cell(k.meaning) << " | " << (k.unit == "-" ? "–" : cell(k.unit)) << " | "
       << defaultCell(k) << " | " << cell(k.allowed) << " | " << (k.source.empty() ? "–" : cell(k.source))
       << " |\n";
  }
}

}  // namespace

std::string sceneReferenceMarkdown() {
  const std::vector<SceneKeyDoc> keys = sceneKeyDocs();
  const std::vector<std::string> sections = sectionsInOrder(keys);
  std::ostringstream md;
  referenceIntroduction(md, keys.size(), sections.size());
  for (const std::string& section : sections) referenceSection(md, section, keys);
  return md.str();
}

std::string sceneKeysText(const std::string& prefix) {
  std::ostringstream out;
  for (const SceneKeyDoc& k : sceneKeyDocs()) {
    if (!prefix.empty() && k.key != prefix && k.key.compare(0, prefix.size() + 1, prefix + ".") != 0) continue;
    out << k.key;
    if (k.unit != "-") out << " [" << k.unit << "]";
    if (k.presence == "required") out << "  required";
    else if (k.presence == "conditional") out << "  conditional" << (k.condition.empty() ? "" : ": " + k.condition);
    else out << "  default " << (k.default_value.empty() ? "none" : k.default_value);
    out << "\n    " << k.meaning << "\n    allowed: " << k.allowed;
    if (!k.source.empty()) out << "; source: " << k.source;
    out << "\n";
  }
  return out.str();
}

}  // namespace rollerdyn
