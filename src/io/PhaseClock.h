// Wall and CPU time of the named phases of one piece of work (a report, a short run), for
// `rollerdyn bench --study setup`. Given as a pointer that may be null: null costs nothing.
#pragma once

#include <chrono>
#include <string>
#include <vector>

namespace rollerdyn {

struct PhaseTime {
  std::string name;
  double wall = 0;        // [s]
  double cpu = 0;         // [s] of this process, all its threads
  double child_cpu = 0;   // [s] of the child processes it waited for in the phase (gnuplot)
};

class PhaseClock {
 public:
  PhaseClock();
  // Ends the phase begun at the last mark() (or construction) and records it as `name`.
  void mark(const std::string& name);
  const std::vector<PhaseTime>& phases() const { return phases_; }

 private:
  std::chrono::steady_clock::time_point wall_;
  double cpu_ = 0, child_ = 0;
  std::vector<PhaseTime> phases_;
};

// Marks `name` on `clock` if there is one.
inline void markPhase(PhaseClock* clock, const std::string& name) {
  if (clock) clock->mark(name);
}

}  // namespace rollerdyn
