// Progress of a long command on the terminal, for simulate, report and any command that runs
// for a while (sweep, bench, validate): share done, speed, estimated time left, on one line of
// stderr rewritten in place with '\r'.
//
//   simulated time:   "   42.0 %  t = 4.200 s  3.1x real time  6 s left"
//   items (runs):     "   40.0 %  4/10 runs  0.52 runs/s  12 s left"
//
// Silent when stderr is not a terminal, so logs, pipes and CI output stay clean. Redraws at most
// every 0.2 s (and always at 100 %). Speed and time left use the process CPU time, like
// summary.json's real_time_factor.
#pragma once

#include <cstdio>
#include <functional>
#include <string>

namespace rollerdyn::cli {

class Progress {
 public:
  // Draws on stderr iff stderr is a terminal.
  Progress();
  // Draws on `out` iff `enabled`; `clock` returns seconds (default: process CPU time). For tests
  // and for commands that want their own stream.
  Progress(std::FILE* out, bool enabled, std::function<double()> clock = {});
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;
  ~Progress();  // ends the line if one was drawn

  // Text put before the figures, e.g. "dphi = 60 deg" for one case of a sweep.
  void setLabel(std::string label) { label_ = std::move(label); }

  // Simulated time t of t_end seconds; usable directly as RunControl::progress.
  void operator()(double t, double t_end);
  // `done` of `total` items, e.g. runs of a sweep; `unit` names them ("runs", "cases").
  void items(double done, double total, const std::string& unit = "runs");

  bool enabled() const { return enabled_; }

 private:
  bool due(bool finished);
  void draw(const std::string& line, bool finished);

  std::FILE* out_;
  bool enabled_;
  std::function<double()> clock_;
  double start_;
  double last_ = -1;       // clock time of the last redraw, < 0 before the first
  bool line_open_ = false; // a line was drawn and not yet ended with '\n'
  std::string label_;
};

}  // namespace rollerdyn::cli
