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
#include <map>
#include <stdexcept>

#include "io/AtomicFile.h"
#include "io/ReadFile.h"
#include "io/FieldFormat.h"

namespace rollerdyn {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double numberOrNaN(const nlohmann::json& j) { return j.is_number() ? j.get<double>() : kNaN; }

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
  for (double v : p.values) values.push_back(jsonNumber(v));
  const auto& names = sweepNumericMetrics();
  for (std::size_t k = 0; k < names.size() && k < p.metrics.size(); ++k) metrics[names[k]] = jsonNumber(p.metrics[k]);
  return {{"texts", p.texts},         {"values", values},     {"metrics", metrics},
          {"ran", p.ran},             {"complete", p.complete}, {"steady", p.steady},
          {"status", p.status},       {"motion", p.motion},     {"cpu_seconds", jsonNumber(p.cpu_seconds)}, {"warnings", p.warnings}};
}

SweepPoint sweepPointFromJson(const nlohmann::json& j) {
  SweepPoint p;
  p.texts = j.at("texts").get<std::vector<std::string>>();
  for (const auto& v : j.at("values")) p.values.push_back(numberOrNaN(v));
  const auto& names = sweepNumericMetrics();
  const nlohmann::json& m = j.at("metrics");
  p.metrics.assign(names.size(), kNaN);
  for (std::size_t k = 0; k < names.size(); ++k)
    if (m.contains(names[k])) p.metrics[k] = numberOrNaN(m[names[k]]);
  p.ran = j.at("ran").get<bool>();
  p.complete = j.at("complete").get<bool>();
  p.steady = j.at("steady").get<bool>();
  p.status = j.at("status").get<std::string>();
  p.motion = j.value("motion", std::string("not run"));
  p.cpu_seconds = numberOrNaN(j.at("cpu_seconds"));
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

namespace {

// A progress file saved before, read for --resume: its header must carry this sweep's fingerprint;
// the whole rows are kept by index. Only the last line can be cut by a kill mid-write: it is
// dropped; anything else that does not read is damage.
class SavedProgressReader {
 public:
  SavedProgressReader(const std::string& path, const std::string& fingerprint, std::size_t points)
      : path_(path), fingerprint_(fingerprint), points_(points) {}

  void read() {
    std::ifstream in(path_);
    std::string line;
    std::vector<std::string> lines;
    while (std::getline(in, line)) lines.push_back(line);
    for (std::size_t i = 0; i < lines.size(); ++i)
      if (!lines[i].empty()) readLine(lines[i], i + 1, i + 1 == lines.size());
  }

  bool have_header = false;
  std::string kept;  // the header and the whole rows: the file is rewritten with just these
  std::map<std::size_t, SweepPoint> saved;

 private:
  void readLine(const std::string& l, std::size_t line_no, bool last) {
    nlohmann::json j;
    try {
      j = nlohmann::json::parse(l);
    } catch (const nlohmann::json::exception&) {
      if (last) return;
      throw std::invalid_argument(path_ + ":" + std::to_string(line_no) + ": not a saved sweep row (damaged file?)");
    }
    if (line_no == 1) {
      checkHeader(j);
      have_header = true;
      kept += l + "\n";
      return;
    }
    try {
      readRow(j, line_no);
      kept += l + "\n";
    } catch (const nlohmann::json::exception& e) {
      if (last) return;  // cut by the kill: dropped
      throw std::invalid_argument(path_ + ":" + std::to_string(line_no) + ": not a saved sweep row: " + e.what());
    }
  }

  void checkHeader(const nlohmann::json& j) const {
    if (!j.is_object() || !j.contains("fingerprint"))
      throw std::invalid_argument(path_ + ":1: not a sweep progress file (no fingerprint)");
    const std::string saved_fp = j["fingerprint"].get<std::string>();
    if (saved_fp != fingerprint_)
      throw std::invalid_argument(
          "--resume: " + path_ + " was saved by a different sweep (fingerprint " + saved_fp + ", this sweep " +
          fingerprint_ + "): the scene file, model, --set overrides, parameters, designs or --point-budget "
          "differ. Run the same command as before, or use another --out (or drop --resume to start afresh).");
  }

  void readRow(const nlohmann::json& j, std::size_t line_no) {
    const std::size_t index = j.at("index").get<std::size_t>();
    if (index >= points_)
      throw std::invalid_argument(path_ + ":" + std::to_string(line_no) + ": point index " + std::to_string(index) +
                                  " beyond the " + std::to_string(points_) + " designs");
    saved.emplace(index, sweepPointFromJson(j.at("point")));
  }

  const std::string& path_;
  const std::string& fingerprint_;
  std::size_t points_;
};

// The file opened for appending rows, emptied unless it keeps a header to resume after.
int openForAppending(const std::string& path, bool have_header) {
  std::filesystem::create_directories(std::filesystem::path(path).parent_path().empty()
                                          ? std::filesystem::path(".")
                                          : std::filesystem::path(path).parent_path());
  const int flags = O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC | (have_header ? 0 : O_TRUNC);
  const int fd = ::open(path.c_str(), flags, 0644);
  if (fd < 0) throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
  return fd;
}

}  // namespace

SweepProgressFile::SweepProgressFile(const std::string& path, const std::string& fingerprint,
                                     std::size_t points, bool resume)
    : path_(path) {
  bool have_header = false;
  if (resume && std::filesystem::exists(path)) {
    SavedProgressReader saved(path, fingerprint, points);
    saved.read();
    saved_ = std::move(saved.saved);
    have_header = saved.have_header;
    // Without a line cut by the kill, so the rows appended next start on a line of their own.
    if (have_header) writeFileAtomic(path, saved.kept);
  }
  fd_ = openForAppending(path, have_header);
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
