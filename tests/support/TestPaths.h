// Where the tests find the source tree and the command line built beside them. The two paths live
// in one file generated per build folder (tests/CMakeLists.txt), and ROLLERDYN_SOURCE_DIR and
// ROLLERDYN_BINARY call these functions, so no other test file holds an absolute path.
#pragma once

namespace rollerdyn::test {
const char* sourceDir();   // the source tree (absolute)
const char* binaryPath();  // the rollerdyn command line of this build (absolute)
}  // namespace rollerdyn::test
