#include "io/PhaseClock.h"

#include <sys/resource.h>

namespace rollerdyn {
namespace {

double seconds(const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); }

double cpuOf(int who) {
  rusage u{};
  getrusage(who, &u);
  return seconds(u.ru_utime) + seconds(u.ru_stime);
}

}  // namespace

PhaseClock::PhaseClock()
    : wall_(std::chrono::steady_clock::now()), cpu_(cpuOf(RUSAGE_SELF)), child_(cpuOf(RUSAGE_CHILDREN)) {}

void PhaseClock::mark(const std::string& name) {
  const auto now = std::chrono::steady_clock::now();
  const double cpu = cpuOf(RUSAGE_SELF), child = cpuOf(RUSAGE_CHILDREN);
  phases_.push_back({name, std::chrono::duration<double>(now - wall_).count(), cpu - cpu_, child - child_});
  wall_ = now;
  cpu_ = cpu;
  child_ = child;
}

}  // namespace rollerdyn
