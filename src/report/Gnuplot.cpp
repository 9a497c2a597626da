#include "report/Gnuplot.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <utility>
#include <vector>

#include "io/AtomicFile.h"

namespace rollerdyn {
namespace {

// A gnuplot double-quoted string. Control characters are escaped or dropped: a raw newline would
// end the string and make the rest of a title (a file name, a CSV header) a gnuplot command.
std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '\n') { out += "\\n"; continue; }
    if (c == '\t') { out += ' '; continue; }
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) continue;
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

// One output of a figure: gnuplot's terminal and the file.
struct Output {
  std::string terminal, file;
};

std::vector<Output> outputsOf(const PlotJob& job) {
  const std::string size = std::to_string(job.width) + "," + std::to_string(job.height);
  std::vector<Output> outputs;
  if (job.png) outputs.push_back({"pngcairo size " + size + " font 'Sans,10'", job.base + ".png"});
  if (job.svg) outputs.push_back({"svg size " + size + " dynamic font 'Sans,10'", job.base + ".svg"});
  return outputs;
}

// One gnuplot run's script and the files it draws (temporary name, final name).
struct BatchScript {
  std::string script;
  std::vector<std::pair<std::string, std::string>> files;
};

// Every job's commands once for each of its outputs, each to a temporary name (its folder made).
BatchScript batchScript(const std::vector<const PlotJob*>& jobs, const std::string& tag) {
  namespace fs = std::filesystem;
  BatchScript b;
  for (const PlotJob* job : jobs) {
    bool first_output = true;
    for (const Output& o : outputsOf(*job)) {
      const fs::path target(o.file);
      if (target.has_parent_path()) fs::create_directories(target.parent_path());
      const std::string tmp_out = o.file + ".tmp." + tag;
      b.files.push_back({tmp_out, o.file});
      if (!b.script.empty()) b.script += first_output ? "reset session\n" : "reset\n";
      first_output = false;
      b.script += "set terminal " + o.terminal + "\nset output " + quoted(tmp_out) + "\n" + job->script +
                  "\nunset output\n";
    }
  }
  return b;
}

// Runs ONE gnuplot on a script that draws every job's commands once for each of its outputs (to a
// temporary name each). `reset` between the outputs of a figure and `reset session` between
// figures give each the settings of a fresh gnuplot (terminal and output are not reset). Returns
// true when gnuplot succeeded and every temporary file exists; then they are renamed into place.
// Otherwise the temporary files are removed and nothing is renamed.
bool runGnuplot(const std::vector<const PlotJob*>& jobs, const std::string& tag) {
  namespace fs = std::filesystem;
  const BatchScript batch = batchScript(jobs, tag);
  const std::string& script = batch.script;
  const std::vector<std::pair<std::string, std::string>>& files = batch.files;
  if (files.empty()) return true;
  const std::string script_path = files.front().second + ".gp.tmp." + tag;
  writeFileAtomic(script_path, script);
  const std::string cmd = "gnuplot " + quoted(script_path) + " 2>/dev/null";
  const int rc = std::system(cmd.c_str());
  std::remove(script_path.c_str());
  bool drawn = rc == 0;
  for (const auto& f : files) drawn = drawn && fs::exists(f.first);
  if (!drawn) {
    for (const auto& f : files) std::remove(f.first.c_str());
    return false;
  }
  for (const auto& f : files) fs::rename(f.first, f.second);
  return true;
}

void drawOne(const PlotJob& job, const std::string& tag) {
  if (!runGnuplot({&job}, tag)) {
    const std::vector<Output> outputs = outputsOf(job);
    throw std::runtime_error("gnuplot failed to draw '" + (outputs.empty() ? job.base : outputs.front().file) + "'");
  }
}

}  // namespace

std::string escapeUnderscores(const std::string& text) {
  std::string out;
  for (char c : text) out += (c == '_') ? std::string("\\_") : std::string(1, c);
  return out;
}

bool gnuplotAvailable() {
  // Found once, found for the process (a shell started per figure cost as much as a small
  // figure); not found is looked for again.
  static std::atomic<bool> found{false};
  if (!found) found = std::system("command -v gnuplot >/dev/null 2>&1") == 0;
  return found;
}

namespace {

// Series i as the datablock $Di: the points gnuplot can draw (finite, positive on a log axis); a
// point that cannot be drawn breaks the line where the series asks for it.
void writeDataBlock(std::ostringstream& os, const PlotSpec& spec, size_t i) {
  const PlotSeries& s = spec.series[i];
  os << "$D" << i << " << EOD\n";
  bool gap = false;  // a blank line in gnuplot data breaks a line; write at most one in a row
  for (size_t k = 0; k < s.x.size() && k < s.y.size(); ++k) {
    const bool ok = std::isfinite(s.x[k]) && std::isfinite(s.y[k]) && (!spec.logx || s.x[k] > 0) &&
                    (!spec.logy || s.y[k] > 0);
    if (ok) {
      os << s.x[k] << ' ' << s.y[k] << '\n';
      gap = false;
    } else if (s.break_at_nonfinite && !gap) {
      os << '\n';
      gap = true;
    }
  }
  os << "EOD\n";
}

// The plot command: every datablock with its style, width, colour, dash and title.
void writePlotCommand(std::ostringstream& os, const PlotSpec& spec) {
  os << "plot ";
  for (size_t i = 0; i < spec.series.size(); ++i) {
    const PlotSeries& s = spec.series[i];
    os << (i ? ", " : "") << "$D" << i << " using 1:2 with " << s.style;
    if (s.line_width != 1.0) os << " lw " << s.line_width;
    if (!s.color.empty()) os << " lc rgb " << quoted(s.color);
    if (s.dash > 0) os << " dt " << s.dash;
    os << " title " << quoted(s.title);
  }
  if (spec.series.empty()) os << "NaN notitle";
  os << '\n';
}

}  // namespace

PlotJob plotJob(const PlotSpec& spec, const std::string& base, bool png, bool svg) {
  std::ostringstream os;
  os.precision(12);
  os << "set title " << quoted(spec.title) << "\nset xlabel " << quoted(spec.xlabel) << "\nset ylabel "
     << quoted(spec.ylabel) << "\nset grid\nset key outside right top\n";
  if (spec.logx) os << "set logscale x\nset format x '10^{%L}'\n";
  if (spec.logy) os << "set logscale y\nset format y '10^{%L}'\n";
  if (!spec.preamble.empty()) os << spec.preamble << '\n';
  for (size_t i = 0; i < spec.series.size(); ++i) writeDataBlock(os, spec, i);
  writePlotCommand(os, spec);
  return {os.str(), spec.width, spec.height, base, png, svg};
}

void renderPlot(const PlotSpec& spec, const std::string& base, bool png, bool svg) {
  renderPlots({plotJob(spec, base, png, svg)}, 1);
}

PlotJob heatMapJob(const std::string& title, const std::string& xlabel, const std::string& ylabel,
                   const std::string& zlabel, const std::vector<double>& x, const std::vector<double>& y,
                   const std::vector<std::vector<double>>& z, const std::string& base, bool png, bool svg,
                   const std::string& preamble) {
  std::ostringstream os;
  os.precision(12);
  os << "set title " << quoted(title) << "\nset xlabel " << quoted(xlabel) << "\nset ylabel " << quoted(ylabel)
     << "\nset cblabel " << quoted(zlabel) << "\nset view map\nset palette rgb 33,13,10\n$G << EOD\n";
  for (size_t i = 0; i < y.size(); ++i) {
    for (size_t j = 0; j < x.size(); ++j) {
      const double v = (i < z.size() && j < z[i].size()) ? z[i][j] : NAN;
      os << x[j] << ' ' << y[i] << ' ';
      if (std::isfinite(v)) os << v; else os << "NaN";
      os << '\n';
    }
    os << '\n';
  }
  os << "EOD\n" << preamble << (preamble.empty() || preamble.back() == '\n' ? "" : "\n")
     << "plot $G using 1:2:3 with image notitle\n";
  return {os.str(), 900, 640, base, png, svg};
}

void renderHeatMap(const std::string& title, const std::string& xlabel, const std::string& ylabel,
                   const std::string& zlabel, const std::vector<double>& x, const std::vector<double>& y,
                   const std::vector<std::vector<double>>& z, const std::string& base, bool png, bool svg,
                   const std::string& preamble) {
  renderPlots({heatMapJob(title, xlabel, ylabel, zlabel, x, y, z, base, png, svg, preamble)}, 1);
}

namespace {

// Shares of about equal script length (what gnuplot reads and draws), in the jobs' order.
std::vector<std::vector<const PlotJob*>> shareJobs(const std::vector<PlotJob>& jobs, int processes) {
  size_t total = 0;
  for (const PlotJob& j : jobs) total += j.script.size() + 1;
  std::vector<std::vector<const PlotJob*>> shares(static_cast<size_t>(processes));
  size_t done = 0;
  for (const PlotJob& j : jobs) {
    const size_t k = std::min(size_t(processes) - 1, done * size_t(processes) / total);
    shares[k].push_back(&j);
    done += j.script.size() + 1;
  }
  return shares;
}

}  // namespace

void renderPlots(const std::vector<PlotJob>& jobs, int processes) {
  if (jobs.empty()) return;
  if (!gnuplotAvailable()) throw std::runtime_error("gnuplot not found (Debian package gnuplot-nox)");
  if (processes <= 0) processes = int(std::max(1u, std::thread::hardware_concurrency()));
  processes = std::min<int>(processes, int(jobs.size()));
  const std::vector<std::vector<const PlotJob*>> shares = shareJobs(jobs, processes);
  static std::atomic<long> serial{0};
  const std::string pid = std::to_string(::getpid());
  std::vector<char> ok(shares.size(), 0);
  auto draw = [&](size_t k) { ok[k] = runGnuplot(shares[k], pid + "." + std::to_string(serial++)); };
  std::vector<std::thread> pool;
  for (size_t k = 1; k < shares.size(); ++k) pool.emplace_back(draw, k);
  if (!shares.empty()) draw(0);
  for (std::thread& t : pool) t.join();
  for (size_t k = 0; k < shares.size(); ++k)
    if (!ok[k])
      for (const PlotJob* j : shares[k]) drawOne(*j, pid + "." + std::to_string(serial++));
}

}  // namespace rollerdyn
