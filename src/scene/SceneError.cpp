#include "scene/SceneError.h"

#include <utility>

namespace rollerdyn {

namespace {

// "ORIGIN: KEY: expected WHAT, got GOT"; the key part is left out for whole-document errors.
std::string formatMessage(const std::string& origin, const std::string& key,
                          const std::string& expected, const std::string& got) {
  std::string m = origin + ": ";
  if (!key.empty()) m += key + ": ";
  m += "expected " + expected + ", got " + got;
  return m;
}

}  // namespace

SceneError::SceneError(std::string file, int line, int override_index, std::string origin,
                       std::string key, std::string expected, std::string got)
    : std::runtime_error(formatMessage(origin, key, expected, got)),
      file_(std::move(file)),
      line_(line),
      override_(override_index),
      origin_(std::move(origin)),
      key_(std::move(key)),
      expected_(std::move(expected)),
      got_(std::move(got)) {}

SceneError SceneError::inFile(const std::string& file, int line, const std::string& key,
                              const std::string& expected, const std::string& got) {
  std::string origin = line > 0 ? file + ":" + std::to_string(line) : file;
  return SceneError(file, line > 0 ? line : 0, 0, origin, key, expected, got);
}

SceneError SceneError::inOverride(const std::string& file, int n, const std::string& arg,
                                  const std::string& key, const std::string& expected,
                                  const std::string& got) {
  std::string origin = "--set #" + std::to_string(n) + " (" + arg + ")";
  return SceneError(file, 0, n, origin, key, expected, got);
}

}  // namespace rollerdyn
