// The subcommands of the `rollerdyn` command line. Each returns the process exit code and
// throws for bad input (main() turns any exception into a one-line reason and exit code 2).
#pragma once

#include <atomic>
#include <string>
#include <vector>

namespace rollerdyn::cli {

// Options shared by the commands that read a scene.
struct SceneArgs {
  std::string scene_path;              // scene file (YAML)
  std::vector<std::string> overrides;  // --set key.path=value, in order
};

// Set by the SIGINT handler; long runs stop at the next output row and keep what they have.
extern std::atomic<bool> g_interrupted;

int runCheck(const SceneArgs& args);
int runSimulate(const SceneArgs& args, const std::string& out_dir, const std::string& model);

// out/<scene name>/ unless the user named a folder.
std::string defaultOutDir(const std::string& scene_name);

}  // namespace rollerdyn::cli
