// Bad scene files on disk (tests/scene/bad/*.yaml): each file states the message fragments it
// must produce in lines "# expect: <fragment>", so the corpus documents itself and a new bad
// file is a new test without code.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "scene/SceneParser.h"

namespace rollerdyn {
namespace {

namespace fs = std::filesystem;

const fs::path kBadDir = fs::path(ROLLERDYN_SOURCE_DIR) / "tests" / "scene" / "bad";

std::vector<std::string> expectedFragments(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> out;
  const std::string tag = "# expect: ";
  for (std::string line; std::getline(in, line);)
    if (line.rfind(tag, 0) == 0) out.push_back(line.substr(tag.size()));
  return out;
}

std::vector<fs::path> badFiles() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(kBadDir))
    if (entry.path().extension() == ".yaml") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

TEST(SceneBadFiles, CorpusIsPresent) {
  // Guards against the loop below passing vacuously on a missing or emptied directory.
  EXPECT_GE(badFiles().size(), 8u);
}

TEST(SceneBadFiles, EachFileFailsWithItsExpectedMessage) {
  for (const fs::path& file : badFiles()) {
    SCOPED_TRACE(file.filename().string());
    const std::vector<std::string> fragments = expectedFragments(file);
    ASSERT_FALSE(fragments.empty()) << "bad file has no '# expect: ' line";
    try {
      parseSceneFile(file.string());
      ADD_FAILURE() << "parsed without error";
    } catch (const SceneError& e) {
      const std::string msg = e.what();
      // Every message starts with the file path it came from.
      EXPECT_EQ(msg.rfind(file.string(), 0), 0u) << msg;
      for (const std::string& f : fragments)
        EXPECT_NE(msg.find(f), std::string::npos) << "message lacks \"" << f << "\":\n  " << msg;
    }
  }
}

}  // namespace
}  // namespace rollerdyn
