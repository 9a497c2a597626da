// An empty folder under the system temp dir, <tmp>/rollerdyn-<name>-<pid>: whatever an earlier run
// left there is removed first. The test removes it when done (it may have made parts read-only).
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>

namespace rollerdyn::test {

inline std::filesystem::path freshTempDir(const std::string& name) {
  const std::filesystem::path p =
      std::filesystem::temp_directory_path() / ("rollerdyn-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(p);
  std::filesystem::create_directories(p);
  return p;
}

}  // namespace rollerdyn::test
