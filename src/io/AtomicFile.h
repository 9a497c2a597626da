// Every output file is written to a temporary sibling and renamed into place, so a crash or an
// interrupt never leaves a half-written file that looks complete (rename(2) is atomic on POSIX).
#pragma once

#include <string>

#include "io/Table.h"

namespace rollerdyn {

// Writes `contents` to `path` atomically; creates missing parent directories. Throws
// std::runtime_error naming the path on failure; the previous file, if any, is left intact.
void writeFileAtomic(const std::string& path, const std::string& contents);

// CSV with a header row of `name[unit]` cells (io/Table.h: headerWithUnit); numbers printed with 12 significant digits (enough to round-trip the
// integrator accuracies we use; full 17 digits would triple the file size for no information).
std::string toCsv(const Table& table);
void writeCsvAtomic(const std::string& path, const Table& table);

}  // namespace rollerdyn
