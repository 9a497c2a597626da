#include "report/OutputDir.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <system_error>

#include "report/RunFigures.h"

namespace rollerdyn {

namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const std::string& label, const std::string& dir, const std::string& why) {
  throw std::runtime_error(label + " '" + dir + "': " + why);
}

// Creates and removes a probe file: the only reliable test (permissions, read-only mounts,
// ACLs, a full quota on inodes all show here, as they would for the first output file).
void probeWritable(const std::string& label, const fs::path& dir) {
  const fs::path probe = dir / (".rollerdyn-write-test-" + std::to_string(::getpid()));
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0) fail(label, dir.string(), std::string("the folder is not writable (") + std::strerror(errno) + ")");
  const bool wrote = ::write(fd, "x", 1) == 1;
  const int write_errno = errno;
  ::close(fd);
  ::unlink(probe.c_str());
  if (!wrote) fail(label, dir.string(), std::string("cannot write into the folder (") + std::strerror(write_errno) + ")");
}

void removeIfFile(const fs::path& p, std::vector<std::string>& removed) {
  std::error_code ec;
  if (fs::is_regular_file(p, ec) && fs::remove(p, ec)) removed.push_back(p.string());
}

}  // namespace

std::vector<std::string> prepareOutputDir(const std::string& dir_in, StaleOutputs stale, const std::string& label) {
  const fs::path dir = dir_in.empty() ? fs::path(".") : fs::path(dir_in);
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    fail(label, dir_in, "expected a folder, got an existing file");
  fs::create_directories(dir, ec);
  if (ec) fail(label, dir_in, "cannot create the folder (" + ec.message() + ")");
  probeWritable(label, dir);

  std::vector<std::string> removed;
  if (stale == StaleOutputs::Keep) return removed;
  const fs::path figures = dir / "figures";
  if (fs::is_directory(figures, ec)) {
    for (const auto& entry : fs::directory_iterator(figures, ec)) {
      const fs::path& p = entry.path();
      if ((p.extension() == ".png" || p.extension() == ".svg") && isRunFigureName(p.stem().string()))
        removeIfFile(p, removed);
    }
    if (fs::is_empty(figures, ec)) fs::remove(figures, ec);  // ours, and nothing else was in it
  }
  if (stale == StaleOutputs::RunFiguresAndReport)
    for (const char* name : {"report.html", "report.png"}) removeIfFile(dir / name, removed);
  return removed;
}

}  // namespace rollerdyn
