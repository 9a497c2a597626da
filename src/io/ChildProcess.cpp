#include "io/ChildProcess.h"

#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstddef>
#include <cstdio>

namespace rollerdyn {
namespace {

// Writes all of `text` to `fd`, retrying after signals; gives up silently on a write error
// (the reader then sees a short message and reports the child as failed).
void writeAllToFd(int fd, const std::string& text) {
  const char* p = text.data();
  std::size_t left = text.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      return;
    }
    p += n;
    left -= std::size_t(n);
  }
}

// Reads `fd` to end of file (or a read error), retrying after signals.
std::string readAllFromFd(int fd) {
  std::string out;
  char buf[65536];
  for (;;) {
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    out.append(buf, std::size_t(n));
  }
  return out;
}

// The child's side: the work under the CPU limit, its text sent down the pipe, then _exit (no exit
// handlers run in the child).
[[noreturn]] void workInChild(const int fds[2], long cpu_soft, long cpu_hard,
                              const std::function<std::string()>& work) {
  ::close(fds[0]);
  const struct rlimit lim = {rlim_t(cpu_soft), rlim_t(cpu_hard)};
  ::setrlimit(RLIMIT_CPU, &lim);
  writeAllToFd(fds[1], work());
  ::close(fds[1]);
  ::_exit(0);
}

// The parent's side: the child's text read to end of file, then its wait status and its user +
// system CPU time [s] once it has ended.
ChildOutcome collectChild(pid_t pid, const int fds[2]) {
  ::close(fds[1]);
  ChildOutcome out;
  out.text = readAllFromFd(fds[0]);
  ::close(fds[0]);
  struct rusage usage {};
  while (::wait4(pid, &out.wait_status, 0, &usage) < 0 && errno == EINTR) {
  }
  out.cpu_seconds = double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                    1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  return out;
}

}  // namespace

bool ChildOutcome::exitedCleanly() const { return WIFEXITED(wait_status) && WEXITSTATUS(wait_status) == 0; }

bool ChildOutcome::stoppedByCpuLimit() const { return killedBy(SIGXCPU) || killedBy(SIGKILL); }

bool ChildOutcome::killedBy(int signal) const { return WIFSIGNALED(wait_status) && WTERMSIG(wait_status) == signal; }

bool ChildOutcome::endedBySignal() const { return WIFSIGNALED(wait_status); }

std::string ChildOutcome::howItEnded() const {
  return WIFSIGNALED(wait_status) ? "signal " + std::to_string(WTERMSIG(wait_status))
                                  : "exit " + std::to_string(WEXITSTATUS(wait_status));
}

std::optional<ChildOutcome> runInChild(long cpu_soft, long cpu_hard, const std::function<std::string()>& work) {
  int fds[2];
  if (::pipe(fds) != 0) return std::nullopt;
  std::fflush(nullptr);  // nothing buffered is printed twice
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    return std::nullopt;
  }
  if (pid == 0) workInChild(fds, cpu_soft, cpu_hard, work);
  return collectChild(pid, fds);
}

}  // namespace rollerdyn
