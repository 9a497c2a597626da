// Saved rows of a running sweep, so a killed sweep (a cluster job's wall-time limit, Ctrl-C, a
// lost node) loses nothing it finished. The progress file (sweep.progress.jsonl in the output
// folder) is JSON Lines: a header line with the sweep's fingerprint, then one line per finished
// point, appended with one write(2) each as the point arrives (a kill can cut at most the last
// line, which reading skips). --resume reads it back and the sweep computes only the missing
// points; the fingerprint (a hash of the scene file's text, the model, the --set overrides, the
// parameter keys, every design and the metric list) keeps rows of a different sweep out.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "studies/Sweep.h"

namespace rollerdyn {

// A point as JSON and back; numbers round-trip exactly (shortest representation that reads back
// to the same double), NaN as null. Used for the progress file and the MPI transport.
nlohmann::json sweepPointToJson(const SweepPoint& point);
SweepPoint sweepPointFromJson(const nlohmann::json& j);  // throws nlohmann::json::exception

// 16 hex digits (FNV-1a, 64 bit) over what determines the rows of a sweep.
std::string sweepFingerprint(const SweepOptions& options, const std::vector<std::vector<std::string>>& designs);

class SweepProgressFile {
 public:
  // Opens path for appending. resume: reads the rows saved there first (a missing file is an
  // empty start); a header whose fingerprint differs throws std::invalid_argument saying so.
  // Without resume the file is started afresh. Throws std::runtime_error when it cannot be written.
  SweepProgressFile(const std::string& path, const std::string& fingerprint, std::size_t points, bool resume);
  ~SweepProgressFile();
  SweepProgressFile(const SweepProgressFile&) = delete;
  SweepProgressFile& operator=(const SweepProgressFile&) = delete;

  // Rows read back by resume, by point index.
  const std::map<std::size_t, SweepPoint>& saved() const { return saved_; }
  // Appends one point (not thread-safe: the caller serialises).
  void append(std::size_t index, const SweepPoint& point);

 private:
  std::string path_;
  int fd_ = -1;
  double last_sync_ = 0;  // steady-clock time of the last fdatasync [s]
  std::map<std::size_t, SweepPoint> saved_;
};

}  // namespace rollerdyn
