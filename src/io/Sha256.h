// SHA-256 (FIPS 180-4) of a byte string, as 64 lower-case hex digits: the same as `sha256sum`
// prints, so a reader can check that a document was made from the file it names.
#pragma once

#include <string>

namespace rollerdyn {

std::string sha256Hex(const std::string& bytes);

}  // namespace rollerdyn
