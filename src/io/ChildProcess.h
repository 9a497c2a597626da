// One piece of work isolated in a fork()ed child process under a hard CPU limit, its result sent
// back as text over a pipe: a run that overruns its budget or crashes becomes a reported
// outcome of the parent, never a hang or a crash of it (bench repetitions, sweep points with a
// CPU budget).
#pragma once

#include <functional>
#include <optional>
#include <string>

namespace rollerdyn {

struct ChildOutcome {
  std::string text;         // what the work returned (empty or cut short if the child died)
  int wait_status = 0;      // the child's status as waitpid() reports it
  double cpu_seconds = 0;   // the child's user + system CPU time [s]
  bool exitedCleanly() const;    // the work returned and its text was sent in full
  bool stoppedByCpuLimit() const;  // killed by the CPU limit (SIGXCPU at the soft, SIGKILL at the hard one)
  bool killedBy(int signal) const;
  bool endedBySignal() const;
  std::string howItEnded() const;  // "signal N" or "exit N"
};

// Runs `work` in a child process whose CPU time is limited to cpu_soft seconds (SIGXCPU) and
// cpu_hard seconds (SIGKILL), and returns what it returned. The child leaves by _exit, without
// running exit handlers (MPI, static destructors). std::nullopt when no child can be made (no
// pipe or no fork): the caller then runs the work itself.
std::optional<ChildOutcome> runInChild(long cpu_soft, long cpu_hard, const std::function<std::string()>& work);

}  // namespace rollerdyn
