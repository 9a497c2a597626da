#include "io/AtomicFile.h"

#include <unistd.h>

#include <charconv>
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
  std::string out;
  for (size_t i = 0; i < table.columns.size(); ++i) out += (i ? "," : "") + headerWithUnit(table.columns[i]);
  out += '\n';
  // Numbers as printf's %.12g (what an ostream with precision 12 writes), by std::to_chars,
  // which is specified to give exactly that text and costs a fraction of a stream insertion
  // (a 2001-row run's tables were a fifth of the process's instructions).
  char buf[32];
  for (const auto& row : table.rows) {
    for (size_t i = 0; i < row.size(); ++i) {
      if (i) out += ',';
      const std::to_chars_result r = std::to_chars(buf, buf + sizeof buf, row[i], std::chars_format::general, 12);
      out.append(buf, r.ptr);
    }
    out += '\n';
  }
  return out;
}

void writeCsvAtomic(const std::string& path, const Table& table) {
  writeFileAtomic(path, toCsv(table));
}

}  // namespace rollerdyn
