// Whole-message transfer over a pipe between a fork()ed child and its parent: the child writes
// its result as text, the parent reads until end of file. Used where a run is isolated in a
// child process under a CPU limit (bench repetitions, sweep points with a CPU budget).
#pragma once

#include <string>

namespace rollerdyn {

// Writes all of `text` to `fd`, retrying after signals; gives up silently on a write error
// (the reader then sees a short message and reports the child as failed).
void writeAllToFd(int fd, const std::string& text);

// Reads `fd` to end of file (or a read error), retrying after signals.
std::string readAllFromFd(int fd);

}  // namespace rollerdyn
