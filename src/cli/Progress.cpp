#include "cli/Progress.h"

#include <unistd.h>

#include <cstdio>
#include <ctime>

namespace rollerdyn::cli {

namespace {

double cpuSeconds() { return double(std::clock()) / CLOCKS_PER_SEC; }

}  // namespace

Progress::Progress() : Progress(stderr, ::isatty(STDERR_FILENO) == 1) {}

Progress::Progress(std::FILE* out, bool enabled, std::function<double()> clock)
    : out_(out), enabled_(enabled && out != nullptr), clock_(clock ? std::move(clock) : cpuSeconds),
      start_(clock_()) {}

Progress::~Progress() {
  if (enabled_ && line_open_) std::fputc('\n', out_);
}

bool Progress::due(bool finished) {
  if (!enabled_) return false;
  const double now = clock_() - start_;
  if (last_ >= 0 && now - last_ < 0.2 && !finished) return false;
  last_ = now;
  return true;
}

void Progress::draw(const std::string& line, bool finished) {
  std::fprintf(out_, "\r%s%s   ", label_.empty() ? "" : (label_ + "  ").c_str(), line.c_str());
  line_open_ = !finished;
  if (finished) std::fputc('\n', out_);
  std::fflush(out_);
}

void Progress::operator()(double t, double t_end) {
  const bool finished = t >= t_end;
  if (!due(finished)) return;
  const double elapsed = last_;
  const double speed = elapsed > 0 ? t / elapsed : 0;
  const double left = speed > 0 ? (t_end - t) / speed : 0;
  char buf[160];
  std::snprintf(buf, sizeof buf, "  %5.1f %%  t = %.3f s  %.1fx real time  %.0f s left",
                t_end > 0 ? 100.0 * t / t_end : 100.0, t, speed, left);
  draw(buf, finished);
}

void Progress::items(double done, double total, const std::string& unit) {
  const bool finished = done >= total;
  if (!due(finished)) return;
  const double elapsed = last_;
  const double rate = elapsed > 0 ? done / elapsed : 0;
  const double left = rate > 0 ? (total - done) / rate : 0;
  char buf[160];
  std::snprintf(buf, sizeof buf, "  %5.1f %%  %.0f/%.0f %s  %.2f %s/s  %.0f s left",
                total > 0 ? 100.0 * done / total : 100.0, done, total, unit.c_str(), rate, unit.c_str(), left);
  draw(buf, finished);
}

}  // namespace rollerdyn::cli
