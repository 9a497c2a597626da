#include "studies/SweepProgress.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>

#include "io/AtomicFile.h"
#include "io/ReadFile.h"

namespace rollerdyn {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

nlohmann::json number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }
double number(const nlohmann::json& j) { return j.is_number() ? j.get<double>() : kNaN; }

double steadySeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

void writeLine(int fd, const std::string& path, const std::string& line) {
  const char* p = line.data();
  std::size_t left = line.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
    }
    p += n;
    left -= std::size_t(n);
  }
}

}  // namespace

nlohmann::json sweepPointToJson(const SweepPoint& p) {
  nlohmann::json values = nlohmann::json::array(), metrics = nlohmann::json::object();
  for (double v : p.values) values.push_back(number(v));
  const auto& names = sweepNumericMetrics();
  for (std::size_t k = 0; k < names.size() && k < p.metrics.size(); ++k) metrics[names[k]] = number(p.metrics[k]);
  return {{"texts", p.texts},         {"values", values},     {"metrics", metrics},
          {"ran", p.ran},             {"complete", p.complete}, {"steady", p.steady},
          {"status", p.status},       {"motion", p.motion},     {"cpu_seconds", number(p.cpu_seconds)}, {"warnings", p.warnings}};
}

SweepPoint sweepPointFromJson(const nlohmann::json& j) {
  SweepPoint p;
  p.texts = j.at("texts").get<std::vector<std::string>>();
  for (const auto& v : j.at("values")) p.values.push_back(number(v));
  const auto& names = sweepNumericMetrics();
  const nlohmann::json& m = j.at("metrics");
  p.metrics.assign(names.size(), kNaN);
  for (std::size_t k = 0; k < names.size(); ++k)
    if (m.contains(names[k])) p.metrics[k] = number(m[names[k]]);
  p.ran = j.at("ran").get<bool>();
  p.complete = j.at("complete").get<bool>();
  p.steady = j.at("steady").get<bool>();
  p.status = j.at("status").get<std::string>();
  p.motion = j.value("motion", std::string("not run"));
  p.cpu_seconds = number(j.at("cpu_seconds"));
  p.warnings = j.at("warnings");
  return p;
}

std::string sweepFingerprint(const SweepOptions& o, const std::vector<std::vector<std::string>>& designs) {
  nlohmann::json what = {{"scene_text", o.scene_input ? o.scene_input->text : readFileContents(o.scene_path, "scene")},
                         {"model", o.model},
                         {"base_overrides", o.base_overrides},
                         {"designs", designs},
                         {"point_budget", o.point_budget},
                         {"metrics", sweepNumericMetrics()}};
  nlohmann::json keys = nlohmann::json::array();
  for (const SweepParameter& p : o.params) keys.push_back(p.key);
  what["keys"] = keys;
  std::uint64_t h = 0xcbf29ce484222325ULL;  // FNV-1a offset basis
  for (unsigned char c : what.dump()) {
    h ^= c;
    h *= 0x100000001b3ULL;  // FNV prime
  }
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

SweepProgressFile::SweepProgressFile(const std::string& path, const std::string& fingerprint,
                                     std::size_t points, bool resume)
    : path_(path) {
  bool have_header = false;
  if (resume && std::filesystem::exists(path)) {
    std::ifstream in(path);
    std::string line;
    std::size_t line_no = 0;
    std::vector<std::string> lines;
    while (std::getline(in, line)) lines.push_back(line);
    std::string kept;  // the header and the whole rows: the file is rewritten with just these
    for (const std::string& l : lines) {
      ++line_no;
      if (l.empty()) continue;
      nlohmann::json j;
      try {
        j = nlohmann::json::parse(l);
      } catch (const nlohmann::json::exception&) {
        // Only the last line can be cut by a kill mid-write: skip it; anything else is damage.
        if (line_no == lines.size()) break;
        throw std::invalid_argument(path + ":" + std::to_string(line_no) + ": not a saved sweep row (damaged file?)");
      }
      if (line_no == 1) {
        if (!j.is_object() || !j.contains("fingerprint"))
          throw std::invalid_argument(path + ":1: not a sweep progress file (no fingerprint)");
        const std::string saved_fp = j["fingerprint"].get<std::string>();
        if (saved_fp != fingerprint)
          throw std::invalid_argument(
              "--resume: " + path + " was saved by a different sweep (fingerprint " + saved_fp + ", this sweep " +
              fingerprint + "): the scene file, model, --set overrides, parameters, designs or --point-budget "
              "differ. Run the same command as before, or use another --out (or drop --resume to start afresh).");
        have_header = true;
        kept += l + "\n";
        continue;
      }
      try {
        const std::size_t index = j.at("index").get<std::size_t>();
        if (index >= points)
          throw std::invalid_argument(path + ":" + std::to_string(line_no) + ": point index " +
                                      std::to_string(index) + " beyond the " + std::to_string(points) + " designs");
        saved_.emplace(index, sweepPointFromJson(j.at("point")));
        kept += l + "\n";
      } catch (const nlohmann::json::exception& e) {
        if (line_no == lines.size()) break;  // cut by the kill: dropped
        throw std::invalid_argument(path + ":" + std::to_string(line_no) + ": not a saved sweep row: " + e.what());
      }
    }
    // Without a line cut by the kill, so the rows appended next start on a line of their own.
    if (have_header) writeFileAtomic(path, kept);
  }
  std::filesystem::create_directories(std::filesystem::path(path).parent_path().empty()
                                          ? std::filesystem::path(".")
                                          : std::filesystem::path(path).parent_path());
  const int flags = O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC | (have_header ? 0 : O_TRUNC);
  fd_ = ::open(path.c_str(), flags, 0644);
  if (fd_ < 0) throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
  if (!have_header) {
    const nlohmann::json header = {{"rollerdyn_sweep_progress", 1}, {"fingerprint", fingerprint}, {"points", points}};
    writeLine(fd_, path_, header.dump() + "\n");
  }
  last_sync_ = steadySeconds();
}

SweepProgressFile::~SweepProgressFile() {
  if (fd_ >= 0) {
    ::fdatasync(fd_);
    ::close(fd_);
  }
}

void SweepProgressFile::append(std::size_t index, const SweepPoint& point) {
  const nlohmann::json row = {{"index", index}, {"point", sweepPointToJson(point)}};
  writeLine(fd_, path_, row.dump() + "\n");  // one write: a kill keeps whole lines
  // A killed process keeps what write(2) handed to the kernel; a lost node only what reached the
  // disk. Syncing at most once a second bounds that loss without a disk flush per point.
  const double now = steadySeconds();
  if (now - last_sync_ > 1.0) {
    ::fdatasync(fd_);
    last_sync_ = now;
  }
}

}  // namespace rollerdyn
