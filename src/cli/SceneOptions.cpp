#include "cli/SceneOptions.h"

#include <CLI/CLI.hpp>

#include "cli/Commands.h"

namespace rollerdyn::cli {

void addSceneFile(CLI::App& cmd, SceneArgs& args, const std::string& help) {
  cmd.add_option("scene", args.scene_path, help)->required()->check(CLI::ExistingFile);
}

void addSceneOverrides(CLI::App& cmd, SceneArgs& args, const std::string& help) {
  // One value per --set, so a positional after it is not read as a second override.
  cmd.add_option("--set", args.overrides, help)->allow_extra_args(false);
}

void addStudyParams(CLI::App& cmd, std::vector<std::string>& params) {
  cmd.add_option("--param", params, "scene key to vary, e.g. crank.offset_deg (repeatable)")
      ->required()
      ->allow_extra_args(false);
}

}  // namespace rollerdyn::cli
