// Running a simulation from Python without holding the GIL, while Ctrl-C still works.
//
// The work runs on a worker thread with the GIL released, so other Python threads (a notebook's
// kernel, the caller's own threads) run meanwhile. The calling thread waits in steps of 50 ms and
// at each step lets Python run its signal handlers (PyErr_CheckSignals): on Ctrl-C (a notebook's
// "interrupt kernel" too) it sets `stop`, which the runs poll at each output row exactly as the
// command line's Ctrl-C does (RunControl::interrupt), waits for the work to return what it has,
// and reports the interruption; the caller keeps that partial result and raises
// KeyboardInterrupt with it. An exception of the work is rethrown in the calling thread.
#pragma once

#include <atomic>
#include <chrono>
#include <future>
#include <optional>
#include <thread>
#include <utility>

#include <pybind11/pybind11.h>

namespace rollerdyn::python {

namespace py = pybind11;

// Called with the GIL held. Returns work()'s result; *interrupted says whether Ctrl-C stopped it.
// A Python exception other than KeyboardInterrupt raised by a signal handler meanwhile is
// rethrown once the work has stopped.
template <class Work>
auto runInterruptible(Work work, std::atomic<bool>& stop, bool* interrupted) -> decltype(work()) {
  using Result = decltype(work());
  std::packaged_task<Result()> task(std::move(work));
  std::future<Result> done = task.get_future();
  std::optional<py::error_already_set> pending;
  {
    py::gil_scoped_release release;
    std::thread worker(std::move(task));
    while (done.wait_for(std::chrono::milliseconds(50)) != std::future_status::ready) {
      py::gil_scoped_acquire acquire;
      if (!pending && PyErr_CheckSignals() != 0) {
        pending.emplace();  // takes the exception the handler raised
        stop = true;
      }
    }
    worker.join();
  }
  *interrupted = false;
  if (pending) {
    if (!pending->matches(PyExc_KeyboardInterrupt)) throw std::move(*pending);
    *interrupted = true;
  }
  return done.get();
}

}  // namespace rollerdyn::python
