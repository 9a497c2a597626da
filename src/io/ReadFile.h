// Reading a whole file (text or binary) into memory, with an error that names the file.
#pragma once

#include <string>

namespace rollerdyn {

// The bytes of `path`. Throws std::runtime_error "cannot read <what> '<path>'" (or "cannot read
// '<path>'" when `what` is empty) when it cannot be opened.
std::string readFileContents(const std::string& path, const std::string& what = "");

}  // namespace rollerdyn
