// The one exception a scene file or a --set override can raise.
// Every rejection names where the bad input is (file and 1-based line, or which --set argument),
// the dotted key path, what was expected and what was found, so a user can fix the input without
// reading the parser:
//   balanced.yaml:7: carts.cuont: expected one of the keys allowed under carts: ..., got ...
//   --set #2 (rods.length=0.1): rods.length: expected l > r = 0.2 m (crank.radius), got 0.1
#pragma once

#include <stdexcept>
#include <string>

namespace rollerdyn {

class SceneError : public std::runtime_error {
 public:
  // An error located in the scene file. line is 1-based; 0 when no line is known (then the
  // location reads "FILE" alone). key may be empty for whole-document errors.
  static SceneError inFile(const std::string& file, int line, const std::string& key,
                           const std::string& expected, const std::string& got);
  // An error whose value came from the n-th (1-based) --set argument `arg` ("key=value").
  static SceneError inOverride(const std::string& file, int n, const std::string& arg,
                               const std::string& key, const std::string& expected,
                               const std::string& got);

  const std::string& file() const { return file_; }          // scene file label
  int line() const { return line_; }                         // 1-based; 0 if unknown / --set
  const std::string& key() const { return key_; }            // dotted key path, e.g. carts.sides[1]
  const std::string& expected() const { return expected_; }  // the expected-clause
  const std::string& got() const { return got_; }            // what was found instead
  const std::string& origin() const { return origin_; }      // "FILE:LINE" or "--set #N (ARG)"
  int overrideIndex() const { return override_; }            // N of "--set #N"; 0 if from file

 private:
  SceneError(std::string file, int line, int override_index, std::string origin, std::string key,
             std::string expected, std::string got);

  std::string file_;
  int line_;
  int override_;
  std::string origin_;
  std::string key_;
  std::string expected_;
  std::string got_;
};

}  // namespace rollerdyn
