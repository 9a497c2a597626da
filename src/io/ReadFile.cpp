#include "io/ReadFile.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace rollerdyn {

std::string readFileContents(const std::string& path, const std::string& what) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + (what.empty() ? "" : what + " ") + "'" + path + "'");
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

}  // namespace rollerdyn
