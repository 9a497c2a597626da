// What the caller of a run may do while it runs, the same for every model and integrator: stop
// it (Ctrl-C on the command line, KeyboardInterrupt in Python) and follow its progress. A run
// stopped this way keeps the rows it has (analysis/RunRecorder.h writes the status line).
#pragma once

#include <atomic>
#include <functional>

namespace rollerdyn {

struct RunControl {
  const std::atomic<bool>* interrupt = nullptr;      // set asynchronously (Ctrl-C): stop, keep rows
  std::function<void(double t, double t_end)> progress;  // called after each output row [s], [s]
};

}  // namespace rollerdyn
