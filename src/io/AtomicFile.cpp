#include "io/AtomicFile.h"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace rollerdyn {

void writeFileAtomic(const std::string& path, const std::string& contents) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  if (target.has_parent_path()) fs::create_directories(target.parent_path());
  const std::string tmp = path + ".tmp." + std::to_string(::getpid());
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot open '" + tmp + "' for writing");
    out << contents;
    out.flush();
    if (!out) {
      std::remove(tmp.c_str());
      throw std::runtime_error("cannot write '" + tmp + "'");
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw std::runtime_error("cannot rename '" + tmp + "' to '" + path + "'");
  }
}

std::string toCsv(const Table& table) {
  std::ostringstream os;
  os.precision(12);
  for (size_t i = 0; i < table.columns.size(); ++i) os << (i ? "," : "") << headerWithUnit(table.columns[i]);
  os << '\n';
  for (const auto& row : table.rows) {
    for (size_t i = 0; i < row.size(); ++i) os << (i ? "," : "") << row[i];
    os << '\n';
  }
  return os.str();
}

void writeCsvAtomic(const std::string& path, const Table& table) {
  writeFileAtomic(path, toCsv(table));
}

}  // namespace rollerdyn
