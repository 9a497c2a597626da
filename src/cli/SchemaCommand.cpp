// `rollerdyn schema [KEY] [--markdown] [--columns]`: the keys a scene file may contain, from the
// scene schema itself (src/scene/SceneReference.h): every key, or those under KEY, with unit,
// default, allowed values, meaning and source; --markdown prints the scene file reference page
// (docs/scene-reference.md is this output, checked by a test); --columns the output columns'
// tables of docs/outputs.md, from the output column table (io/OutputColumns.h; a test checks the
// page holds them).
#include <iostream>
#include <memory>
#include <stdexcept>

#include <CLI/CLI.hpp>

#include "cli/Commands.h"
#include "io/OutputColumns.h"
#include "scene/DidYouMean.h"
#include "scene/SceneReference.h"
#include "scene/SceneSchema.h"

namespace rollerdyn::cli {

namespace {

struct SchemaArgs {
  std::string key;
  bool markdown = false;
  bool columns = false;
};

int runSchemaCommand(const SchemaArgs& a) {
  if (a.columns) {
    if (!a.key.empty() || a.markdown)
      throw std::invalid_argument("schema: --columns prints the output columns alone; leave out KEY and --markdown");
    std::cout << outputColumnsMarkdown();
    return 0;
  }
  if (a.markdown) {
    if (!a.key.empty()) throw std::invalid_argument("schema: --markdown prints the whole reference; leave out KEY");
    std::cout << sceneReferenceMarkdown();
    return 0;
  }
  if (!a.key.empty() && !findSceneKey(a.key) && !isSceneMap(a.key)) {
    std::vector<std::string> names;
    for (const KeySpec& k : sceneSchema()) {
      names.push_back(k.path);
      for (std::size_t dot = k.path.find('.'); dot != std::string::npos; dot = k.path.find('.', dot + 1))
        names.push_back(k.path.substr(0, dot));
    }
    throw std::invalid_argument("schema: expected a key or section of the scene schema, got '" + a.key + "'" +
                                didYouMean(a.key, names));
  }
  std::cout << sceneKeysText(a.key);
  return 0;
}

}  // namespace

Subcommand addSchemaCommand(CLI::App& app) {
  auto args = std::make_shared<SchemaArgs>();
  CLI::App* cmd = app.add_subcommand("schema", "the keys a scene file may contain: unit, default, allowed values, meaning, source");
  cmd->add_option("key", args->key, "a key or section, e.g. coupling or coupling.damping (default: every key)");
  cmd->add_flag("--markdown", args->markdown, "print the scene file reference as Markdown (docs/scene-reference.md)");
  cmd->add_flag("--columns", args->columns,
                "print the columns of timeseries.csv and reactions.csv (unit, meaning, which model writes them) "
                "as Markdown tables (docs/outputs.md)");
  cmd->footer("Examples:\n  rollerdyn schema coupling\n  rollerdyn schema motor.critical_slip\n"
              "  rollerdyn schema --markdown > docs/scene-reference.md");
  return {cmd, [args] { return runSchemaCommand(*args); }};
}

}  // namespace rollerdyn::cli
