#include "report/Gnuplot.h"

#include <unistd.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <stdexcept>
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

// Runs ONE gnuplot on a script that draws `script_body` once for each output (to a temporary
// name each, renamed into place after): a figure in PNG and SVG costs one start of gnuplot, not
// two. `reset` between the outputs gives each the settings of a fresh gnuplot (terminal and
// output are not reset).
void runGnuplot(const std::string& script_body, const std::vector<Output>& outputs) {
  namespace fs = std::filesystem;
  if (outputs.empty()) return;
  const std::string pid = std::to_string(::getpid());
  std::string script;
  std::vector<std::string> tmp;
  for (const Output& o : outputs) {
    const fs::path target(o.file);
    if (target.has_parent_path()) fs::create_directories(target.parent_path());
    const std::string tmp_out = o.file + ".tmp." + pid;
    tmp.push_back(tmp_out);
    if (!script.empty()) script += "reset\n";
    script += "set terminal " + o.terminal + "\nset output " + quoted(tmp_out) + "\n" + script_body +
              "\nunset output\n";
  }
  const std::string script_path = outputs.front().file + ".gp.tmp." + pid;
  writeFileAtomic(script_path, script);
  const std::string cmd = "gnuplot " + quoted(script_path) + " 2>/dev/null";
  const int rc = std::system(cmd.c_str());
  std::remove(script_path.c_str());
  bool drawn = rc == 0;
  for (const std::string& t : tmp) drawn = drawn && fs::exists(t);
  if (!drawn) {
    for (const std::string& t : tmp) std::remove(t.c_str());
    throw std::runtime_error("gnuplot failed to draw '" + outputs.front().file + "'");
  }
  for (size_t i = 0; i < outputs.size(); ++i) fs::rename(tmp[i], outputs[i].file);
}

void render(const std::string& body, int w, int h, const std::string& base, bool png, bool svg) {
  if (!gnuplotAvailable()) throw std::runtime_error("gnuplot not found (Debian package gnuplot-nox)");
  const std::string size = std::to_string(w) + "," + std::to_string(h);
  std::vector<Output> outputs;
  if (png) outputs.push_back({"pngcairo size " + size + " font 'Sans,10'", base + ".png"});
  if (svg) outputs.push_back({"svg size " + size + " dynamic font 'Sans,10'", base + ".svg"});
  runGnuplot(body, outputs);
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

void renderPlot(const PlotSpec& spec, const std::string& base, bool png, bool svg) {
  std::ostringstream os;
  os.precision(12);
  os << "set title " << quoted(spec.title) << "\nset xlabel " << quoted(spec.xlabel) << "\nset ylabel "
     << quoted(spec.ylabel) << "\nset grid\nset key outside right top\n";
  if (spec.logx) os << "set logscale x\nset format x '10^{%L}'\n";
  if (spec.logy) os << "set logscale y\nset format y '10^{%L}'\n";
  if (!spec.preamble.empty()) os << spec.preamble << '\n';
  for (size_t i = 0; i < spec.series.size(); ++i) {
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
  render(os.str(), spec.width, spec.height, base, png, svg);
}

void renderHeatMap(const std::string& title, const std::string& xlabel, const std::string& ylabel,
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
  render(os.str(), 900, 640, base, png, svg);
}

}  // namespace rollerdyn
