// The options every command that reads a scene registers alike: the scene file (the positional
// argument), its --set overrides and, for the studies, the scene keys they vary. Each command
// keeps its own help words; the option's name, type and checks live here once.
#pragma once

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace rollerdyn::cli {

struct SceneArgs;

// The help words most commands give the scene file and --set.
inline constexpr const char* kSceneFileHelp = "scene file (YAML), e.g. model/balanced-4cart.yaml";
inline constexpr const char* kOverridesHelp = "override a scene value, key.path=value (repeatable)";

// The required positional `scene`: an existing file.
void addSceneFile(CLI::App& cmd, SceneArgs& args, const std::string& help = kSceneFileHelp);
// --set key.path=value (repeatable), kept in the order given.
void addSceneOverrides(CLI::App& cmd, SceneArgs& args, const std::string& help = kOverridesHelp);
// --param KEY (repeatable, required): the scene keys a sweep or an optimization varies.
void addStudyParams(CLI::App& cmd, std::vector<std::string>& params);

}  // namespace rollerdyn::cli
