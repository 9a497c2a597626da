// The tool's version as documents state it: "rollerdyn 0.1 (commit 08674ee1c2d3)", CMake's
// project(VERSION) and the git commit at configure time (CMakeLists.txt), like `rollerdyn --version`.
#pragma once

#include <string>

namespace rollerdyn {

std::string toolVersionText();

// The current time as "2026-11-28 10:30 UTC".
std::string utcTimestamp();

}  // namespace rollerdyn
