#include "studies/SweepPointBudget.h"

#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

#include "io/ChildProcess.h"
#include "studies/SweepProgress.h"

namespace rollerdyn {

namespace {

// Why the run process gave no row: the CPU limit stopped it, a signal ended it, or it ended abnormally.
std::string childFailure(const ChildOutcome& child, double budget) {
  std::ostringstream os;
  if (child.stoppedByCpuLimit()) {
    os << "timeout: CPU budget " << budget << " s exceeded (stopped by the CPU limit)";
  } else if (child.endedBySignal()) {
    os << "error: run process ended by " << child.howItEnded();
  } else {
    os << "error: run process ended abnormally (" << child.howItEnded() << ")";
  }
  return os.str();
}

}  // namespace

SweepPoint runSweepPointWithBudget(const SweepOptions& o, const std::vector<std::string>& texts,
                                   const std::vector<double>& values, double budget) {
  const long soft = long(std::ceil(budget));
  const std::optional<ChildOutcome> child =
      runInChild(soft, soft + 1, [&] { return sweepPointToJson(runSweepPoint(o, texts, values)).dump(); });
  if (!child) return runSweepPoint(o, texts, values);  // no isolation possible
  if (child->exitedCleanly()) {
    try {
      return sweepPointFromJson(nlohmann::json::parse(child->text));
    } catch (const std::exception&) {
      // fall through: an incomplete row is a failure of the run process
    }
  }
  SweepPoint p = pointNotRun(texts, values);
  p.ran = true;
  p.cpu_seconds = child->cpu_seconds;
  p.status = childFailure(*child, budget);
  return p;
}

}  // namespace rollerdyn
