#include "studies/SweepPointBudget.h"
#include "io/Pipe.h"

#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <limits>
#include <sstream>

#include "studies/SweepProgress.h"

namespace rollerdyn {

namespace {

}  // namespace

SweepPoint runSweepPointWithBudget(const SweepOptions& o, const std::vector<std::string>& texts,
                                   const std::vector<double>& values, double budget) {
  int fds[2];
  if (::pipe(fds) != 0) return runSweepPoint(o, texts, values);  // no isolation possible
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    return runSweepPoint(o, texts, values);
  }
  if (pid == 0) {  // child: run, send the row, leave without running exit handlers (MPI, ...)
    ::close(fds[0]);
    const rlim_t soft = rlim_t(std::ceil(budget));
    const struct rlimit lim = {soft, soft + 1};
    ::setrlimit(RLIMIT_CPU, &lim);
    const SweepPoint p = runSweepPoint(o, texts, values);
    writeAllToFd(fds[1], sweepPointToJson(p).dump());
    ::close(fds[1]);
    ::_exit(0);
  }
  ::close(fds[1]);
  const std::string text = readAllFromFd(fds[0]);
  ::close(fds[0]);
  int wstatus = 0;
  struct rusage usage {};
  while (::wait4(pid, &wstatus, 0, &usage) < 0 && errno == EINTR) {
  }
  if (WIFEXITED(wstatus) && WEXITSTATUS(wstatus) == 0) {
    try {
      return sweepPointFromJson(nlohmann::json::parse(text));
    } catch (const std::exception&) {
      // fall through: an incomplete row is a failure of the run process
    }
  }
  SweepPoint p;
  p.texts = texts;
  p.values = values;
  p.metrics.assign(sweepNumericMetrics().size(), std::numeric_limits<double>::quiet_NaN());
  p.ran = true;
  p.cpu_seconds = double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                  1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  std::ostringstream os;
  if (WIFSIGNALED(wstatus) && (WTERMSIG(wstatus) == SIGXCPU || WTERMSIG(wstatus) == SIGKILL)) {
    os << "timeout: CPU budget " << budget << " s exceeded (stopped by the CPU limit)";
  } else if (WIFSIGNALED(wstatus)) {
    os << "error: run process ended by signal " << WTERMSIG(wstatus);
  } else {
    os << "error: run process ended abnormally (exit " << WEXITSTATUS(wstatus) << ")";
  }
  p.status = os.str();
  return p;
}

}  // namespace rollerdyn
