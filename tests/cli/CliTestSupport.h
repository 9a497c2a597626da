// Running the built `rollerdyn` binary from a test: exit code, stdout and stderr (stderr is a
// file, never a terminal, so progress output must stay silent), plus small file helpers.
#pragma once

#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace rollerdyn::test {

struct CliResult {
  int exit_code = -1;       // -1: killed by a signal
  int signal = 0;           // the signal that ended it, 0 if it exited
  std::string out, err;
};

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

// A fresh, empty folder under the system temp dir, removed by the destructor.
class TempDir {
 public:
  explicit TempDir(const std::string& tag) {
    path_ = std::filesystem::temp_directory_path() /
            ("rollerdyn-" + tag + "-" + std::to_string(::getpid()) + "-" + std::to_string(counter()++));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  const std::filesystem::path& path() const { return path_; }
  std::string str() const { return path_.string(); }

 private:
  static int& counter() {
    static int c = 0;
    return c;
  }
  std::filesystem::path path_;
};

// Starts ROLLERDYN_BINARY with `args` in working directory `cwd` (default: the source tree),
// stdout/stderr to files in `io_dir`. Returns the pid.
inline pid_t startRollerdyn(const std::vector<std::string>& args, const std::filesystem::path& io_dir,
                            const std::string& cwd = ROLLERDYN_SOURCE_DIR) {
  const std::string out = (io_dir / "stdout.txt").string(), err = (io_dir / "stderr.txt").string();
  const pid_t pid = ::fork();
  if (pid == 0) {
    FILE* o = std::freopen(out.c_str(), "w", stdout);
    FILE* e = std::freopen(err.c_str(), "w", stderr);
    if (!o || !e) std::_Exit(127);
    std::vector<char*> argv;
    std::string bin = ROLLERDYN_BINARY;
    argv.push_back(bin.data());
    std::vector<std::string> copy = args;
    for (std::string& a : copy) argv.push_back(a.data());
    argv.push_back(nullptr);
    if (::chdir(cwd.c_str()) != 0) std::_Exit(126);
    ::execv(bin.c_str(), argv.data());
    std::_Exit(127);
  }
  return pid;
}

// Waits for `pid` at most `timeout_s` seconds (then kills it and reports signal 9).
inline CliResult waitRollerdyn(pid_t pid, const std::filesystem::path& io_dir, double timeout_s = 600) {
  CliResult r;
  int status = 0;
  const auto t0 = std::chrono::steady_clock::now();
  while (::waitpid(pid, &status, WNOHANG) == 0) {
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() > timeout_s) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  if (WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
  r.out = slurp(io_dir / "stdout.txt");
  r.err = slurp(io_dir / "stderr.txt");
  return r;
}

// Runs rollerdyn to completion; stdout/stderr captured through files in a temp dir.
inline CliResult runRollerdyn(const std::vector<std::string>& args, double timeout_s = 600) {
  TempDir io("io");
  return waitRollerdyn(startRollerdyn(args, io.path()), io.path(), timeout_s);
}

// The same, run from working directory `cwd`.
inline CliResult runRollerdynIn(const std::string& cwd, const std::vector<std::string>& args, double timeout_s = 600) {
  TempDir io("io");
  return waitRollerdyn(startRollerdyn(args, io.path(), cwd), io.path(), timeout_s);
}

inline std::string model(const std::string& file) {
  return std::string(ROLLERDYN_SOURCE_DIR) + "/model/" + file;
}

}  // namespace rollerdyn::test
